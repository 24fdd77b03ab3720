// The 3D view's still part as triangles (lib/p5/scene-view/mesh.js): every
// shape, light and the eye; glass apart; colours lit by one fixed light.
import { describe, it, expect } from 'vitest';
import { Scene } from '../../lib/scene/scene.js';
import { Sphere } from '../../lib/shapes/sphere.js';
import { Plane } from '../../lib/shapes/plane.js';
import { Box } from '../../lib/shapes/box.js';
import { Cylinder } from '../../lib/shapes/cylinder.js';
import { Cone } from '../../lib/shapes/cone.js';
import { Triangle } from '../../lib/shapes/triangle.js';
import { AreaLight } from '../../lib/lights/area-light.js';
import { PointLight } from '../../lib/lights/point-light.js';
import { Camera } from '../../lib/math/camera.js';
import { Vec3 } from '../../lib/math/vec3.js';
import { sceneBounds } from '../../lib/lesson/rays3d.js';
import { buildMeshes, shapesKey, shade, glassAlpha, nearestAhead, GLOW } from '../../lib/p5/scene-view/mesh.js';

const SPHERE = 16 * 28 * 6, SMALL_SPHERE = 8 * 12 * 6, BOX = 6 * 6, PATCH = 6; // vertices

function fixture() {
  const pink = new Sphere([0, 0, -20], 4, { color: [1, 0.32, 0.36] });
  const glass = new Sphere([6, 0, -24], 2, { color: [0.9, 0.9, 1], transparency: 0.8 });
  const scene = new Scene()
    .add(pink).add(glass)
    .add(new Box([-8, -2, -26], [-5, 1, -23], { color: [0.2, 0.8, 0.3] }))
    .add(new Plane([0, -4, 0], [0, 1, 0], { color: [0.5, 0.5, 0.5] }))
    .add(new PointLight([-10, 20, 8]));
  const camera = new Camera({ width: 32, height: 24 });
  const bounds = sceneBounds(scene, camera, 10);
  return { scene, camera, bounds, pink, glass };
}

describe('buildMeshes', () => {
  it('has every shape, the light and the eye as triangles; glass in a list of its own, see-through', () => {
    const { scene, camera, bounds } = fixture();
    const { mesh, glass } = buildMeshes({ scene, camera, bounds, constructionSphere: null });
    expect(mesh.positions.length / 3).toBe(SPHERE + BOX + PATCH + SMALL_SPHERE + SMALL_SPHERE);
    expect(glass.positions.length / 3).toBe(SPHERE);
    expect(mesh.colors.length / 4).toBe(mesh.positions.length / 3);
    expect(new Set(glass.colors.filter((_, i) => i % 4 === 3))).toEqual(new Set([glassAlpha(0.8)]));
    expect(new Set(mesh.colors.filter((_, i) => i % 4 === 3))).toEqual(new Set([1]));
    expect(mesh.colors.every((c) => c >= 0 && c <= 1)).toBe(true);
  });

  it('writes y negated (p5\'s WEBGL y points down)', () => {
    const scene = new Scene().add(new Box([1, 2, -10], [3, 5, -8], { color: [1, 1, 1] }));
    const camera = new Camera({ width: 8, height: 6 });
    const { mesh } = buildMeshes({ scene, camera, bounds: sceneBounds(scene, camera, 1), constructionSphere: null });
    const ys = mesh.positions.slice(0, BOX * 3).filter((_, i) => i % 3 === 1);
    expect(new Set(ys)).toEqual(new Set([-2, -5]));
  });

  it('leaves out the construction sphere (drawn as a wire ball)', () => {
    const { scene, camera, bounds, pink } = fixture();
    const all = buildMeshes({ scene, camera, bounds, constructionSphere: null }).mesh.positions.length;
    const without = buildMeshes({ scene, camera, bounds, constructionSphere: pink }).mesh.positions.length;
    expect(all - without).toBe(SPHERE * 3);
  });
});

describe('shade', () => {
  it('lights a surface facing the fixed light fully, one facing away by the ambient share only', () => {
    const up = shade([1, 1, 1], new Vec3(0, 1, 0)), down = shade([1, 1, 1], new Vec3(0, -1, 0));
    expect(down).toEqual([115, 115, 115]); // 255 × 0.45
    expect(up[0]).toBeGreaterThan(down[0]);
    expect(up[0]).toBeLessThanOrEqual(255);
    expect(shade([1, 0.5, 0], new Vec3(0, -1, 0), false)).toEqual([255, 128, 0]); // a glow is not shaded
  });

  it('draws clear glass faint, never invisible', () => {
    expect(glassAlpha(0)).toBe(1);
    expect(glassAlpha(1)).toBe(0.25);
  });

  it('gives emissive shapes and lights a warm glow', () => {
    expect(GLOW).toEqual([1, 0.84, 0.3]);
  });
});

describe('shapesKey', () => {
  it('changes when a shape moves or the construction sphere is chosen, and not otherwise', () => {
    const { scene, camera, bounds, pink } = fixture();
    const key = shapesKey({ scene, camera, bounds, constructionSphere: null });
    expect(shapesKey({ scene, camera, bounds, constructionSphere: null })).toBe(key);
    expect(shapesKey({ scene, camera, bounds, constructionSphere: pink })).not.toBe(key);
    pink.center.x += 1;
    expect(shapesKey({ scene, camera, bounds, constructionSphere: null })).not.toBe(key);
  });

  const keyOf = (...items) => {
    const scene = new Scene();
    for (const item of items) scene.add(item);
    const camera = new Camera({ width: 8, height: 6 });
    return shapesKey({ scene, camera, bounds: sceneBounds(scene, camera, 1), constructionSphere: null });
  };

  it.each([
    ['a cylinder\'s height', () => new Cylinder([0, 0, -10], 1, 2), (c) => { c.height = 3; }],
    ['a cylinder\'s caps', () => new Cylinder([0, 0, -10], 1, 2), (c) => { c.capped = false; }],
    ['a cone\'s height', () => new Cone([0, 0, -10], 1, 2), (c) => { c.height = 4; }],
    ['a cone\'s caps', () => new Cone([0, 0, -10], 1, 2), (c) => { c.capped = false; }],
    ['a triangle\'s corner', () => new Triangle([0, 0, -10], [1, 0, -10], [0, 1, -10]), (t) => { t.c.x = 0.5; }],
    ['an area light\'s radius', () => new AreaLight([0, 5, -10], 1), (l) => { l.radius = 2; }],
  ])('changes with %s (each shape and light says its own key)', (_, make, change) => {
    const item = make(), before = keyOf(item);
    change(item);
    expect(keyOf(item)).not.toBe(before);
  });

  it('tells two triangles apart, and a cylinder from a cone of the same numbers', () => {
    expect(keyOf(new Triangle([0, 0, -10], [1, 0, -10], [0, 1, -10]))).not.toBe(keyOf(new Triangle([0, 0, -10], [1, 0, -10], [0, 2, -10])));
    expect(keyOf(new Cylinder([0, 0, -10], 1, 2))).not.toBe(keyOf(new Cone([0, 0, -10], 1, 2)));
  });
});

describe('nearestAhead', () => {
  it('is the distance along the view to the nearest sphere\'s front, leaving out spheres behind and grounds', () => {
    const camera = new Camera({ width: 8, height: 6 });
    const scene = new Scene()
      .add(new Sphere([0, 0, -20], 4)).add(new Sphere([3, 0, -12], 1))
      .add(new Sphere([0, 0, 10], 2)).add(new Sphere([0, -10004, -20], 10000));
    expect(nearestAhead(scene, camera)).toBe(11);
    expect(nearestAhead(new Scene().add(new Sphere([0, 0, 10], 2)), camera)).toBe(10); // none ahead: 10
  });
});
