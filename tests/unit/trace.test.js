import { describe, it, expect } from 'vitest';
import { Scene, Sphere, Plane, Box, PointLight, Ray } from '../../lib/index.js';
import { trace, nearestHit } from '../../lib/tracing/trace.js';

/** Traces one ray; returns `{ color, hit }` (the inspector's record of the hit). */
function traced(scene, ray) {
  const steps = {};
  const color = trace(scene, ray, [0, 0, 0], steps);
  return { color, hit: steps.hit };
}

const expectColor = (actual, expected, digits = 12) =>
  expected.forEach((c, i) => expect(actual[i], `channel ${i}`).toBeCloseTo(c, digits));

describe('the first thing a ray hits gives the pixel its colour', () => {
  it('a miss is the background', () => {
    const scene = new Scene({ background: [0.1, 0.2, 0.3] }).add(new Sphere([0, 0, -20], 4));
    const { color, hit } = traced(scene, new Ray([0, 0, 0], [0, 1, 0]));
    expect(color).toEqual([0.1, 0.2, 0.3]);
    expect(hit).toBeNull();
  });

  it('nearestHit takes the nearest, whatever the order objects were added', () => {
    const near = new Sphere([0, 0, -10], 1), far = new Sphere([0, 0, -20], 4);
    const hit = {};
    expect(nearestHit([far, near], new Ray([0, 0, 0], [0, 0, -1]), hit)).toBe(true);
    expect(hit).toEqual({ object: near, t: 9 });
    expect(nearestHit([near, far], new Ray([0, 0, 0], [0, 0, -1]), hit)).toBe(true);
    expect(hit.object).toBe(near);
    expect(nearestHit([near, far], new Ray([0, 0, 0], [0, 0, 1]), hit)).toBe(false);
    expect(hit.object).toBeNull();
  });

  it('an emissive sphere shows its emission', () => {
    const scene = new Scene().add(new Sphere([0, 0, -10], 1, { color: [0, 0, 0], emission: [1, 0.5, 0] }));
    expectColor(traced(scene, new Ray([0, 0, 0], [0, 0, -1])).color, [1, 0.5, 0]);
  });

  it('ambient light reaches everything: ambient × surface colour', () => {
    const scene = new Scene({ ambient: 0.2 }).add(new Sphere([0, 0, -10], 1, { color: [1, 0.5, 0] }));
    expectColor(traced(scene, new Ray([0, 0, 0], [0, 0, -1])).color, [0.2, 0.1, 0]);
  });

  it('the hit record: object, t, point, normal, incidence', () => {
    const s = new Sphere([0, 0, -20], 4);
    const scene = new Scene().add(new Plane([0, -10, 0])).add(s);
    const { hit } = traced(scene, new Ray([0, 0, 0], [0, 0, -1]));
    expect(hit).toMatchObject({ object: s, index: 1, t: 16, point: { x: 0, y: 0, z: -16 }, normal: { x: 0, y: 0, z: 1 }, inside: false });
    expect(hit.incidence).toBeCloseTo(0, 9);
    const grazing = traced(scene, new Ray([0, 0, 0], [4, 0, -Math.sqrt(384)])).hit;
    // tangent-ish: the direction to the edge (4, 0, −√384) at distance 20 → incidence near 90°
    expect(grazing.incidence).toBeGreaterThan(85);
  });
});

describe('lighting: Lambert and point lights', () => {
  // the right-most point of a sphere at (−5, 0, −20), r 3: (−2, 0, −20), normal +x
  const sphereA = () => new Sphere([-5, 0, -20], 3, { color: [1, 1, 1] });
  const rayToA = () => new Ray([-1, 0, -20], [-1, 0, 0]);

  it('light straight along the normal: full colour (cos = 1)', () => {
    const scene = new Scene().add(sphereA()).add(new PointLight([0, 0, -20]));
    const { color, hit } = traced(scene, rayToA());
    expectColor(color, [1, 1, 1]);
    expect(hit.lights).toHaveLength(1);
    expect(hit.lights[0]).toMatchObject({ facing: true, inShadow: false, transmission: 1 });
    expect(hit.lights[0].cos).toBeCloseTo(1, 12);
    expect(hit.lights[0].distance).toBeCloseTo(2, 12);
  });

  it('light at 60° from the normal: half (cos 60° = 0.5)', () => {
    const scene = new Scene().add(sphereA()).add(new PointLight([-1, Math.sqrt(3), -20]));
    expectColor(traced(scene, rayToA()).color, [0.5, 0.5, 0.5]);
  });

  it('light behind the surface: nothing (cos < 0), not called a shadow', () => {
    const scene = new Scene().add(sphereA()).add(new PointLight([-3, 0, -30]));
    const { color, hit } = traced(scene, rayToA());
    // (−3,0,−30) − (−2,0,−20) = (−1,0,−10): cos < 0
    expectColor(color, [0, 0, 0]);
    expect(hit.lights[0]).toMatchObject({ facing: false, inShadow: false });
  });

  it('coloured lights and surface colours multiply; several lights add up', () => {
    const scene = new Scene()
      .add(new Sphere([-5, 0, -20], 3, { color: [1, 0.5, 0.25] }))
      .add(new PointLight([0, 0, -20], [1, 0, 1]))
      .add(new PointLight([8, 0, -20], [0, 1, 0], 0.5));
    const { color, hit } = traced(scene, rayToA());
    expectColor(color, [1, 0.25, 0.25]);
    expect(hit.lights.map((l) => l.contribution)).toEqual([
      [1, 0, 0.25],
      [0, 0.25, 0],
    ]);
  });
});

describe('shadows stop at the light', () => {
  // Two spheres on the x axis, A at x = −5 and B at x = +5; we look at A's right side.
  function twoSpheres(light, { shadows = true, transparency = 0 } = {}) {
    const a = new Sphere([-5, 0, -20], 3, { color: [1, 1, 1] });
    const b = new Sphere([5, 0, -20], 3, { color: [1, 1, 1], transparency });
    const scene = new Scene({ shadows }).add(a).add(b).add(light);
    return traced(scene, new Ray([-1, 0, -20], [-1, 0, 0]));
  }

  it('a light between two spheres lights both: the sphere beyond it casts no shadow', () => {
    const { color, hit } = twoSpheres(new PointLight([0, 0, -20]));
    expect(hit.lights[0].inShadow).toBe(false);
    expectColor(color, [1, 1, 1]);
  });

  it('a light just in front of the far sphere still lights A', () => {
    expect(twoSpheres(new PointLight([1.9, 0, -20])).hit.lights[0].inShadow).toBe(false);
  });

  it('a light beyond B: B is in the way, A is in its shadow', () => {
    const { color, hit } = twoSpheres(new PointLight([10, 0, -20]));
    expect(hit.lights[0]).toMatchObject({ facing: true, inShadow: true, transmission: 0 });
    expect(hit.lights[0].contribution).toEqual([0, 0, 0]);
    expectColor(color, [0, 0, 0]);
  });

  it('an emissive sphere is a light; between the spheres it lights A and does not shadow itself', () => {
    const lamp = new Sphere([0, 0, -20], 0.5, { color: [0, 0, 0], emission: 1 });
    const { color, hit } = twoSpheres(lamp);
    expect(hit.lights).toHaveLength(1);
    expect(hit.lights[0]).toMatchObject({ light: lamp, inShadow: false });
    expectColor(color, [1, 1, 1]);
  });

  it('an emissive sphere beyond B is shadowed by B', () => {
    const lamp = new Sphere([12, 0, -20], 0.5, { color: [0, 0, 0], emission: 1 });
    const { color, hit } = twoSpheres(lamp);
    expect(hit.lights[0].inShadow).toBe(true);
    expectColor(color, [0, 0, 0]);
  });

  it('scene.shadows = false: no shadow rays, the light gets through', () => {
    const { color, hit } = twoSpheres(new PointLight([10, 0, -20]), { shadows: false });
    expect(hit.lights[0].inShadow).toBe(false);
    expectColor(color, [1, 1, 1]);
  });

  it('glass casts a partial shadow: its transparency gets through', () => {
    const { color, hit } = twoSpheres(new PointLight([10, 0, -20]), { transparency: 0.5 });
    expect(hit.lights[0]).toMatchObject({ inShadow: true, transmission: 0.5 });
    expectColor(color, [0.5, 0.5, 0.5]);
  });

  it('a box and a plane cast shadows too', () => {
    const a = new Sphere([-5, 0, -20], 3);
    const box = new Box([2, -1, -21], [3, 1, -19]);
    const scene = new Scene().add(a).add(box).add(new PointLight([10, 0, -20]));
    expect(traced(scene, new Ray([-1, 0, -20], [-1, 0, 0])).hit.lights[0].inShadow).toBe(true);
    const wall = new Plane([3, 0, 0], [-1, 0, 0]);
    const scene2 = new Scene().add(a).add(wall).add(new PointLight([10, 0, -20]));
    expect(traced(scene2, new Ray([-1, 0, -20], [-1, 0, 0])).hit.lights[0].inShadow).toBe(true);
  });

  it('no self-shadowing: a sphere lit from the eye is fully lit at its front', () => {
    const s = new Sphere([0, 0, -20], 4, { color: [1, 1, 1] });
    const scene = new Scene().add(s).add(new PointLight([0, 0, 0]));
    for (const dir of [[0, 0, -1], [0.1, 0.05, -1], [-0.15, 0.1, -1]]) {
      const { hit } = traced(scene, new Ray([0, 0, 0], dir));
      expect(hit.lights[0].inShadow).toBe(false);
      expect(hit.lights[0].transmission).toBe(1);
    }
  });

  it('the ground under a sphere is in its shadow', () => {
    const scene = new Scene()
      .add(new Sphere([0, -10004, -20], 10000, { color: [0.5, 0.5, 0.5] }))
      .add(new Sphere([0, 0, -20], 4))
      .add(new PointLight([0, 20, -20]));
    // the ground at (0, −4, −16), just in front of the sphere's foot; the light is above the sphere
    const under = traced(scene, new Ray([0, 0, -5], [0, -4, -11]));
    expect(under.hit.object.radius).toBe(10000);
    expect(under.hit.lights[0].inShadow).toBe(true);
    const aside = traced(scene, new Ray([0, 0, -5], [10, -4, -15]));
    expect(aside.hit.lights[0].inShadow).toBe(false);
  });
});

describe('mirrors', () => {
  // A white mirror ball ahead, a green ball behind the eye, a white light at the eye.
  function mirrorScene(options = {}, reflection = 1) {
    const green = new Sphere([0, 0, 10], 3, { color: [0, 1, 0] });
    const mirror = new Sphere([0, 0, -10], 2, { color: [1, 1, 1], reflection });
    const scene = new Scene({ background: [0, 0, 1], ...options }).add(mirror).add(green).add(new PointLight([0, 0, 0]));
    return { scene, mirror, green };
  }
  const ahead = () => new Ray([0, 0, 0], [0, 0, -1]);

  it('a mirror sphere shows the colour of what it reflects', () => {
    const { scene, green } = mirrorScene();
    const { color, hit } = traced(scene, ahead());
    expectColor(color, [0, 1, 0]);
    expect(hit.reflection.hit.object).toBe(green);
    expect(hit.reflection.hit.point.z).toBeCloseTo(7, 9);
  });

  it('a mirror reflecting nothing shows the background', () => {
    const { scene } = mirrorScene();
    const { color } = traced(scene, new Ray([0, 0, 0], [0, 1.9, -10]));
    // glancing off the top of the mirror, up into the sky: mostly blue
    expect(color[2]).toBeGreaterThan(0.9);
    expect(color[1]).toBeCloseTo(0, 9);
  });

  it('maxDepth 0 disables reflection: the mirror shows its own lit colour', () => {
    const { scene } = mirrorScene({ maxDepth: 0 });
    const { color, hit } = traced(scene, ahead());
    expectColor(color, [1, 1, 1]);
    expect(hit.reflection).toBeNull();
  });

  it('reflection 0.5 mixes half of each', () => {
    const { scene } = mirrorScene({}, 0.5);
    expectColor(traced(scene, ahead()).color, [0.5, 1, 0.5]);
  });

  it('two facing mirrors: the ray bounces exactly maxDepth times', () => {
    for (const maxDepth of [0, 1, 3, 6]) {
      const scene = new Scene({ maxDepth })
        .add(new Plane([0, 0, -5], [0, 0, 1], { reflection: 1 }))
        .add(new Plane([0, 0, 5], [0, 0, -1], { reflection: 1 }));
      let { hit } = traced(scene, new Ray([0, 0, 0], [0, 0, -1]));
      let bounces = 0;
      while (hit.reflection) { bounces++; hit = hit.reflection.hit; }
      expect(bounces).toBe(maxDepth);
    }
  });
});

describe('glass', () => {
  // A glass ball in front of a red lamp, on the axis of the eye.
  function glassScene(ior = 1.5) {
    const glass = new Sphere([0, 0, -10], 2, { color: [1, 1, 1], transparency: 1, ior });
    const lamp = new Sphere([0, 0, -30], 3, { color: [0, 0, 0], emission: [1, 0, 0] });
    return { scene: new Scene().add(glass).add(lamp), glass, lamp };
  }

  it('a ray along the centre line goes straight through', () => {
    const { scene, glass, lamp } = glassScene();
    const { color, hit } = traced(scene, new Ray([0, 0, 0], [0, 0, -1]));
    expect(hit.object).toBe(glass);
    const exit = hit.refraction.hit;
    expect(exit.object).toBe(glass);
    expect(exit.inside).toBe(true);
    expect(exit.point.x).toBeCloseTo(0, 9);
    expect(exit.point.y).toBeCloseTo(0, 9);
    expect(exit.point.z).toBeCloseTo(-12, 9);
    const beyond = exit.refraction.hit;
    expect(beyond.object).toBe(lamp);
    expect(beyond.point.x).toBeCloseTo(0, 9);
    expect(beyond.point.z).toBeCloseTo(-27, 9);
    // through the glass: red, less what the two surfaces reflect (Fresnel)
    expect(color[0]).toBeGreaterThan(0.85);
    expect(color[0]).toBeLessThan(1);
    expect(color[1]).toBe(0);
    expect(color[2]).toBe(0);
    // head-on, Schlick's F is r0 = ((1 − 1.5)/(1 + 1.5))² = 0.04
    expect(hit.fresnel).toBeCloseTo(0.04, 12);
  });

  it('an off-centre ray bends toward the axis (a ball lens)', () => {
    const { scene, glass } = glassScene();
    const { hit } = traced(scene, new Ray([1, 0, 0], [0, 0, -1]));
    const exit = hit.refraction.hit.point;
    expect(exit.x).toBeLessThan(1);
    const c = glass.center;
    expect(Math.hypot(exit.x - c.x, exit.y - c.y, exit.z - c.z)).toBeCloseTo(2, 9);
  });

  it('ior 1 does not bend at all', () => {
    const { scene } = glassScene(1);
    const { hit } = traced(scene, new Ray([1, 0, 0], [0, 0, -1]));
    // (only the shadow-ray offset, bias = 1e-4 along the normal, moves it)
    expect(hit.refraction.hit.point.x).toBeCloseTo(1, 3);
    expect(hit.fresnel).toBeLessThan(1e-3); // Schlick: r0 = 0, only the (1 − cos i)⁵ term
  });

  it('total internal reflection: steep inside the glass, nothing gets out', () => {
    // eye inside a glass ball (centre (3, 0, 0), r 4), looking along −z: it meets the
    // surface at (0, 0, −√7), where cos i = √7/4 ≈ 0.661, i ≈ 48.6°.
    const ray = () => new Ray([0, 0, 0], [0, 0, -1]);
    const ball = (ior) => new Scene({ background: [1, 1, 1] })
      .add(new Sphere([3, 0, 0], 4, { color: [1, 1, 1], transparency: 1, ior }));
    // ior 1.5: critical angle asin(1/1.5) ≈ 41.8° < 48.6° → total internal reflection
    const tir = traced(ball(1.5), ray()).hit;
    expect(tir.inside).toBe(true);
    expect(tir.point.z).toBeCloseTo(-Math.sqrt(7), 12);
    expect(tir.incidence).toBeCloseTo(Math.acos(Math.sqrt(7) / 4) * 180 / Math.PI, 9);
    expect(tir.fresnel).toBe(1);
    expect(tir.refraction).toBeNull();
    expect(tir.reflection).not.toBeNull();
    // ior 1.1: critical angle ≈ 65.4° > 48.6° → it gets out
    const out = traced(ball(1.1), ray()).hit;
    expect(out.fresnel).toBeLessThan(1);
    expect(out.refraction).not.toBeNull();
    expect(out.refraction.hit).toBeNull(); // out into the background
  });
});
