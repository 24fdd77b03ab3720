/**
 * lib/tracing/optics.js in GLSL, one function for one function, the same formulas in
 * the same order: the GPU engine's shading (lib/gpu/glsl-kernel.js) calls
 * these as lib/tracing/kernel.js calls those. tests/e2e/gpu-formulas.spec.js checks
 * each against optics.js on sampled inputs.
 *
 * Two names differ, because GLSL has built-ins by the JS names:
 * optics.js `refract` is `refraction` here, `mix` is `mixShares`. GLSL has no
 * out-array, so `refraction` writes its direction into an `out vec3`.
 */
export const OPTICS_GLSL = /* glsl */ `
// Lambert: cos θ = N·L.
float lambert(vec3 N, vec3 L) {
  return N.x * L.x + N.y * L.y + N.z * L.z;
}

// Phong's highlight: specular·(R·V)^shininess, R·V = (L − 2(N·L)N)·D.
float specular(float strength, float shininess, float cosTheta, vec3 L, vec3 N, vec3 D) {
  if (!(strength > 0.0)) return 0.0;
  float twice = 2.0 * cosTheta;
  float rv = (L.x - twice * N.x) * D.x + (L.y - twice * N.y) * D.y + (L.z - twice * N.z) * D.z;
  return rv > 0.0 ? strength * pow(rv, shininess) : 0.0;
}

// A spot light's share: 1 inside cosInner, 0 outside cosOuter, smoothstep between.
float spotShare(vec3 axis, float cosOuter, float cosInner, vec3 L) {
  float cosAxis = -(L.x * axis.x + L.y * axis.y + L.z * axis.z);
  if (cosAxis >= cosInner) return 1.0;
  if (cosAxis <= cosOuter) return 0.0;
  float s = (cosAxis - cosOuter) / (cosInner - cosOuter);
  return s * s * (3.0 - 2.0 * s);
}

// The fall of light with distance: 1 / (1 + k·d²).
float falloff(float attenuation, float distance) {
  return 1.0 / (1.0 + attenuation * distance * distance);
}

// One channel of one light's share.
float lightShare(float light, float surface, float diffuse, float highlight) {
  return light * (surface * diffuse + highlight);
}

// Snell's law (optics.js refract): T = eta·D + s·N into T; false on total internal reflection.
bool refraction(vec3 D, vec3 N, float cosi, float eta, out vec3 T) {
  float k = 1.0 - eta * eta * (1.0 - cosi * cosi);
  T = vec3(0.0);
  if (k < 0.0) return false;
  float s = eta * cosi - sqrt(k);
  T = vec3(eta * D.x + s * N.x, eta * D.y + s * N.y, eta * D.z + s * N.z);
  return true;
}

// Schlick: r0 + (1 − r0)(1 − cos θ)⁵, the fifth power by multiplying.
float schlick(float cosi, float ior) {
  float r = (1.0 - ior) / (1.0 + ior);
  float r0 = r * r;
  float k = 1.0 - cosi, k2 = k * k;
  return r0 + (1.0 - r0) * k2 * k2 * k;
}

// The share glass reflects: none without glass, all of it on total internal reflection, else Schlick's.
float fresnel(float transparency, bool refracts, float cosi, float ior) {
  if (!(transparency > 0.0)) return 0.0;
  return refracts ? schlick(cosi, ior) : 1.0;
}

// One channel of the mirror and glass mix (optics.js mix).
float mixShares(float local, float mirror, float through, float color, float reflection, float transparency, float F) {
  float opaque = (1.0 - reflection) * local + reflection * color * mirror;
  return (1.0 - transparency) * opaque + transparency * (F * mirror + (1.0 - F) * color * through);
}
`;
