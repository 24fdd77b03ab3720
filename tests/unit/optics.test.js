// The leaf formulas trace.js and the fast path share (lib/tracing/optics.js), each
// against what the lesson says it is.
import { describe, it, expect } from 'vitest';
import { lambert, specular, lightShare, refract, schlick, fresnel, mix } from '../../lib/tracing/optics.js';
import { Vec3, reflect, reflectInto } from '../../lib/math/vec3.js';

describe('lib/tracing/optics.js', () => {
  it("Lambert's cos is N·L: 1 head on, 0 edge on, negative from behind", () => {
    expect(lambert(0, 1, 0, 0, 1, 0)).toBe(1);
    expect(lambert(0, 1, 0, 1, 0, 0)).toBe(0);
    expect(lambert(0, 1, 0, 0, -1, 0)).toBe(-1);
    expect(lambert(0, 1, 0, Math.SQRT1_2, Math.SQRT1_2, 0)).toBeCloseTo(Math.SQRT1_2, 15);
  });

  it("Phong's highlight is full where the ray looks straight down the light's mirror, and none without strength", () => {
    // Light from straight above (L = +y), seen along the mirror of the light: D = −y, so R·V = 1.
    expect(specular(0.5, 20, 1, 0, 1, 0, 0, 1, 0, 0, -1, 0)).toBe(0.5);
    expect(specular(0, 20, 1, 0, 1, 0, 0, 1, 0, 0, -1, 0)).toBe(0);
    // Light at 45° (L = (√½, √½, 0)) seen from the mirror side: R·V = 1 again; from the light's side, R·V = 0.
    const c = Math.SQRT1_2;
    expect(specular(1, 1, c, c, c, 0, 0, 1, 0, c, -c, 0)).toBeCloseTo(1, 12);
    expect(specular(1, 1, c, c, c, 0, 0, 1, 0, -c, -c, 0)).toBe(0);
    expect(specular(1, 8, c, c, c, 0, 0, 1, 0, 0, -1, 0)).toBeCloseTo(c ** 8, 12); // shininess sharpens it
  });

  it("one light's share: the light's colour times the surface's under it, plus the highlight", () => {
    expect(lightShare(0.5, 0.8, 0.25, 0.1)).toBeCloseTo(0.5 * (0.8 * 0.25 + 0.1), 15);
    expect(lightShare(0, 1, 1, 1)).toBe(0);
  });

  it('the mirror direction is d − 2(d·n)n, in numbers as for vectors', () => {
    const out = new Float64Array(4);
    reflectInto(out, 1, Math.SQRT1_2, -Math.SQRT1_2, 0, 0, 1, 0);
    expect([...out]).toEqual([0, Math.SQRT1_2, Math.SQRT1_2, 0]);
    expect(reflect(new Vec3(), new Vec3(0.6, -0.8, 0), new Vec3(0, 1, 0))).toEqual(new Vec3(0.6, 0.8, 0));
  });

  it("Snell's law: straight through head on, bent toward the normal going in, none beyond the critical angle", () => {
    const out = new Float64Array(5);
    expect(refract(out, 2, 0, -1, 0, 0, 1, 0, 1, 1 / 1.5)).toBe(true);
    expect([...out]).toEqual([0, 0, 0, -1, 0]); // at its place in `out`
    const s = Math.sin(Math.PI / 6), c = Math.cos(Math.PI / 6); // 30° from the normal
    expect(refract(out, 0, s, -c, 0, 0, 1, 0, c, 1 / 1.5)).toBe(true);
    expect(out[0]).toBeCloseTo(s / 1.5, 12); // sin θt = sin θi / n
    expect(Math.hypot(out[0], out[1], out[2])).toBeCloseTo(1, 12);
    const g = Math.sin(Math.PI / 3), h = Math.cos(Math.PI / 3); // 60° from inside glass of 1.5: past the critical 41.8°
    expect(refract(out, 0, g, -h, 0, 0, 1, 0, h, 1.5)).toBe(false);
  });

  it("Schlick's Fresnel share: r0 head on, all of it at grazing; none without glass, all on total internal reflection", () => {
    expect(schlick(1, 1.5)).toBeCloseTo(0.04, 15);
    expect(schlick(0, 1.5)).toBe(1);
    expect(fresnel(0, true, 1, 1.5)).toBe(0);
    expect(fresnel(0.5, false, 0.3, 1.5)).toBe(1);
    expect(fresnel(0.5, true, 1, 1.5)).toBe(schlick(1, 1.5));
  });

  it('the mirror and glass mix: the local colour alone for a plain surface, the mirrored one for a perfect mirror', () => {
    expect(mix(0.3, 0.9, 0.7, 0.5, 0, 0, 0)).toBe(0.3);
    expect(mix(0.3, 0.9, 0.7, 1, 1, 0, 0)).toBe(0.9);
    expect(mix(0.3, 0.9, 0.7, 1, 0, 1, 0)).toBe(0.7); // clear glass, no reflection: what it lets through
    expect(mix(0.3, 0.9, 0.7, 1, 0, 1, 1)).toBe(0.9); // total internal reflection: the mirrored colour
  });
});
