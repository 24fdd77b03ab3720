/**
 * Each shape's packed hit test and normal (lib/shapes/*.js, their static
 * `packed`) in GLSL: the same numbers read from the same places, the same
 * steps. `b` is where the shape's numbers start in uShapes; a triangle's and
 * a mesh's first number is their side table's index (lib/gpu/upload.js lays
 * the tables out in uTables). NO_HIT stands for the kernel's Infinity.
 *
 * One change of form, for float32: the sphere's d² is |L − tca·Rd|² rather
 * than L·L − tca², the same number for a unit Rd, but without the
 * cancellation that in float32 loses a ground sphere of radius 10,000's
 * edge (Haines et al., "Precision Improvements for Ray/Sphere Intersection",
 * Ray Tracing Gems, 2019).
 */
export const SHAPES_GLSL = /* glsl */ `
// farOnly: the ray runs inside this sphere from its surface (lib/gpu/glsl-kernel.js, self).
float sphereHit(int b, vec3 o, vec3 d, float tMin, bool farOnly) {
  vec3 c = vec3(shape(b), shape(b + 1), shape(b + 2));
  float radius = shape(b + 3), r2 = radius * radius;
  vec3 L = c - o;
  float tca = dot(L, d);
  float LL = dot(L, L);
  vec3 across = L - tca * d; // d² = |L − tca·Rd|² (see above)
  float gap = r2 - dot(across, across); // r² − d²
  float band = TANGENT * (r2 + LL);
  // d > r: a miss; but a ray running inside always leaves (a path's nearly tangent bounce from
  // just inside a sphere of radius 5 rounds to d > r about once in 10⁶ in float32, and escaped)
  if (gap < -band && !farOnly) return NO_HIT;
  float thc = gap <= band ? 0.0 : sqrt(gap);
  if (tca - thc > tMin && !farOnly) return tca - thc;
  return tca + thc > tMin ? tca + thc : NO_HIT;
}

vec3 sphereNormal(int b, vec3 P) {
  vec3 v = P - vec3(shape(b), shape(b + 1), shape(b + 2));
  float size = sqrt(dot(v, v));
  return v * (size > 0.0 ? 1.0 / size : 0.0);
}

float planeHit(int b, vec3 o, vec3 d, float tMin) {
  vec3 p = vec3(shape(b), shape(b + 1), shape(b + 2)), n = vec3(shape(b + 3), shape(b + 4), shape(b + 5));
  float denom = dot(n, d);
  if (abs(denom) < PARALLEL) return NO_HIT;
  float t = dot(p - o, n) / denom;
  return t > tMin ? t : NO_HIT;
}

vec3 planeNormal(int b) {
  return vec3(shape(b + 3), shape(b + 4), shape(b + 5));
}

// Narrows slab (tNear, tFar) by one axis' slab lo…hi; false when the ray misses it.
bool clipSlab(float lo, float hi, float o, float d, inout vec2 slab) {
  if (d == 0.0) return !(o < lo || o > hi); // parallel: inside this slab or never
  float t1 = (lo - o) / d, t2 = (hi - o) / d;
  if (t1 > t2) { float swap = t1; t1 = t2; t2 = swap; }
  if (t1 > slab.x) slab.x = t1;
  if (t2 < slab.y) slab.y = t2;
  return !(slab.x > slab.y);
}

float boxHit(int b, vec3 o, vec3 d, float tMin) {
  vec2 slab = vec2(-NO_HIT, NO_HIT);
  if (!clipSlab(shape(b), shape(b + 3), o.x, d.x, slab) || !clipSlab(shape(b + 1), shape(b + 4), o.y, d.y, slab) ||
      !clipSlab(shape(b + 2), shape(b + 5), o.z, d.z, slab)) return NO_HIT;
  if (slab.x > tMin) return slab.x;
  return slab.y > tMin ? slab.y : NO_HIT; // the ray starts inside
}

// The axis of the nearest face, x then y then z, min face before max face.
vec3 boxNormal(int b, vec3 P) {
  float best = NO_HIT;
  vec3 n = vec3(0.0, 1.0, 0.0);
  for (int a = 0; a < 3; a++) {
    float toMin = abs(P[a] - shape(b + a)), toMax = abs(P[a] - shape(b + 3 + a));
    if (toMin < best) { best = toMin; n = vec3(0.0); n[a] = -1.0; }
    if (toMax < best) { best = toMax; n = vec3(0.0); n[a] = 1.0; }
  }
  return n;
}

// At² + Bt + C = 0 into roots (t0 ≤ t1); how many real roots: 0, 1 or 2 (lib/shapes/axial.js solveQuadratic).
int solveQuadratic(float A, float B, float C, out vec2 roots) {
  roots = vec2(0.0);
  if (A == 0.0) {
    if (B == 0.0) return 0;
    roots = vec2(-C / B);
    return 1;
  }
  float discriminant = B * B - 4.0 * A * C;
  if (abs(discriminant) <= TANGENT * (B * B + 4.0 * abs(A * C))) { roots = vec2(-B / (2.0 * A)); return 1; }
  if (discriminant < 0.0) return 0;
  float q = -0.5 * (B + (B < 0.0 ? -1.0 : 1.0) * sqrt(discriminant));
  float ta = q / A, tb = C / q;
  roots = vec2(min(ta, tb), max(ta, tb));
  return 2;
}

// t where the ray crosses the plane y = yPlane inside the disc of radius² r2, or NO_HIT.
float capCrossing(float yPlane, float r2, float x, float oy, float z, vec3 d) {
  if (d.y == 0.0) return NO_HIT;
  float t = (yPlane - oy) / d.y;
  float px = x + d.x * t, pz = z + d.z * t;
  return px * px + pz * pz <= r2 ? t : NO_HIT;
}

bool withinSpan(float y, float lo, float hi, bool closedTop) {
  return y > lo && (y < hi || (closedTop && y == hi));
}

float cylinderHit(int b, vec3 o, vec3 d, float tMin) {
  float radius = shape(b + 3), height = shape(b + 4), cy = shape(b + 1);
  bool capped = shape(b + 5) == 1.0;
  float x = o.x - shape(b), z = o.z - shape(b + 2), bottom = cy - height / 2.0, top = cy + height / 2.0, r2 = radius * radius;
  float best = NO_HIT;
  vec2 roots;
  int count = solveQuadratic(d.x * d.x + d.z * d.z, 2.0 * (x * d.x + z * d.z), x * x + z * z - r2, roots);
  for (int i = 0; i < count; i++) {
    float t = roots[i];
    if (t > tMin && t < best && withinSpan(o.y + d.y * t, bottom, top, false)) best = t;
  }
  if (capped) {
    float tTop = capCrossing(top, r2, x, o.y, z, d), tBottom = capCrossing(bottom, r2, x, o.y, z, d);
    if (tTop > tMin && tTop < best) best = tTop;
    if (tBottom > tMin && tBottom < best) best = tBottom;
  }
  return best;
}

vec3 cylinderNormal(int b, vec3 P) {
  float radius = shape(b + 3), height = shape(b + 4), cy = shape(b + 1);
  bool capped = shape(b + 5) == 1.0;
  float x = P.x - shape(b), z = P.z - shape(b + 2);
  float rho = sqrt(x * x + z * z);
  float toSide = abs(rho - radius);
  float toTop = abs(P.y - (cy + height / 2.0)), toBottom = abs(P.y - (cy - height / 2.0));
  if (capped && toTop < toSide && toTop <= toBottom) return vec3(0.0, 1.0, 0.0);
  if (capped && toBottom < toSide) return vec3(0.0, -1.0, 0.0);
  if (rho > 0.0) return vec3(x / rho, 0.0, z / rho);
  return vec3(1.0, 0.0, 0.0);
}

float coneHit(int b, vec3 o, vec3 d, float tMin) {
  float radius = shape(b + 3), height = shape(b + 4), cy = shape(b + 1);
  bool capped = shape(b + 5) == 1.0;
  float k2 = (radius / height) * (radius / height);
  float x = o.x - shape(b), z = o.z - shape(b + 2), base = cy - height / 2.0, apex = cy + height / 2.0, below = apex - o.y;
  float A = d.x * d.x + d.z * d.z - k2 * d.y * d.y;
  float B = 2.0 * (x * d.x + z * d.z + k2 * below * d.y);
  float C = x * x + z * z - k2 * below * below;
  float best = NO_HIT;
  vec2 roots;
  int count = solveQuadratic(A, B, C, roots);
  for (int i = 0; i < count; i++) {
    float t = roots[i];
    if (t > tMin && t < best && withinSpan(o.y + d.y * t, base, apex, true)) best = t;
  }
  if (capped) {
    float tBase = capCrossing(base, radius * radius, x, o.y, z, d);
    if (tBase > tMin && tBase < best) best = tBase;
  }
  return best;
}

vec3 coneNormal(int b, vec3 P) {
  float radius = shape(b + 3), height = shape(b + 4), cy = shape(b + 1);
  bool capped = shape(b + 5) == 1.0;
  float k = radius / height, x = P.x - shape(b), z = P.z - shape(b + 2);
  float rho = sqrt(x * x + z * z);
  float toSide = abs(rho - k * (cy + height / 2.0 - P.y)) / sqrt(1.0 + k * k);
  if (capped && abs(P.y - (cy - height / 2.0)) < toSide) return vec3(0.0, -1.0, 0.0);
  if (rho == 0.0) return vec3(0.0, 1.0, 0.0);
  float size = rho * sqrt(1.0 + k * k);
  return vec3(x / size, (k * rho) / size, z / size);
}

// Möller–Trumbore: corner a, edges e1 = b − a, e2 = c − a (lib/shapes/triangle.js triangleHit).
float triangleHit(vec3 a, vec3 e1, vec3 e2, vec3 o, vec3 d, float tMin) {
  vec3 P = cross(d, e2);
  float determinant = dot(e1, P);
  float size2 = dot(e1, e1) * dot(e2, e2) * dot(d, d);
  if (determinant * determinant <= PARALLEL * PARALLEL * size2) return NO_HIT; // parallel
  vec3 S = o - a;
  float u = dot(S, P) / determinant;
  if (u < 0.0 || u > 1.0) return NO_HIT;
  vec3 Q = cross(S, e1);
  float v = dot(d, Q) / determinant;
  if (v < 0.0 || u + v > 1.0) return NO_HIT;
  float t = dot(e2, Q) / determinant;
  return t > tMin ? t : NO_HIT;
}

// A triangle's side table: a, e1, e2, its normal.
float triangleShapeHit(int b, vec3 o, vec3 d, float tMin) {
  int at = tableStart(int(shape(b)));
  return triangleHit(table3(at), table3(at + 3), table3(at + 6), o, d, tMin);
}

vec3 triangleNormal(int b) {
  return table3(tableStart(int(shape(b))) + 9);
}

#if HAS_MESH
// The slab test on a BVH node's box (lib/shapes/bvh.js enterBox): where the ray enters it, or NO_HIT.
float enterBox(int j, vec3 o, vec3 inv, float tMin, float best) {
  float tNear = tMin, tFar = best;
  for (int a = 0; a < 3; a++) {
    float lo = (table(j + a) - o[a]) * inv[a], hi = (table(j + 3 + a) - o[a]) * inv[a];
    if (lo > hi) { float s = lo; lo = hi; hi = s; }
    if (lo > tNear) tNear = lo;
    if (hi < tFar) tFar = hi;
  }
  return tNear <= tFar ? tNear : NO_HIT;
}

// A mesh (lib/shapes/bvh.js walk): the nearest triangle through its tree; its index into item.
// The mesh's table: where its boxes, nodes, order, corners and normals start.
float meshHit(int b, vec3 o, vec3 d, float tMin, out int item) {
  int at = tableStart(int(shape(b)));
  int boxes = int(table(at)), nodes = int(table(at + 1)), order = int(table(at + 2)), corners = int(table(at + 3));
  vec3 inv = 1.0 / d;
  float best = NO_HIT;
  item = -1;
  int stack[BVH_STACK];
  float stackT[BVH_STACK];
  int top = 0;
  float rootT = enterBox(boxes, o, inv, tMin, NO_HIT);
  if (rootT != NO_HIT) { stack[0] = 0; stackT[0] = rootT; top = 1; }
  while (top > 0) {
    top--;
    if (stackT[top] > best) continue; // a nearer hit was found meanwhile
    int node = stack[top], first = int(table(nodes + 2 * node)), n = int(table(nodes + 2 * node + 1));
    if (n > 0) { // a leaf: its triangles
      for (int k = first; k < first + n; k++) {
        int j = corners + 9 * k, index = int(table(order + k));
        float t = triangleHit(table3(j), table3(j + 3), table3(j + 6), o, d, tMin);
        if (t < best || (t == best && t != NO_HIT && index < item)) { best = t; item = index; }
      }
      continue;
    }
    float tLeft = enterBox(boxes + 6 * first, o, inv, tMin, best);
    float tRight = enterBox(boxes + 6 * (first + 1), o, inv, tMin, best);
    bool nearFirst = tLeft <= tRight;
    int farChild = nearFirst ? first + 1 : first, nearChild = nearFirst ? first : first + 1;
    float tFar = nearFirst ? tRight : tLeft, tNear = nearFirst ? tLeft : tRight;
    if (tFar != NO_HIT) { stack[top] = farChild; stackT[top] = tFar; top++; }
    if (tNear != NO_HIT) { stack[top] = nearChild; stackT[top] = tNear; top++; }
  }
  return best;
}

// The normal of the triangle the mesh's hit found (Mesh#normalAt, its last hit's triangle).
vec3 meshNormal(int b, int item) {
  int at = tableStart(int(shape(b)));
  return table3(int(table(at + 4)) + 3 * item);
}
#else
vec3 meshNormal(int b, int item) { return vec3(0.0, 1.0, 0.0); } // (no mesh in the scene)
#endif
`;
