import { describe, it, expect } from 'vitest';
import { Camera } from '../../lib/math/camera.js';
import { Scene } from '../../lib/scene/scene.js';
import { Sphere, intersectGeometric } from '../../lib/shapes/sphere.js';
import { PointLight } from '../../lib/lights/point-light.js';
import { inspectPixel } from '../../lib/lesson/inspect.js';
import { classScene } from '../../lib/scene/examples.js';
import { Vec3, sub, normalize, length, dot, distance } from '../../lib/math/vec3.js';
import {
  imagePoint, pixelCenter, imagePlane, pixelGrid, frustum, pickImagePlane, raySegments,
  geometricConstruction, orbitCamera, screenRay, projectToScreen, sceneBounds,
  sampleSegments,
} from '../../lib/lesson/rays3d.js';
import { lightsOf } from '../../lib/lights/index.js';
import { penumbraScene, penumbraCamera, pointsSeen, penumbraPixel, BALL } from './penumbra-scene.js';

const close = (a, b, digits = 9) => {
  expect(a.x).toBeCloseTo(b.x, digits); expect(a.y).toBeCloseTo(b.y, digits); expect(a.z).toBeCloseTo(b.z, digits);
};
const dir = (from, to) => normalize(new Vec3(), sub(new Vec3(), to, from));

describe('pixel → image-plane point', () => {
  const cameras = [
    new Camera({ width: 32, height: 24 }),
    new Camera({ width: 64, height: 48, fov: 50, position: [1, 2, 3], yaw: 30, pitch: -20 }),
    new Camera({ width: 7, height: 13, fov: 90, yaw: -140, pitch: 60 }),
  ];
  for (const camera of cameras) {
    it(`the primary ray of every pixel passes through its centre (${camera.width}×${camera.height}, yaw ${camera.yaw})`, () => {
      for (const [x, y] of [[0, 0], [camera.width - 1, 0], [3, 5], [camera.width - 1, camera.height - 1]]) {
        const { ray } = inspectPixel(new Scene(), camera, x, y);
        for (const d of [1, 4.5]) {
          const c = pixelCenter(camera, x, y, d);
          close(dir(camera.position, c), ray.direction, 12);
          // and lies on the plane at distance d along the view direction
          expect(dot(sub(new Vec3(), c, camera.position), camera.forward)).toBeCloseTo(d, 12);
        }
      }
    });
  }

  it('the image plane at distance 1 is 2·tan(fov/2) high, centred on the view direction', () => {
    const camera = new Camera({ width: 40, height: 20, fov: 60 });
    const plane = imagePlane(camera, 1);
    expect(plane.height).toBeCloseTo(2 * Math.tan(Math.PI / 6), 12);
    expect(plane.width).toBeCloseTo(plane.height * 2, 12);
    close(plane.center, new Vec3(0, 0, -1));
    const [tl, tr, br, bl] = plane.corners;
    expect(tl.x).toBeLessThan(tr.x); expect(tl.y).toBeGreaterThan(bl.y);
    close(imagePoint(camera, 0, 0), tl); close(imagePoint(camera, 40, 20), br);
    expect(distance(tl, tr)).toBeCloseTo(plane.width, 12);
  });

  it('the pixel grid has width + 1 columns and height + 1 rows, one pixel apart', () => {
    const camera = new Camera({ width: 8, height: 6 });
    const { columns, rows } = pixelGrid(camera, 3);
    expect(columns).toHaveLength(9); expect(rows).toHaveLength(7);
    const plane = imagePlane(camera, 3);
    expect(distance(columns[0][0], columns[1][0])).toBeCloseTo(plane.width / 8, 12);
    close(columns[0][0], plane.corners[0]); close(rows[6][1], plane.corners[2]);
  });

  it('the frustum edges pass through the image plane corners', () => {
    const camera = new Camera({ width: 16, height: 9, yaw: 20 });
    const { eye, near, far } = frustum(camera, 50);
    for (let i = 0; i < 4; i++) close(dir(eye, near[i]), dir(eye, far[i]), 12);
  });
});

describe('picking a pixel on the image plane in 3D', () => {
  const camera = new Camera({ width: 32, height: 24, yaw: 10, pitch: 5 });
  it('a ray from anywhere through a pixel centre picks that pixel', () => {
    const from = new Vec3(12, 7, 9);
    for (const [x, y] of [[0, 0], [31, 23], [10, 12]]) {
      const c = pixelCenter(camera, x, y, 5);
      const pick = pickImagePlane(camera, 5, from, dir(from, c));
      expect(pick).toMatchObject({ x, y });
      close(pick.point, c, 9);
    }
  });
  it('a ray beside the picture, or away from the plane, picks nothing', () => {
    const from = new Vec3(0, 0, 5);
    expect(pickImagePlane(camera, 5, from, dir(from, imagePoint(camera, -1, 5, 5)))).toBeNull();
    expect(pickImagePlane(camera, 5, from, dir(from, imagePoint(camera, 33, 5, 5)))).toBeNull();
    expect(pickImagePlane(camera, 5, from, new Vec3(0, 0, 1))).toBeNull();
  });
});

describe('ray segments of a pixel, from inspectPixel', () => {
  const camera = new Camera({ width: 32, height: 24 });

  it('a miss: one primary segment off to the background, along the ray', () => {
    const scene = new Scene();
    const record = inspectPixel(scene, camera, 0, 0);
    const segs = raySegments(scene, record, { missLength: 30 });
    expect(segs).toHaveLength(1);
    expect(segs[0]).toMatchObject({ kind: 'primary', hit: false, depth: 0 });
    close(segs[0].to, new Vec3(record.ray.direction.x * 30, record.ray.direction.y * 30, record.ray.direction.z * 30));
  });

  it('a hit: primary to the hit point, the normal, one shadow ray per light (lit or blocked), as the record says', () => {
    const scene = classScene();
    const record = inspectPixel(scene, camera, 16, 12); // the pink sphere
    const segs = raySegments(scene, record);
    const [primary, normal] = segs;
    expect(primary).toMatchObject({ kind: 'primary', hit: true, object: record.hit.object, t: record.hit.t });
    close(primary.to, record.hit.point);
    close(dir(primary.from, primary.to), record.ray.direction, 9);
    expect(normal.kind).toBe('normal');
    close(dir(normal.from, normal.to), record.hit.normal, 12);
    const shadows = segs.filter((s) => s.kind === 'shadow');
    expect(shadows).toHaveLength(record.hit.lights.length);
    expect(shadows.length).toBe(2);
    shadows.forEach((s, i) => {
      const l = record.hit.lights[i];
      close(s.to, l.position);
      expect(s.lit).toBe(l.facing && !l.inShadow);
      expect(s.blockedAt === null).toBe(!(l.facing && l.inShadow));
    });
  });

  it('a blocked shadow ray says where it is blocked: on the blocker, between the point and the light', () => {
    const scene = new Scene();
    scene.add(new Sphere([0, -1001, -10], 1000, { color: [0.5, 0.5, 0.5] }));
    scene.add(Object.assign(new Sphere([0, 2, -10], 1, { color: [1, 0, 0] }), { name: 'blocker' }));
    scene.add(new PointLight([0, 10, -10]));
    const record = inspectPixel(scene, new Camera({ width: 33, height: 33, fov: 60 }), 16, 19);
    expect(record.hit?.lights[0].inShadow).toBe(true);
    const [shadow] = raySegments(scene, record).filter((s) => s.kind === 'shadow');
    expect(shadow.lit).toBe(false);
    expect(distance(shadow.blockedAt, new Vec3(0, 2, -10))).toBeCloseTo(1, 6);
    expect(shadow.blockedAt.y).toBeGreaterThan(record.hit.point.y);
    expect(shadow.blockedAt.y).toBeLessThan(10);
  });

  it('mirrors and glass: bounces follow the record down to maxDepth, each to the next hit', () => {
    const scene = classScene({ full: true });
    const record = inspectPixel(scene, camera, 16, 12); // pink: half mirror, half glass
    const segs = raySegments(scene, record);
    const bounces = segs.filter((s) => s.kind === 'reflection' || s.kind === 'refraction');
    expect(bounces.length).toBeGreaterThan(1);
    expect(Math.max(...bounces.map((s) => s.depth))).toBeLessThanOrEqual(scene.maxDepth);
    // the first reflection leaves the hit point as the mirror law says, to the record's next hit
    const first = segs.find((s) => s.kind === 'reflection');
    close(first.from, record.hit.point);
    const d = record.ray.direction, n = record.hit.normal, k = 2 * dot(d, n);
    close(dir(first.from, first.to), normalize(new Vec3(), new Vec3(d.x - k * n.x, d.y - k * n.y, d.z - k * n.z)), 6);
    if (record.hit.reflection.hit) close(first.to, record.hit.reflection.hit.point);
    // a refraction whose next hit is recorded ends on it
    const refraction = segs.find((s) => s.kind === 'refraction');
    expect(refraction).toBeDefined();
    if (record.hit.refraction.hit) close(refraction.to, record.hit.refraction.hit.point);
    // depth 0: no bounce at all
    scene.maxDepth = 0;
    expect(raySegments(scene, inspectPixel(scene, camera, 16, 12)).some((s) => s.depth > 0)).toBe(false);
  });

  it('refuses anything that is not a record', () => {
    expect(() => raySegments(classScene(), null)).toThrow(TypeError);
  });
});

describe('an area light in 3D: its disc and a pixel\'s shadow rays to each of its points', () => {
  const { scene, lamp } = penumbraScene();
  const camera = penumbraCamera();

  it('a penumbra pixel: primary, normal, then one shadow ray per point, lit as our own shadow rays say', () => {
    const { record, seen } = penumbraPixel(scene, camera, lamp);
    const segs = raySegments(scene, record);
    expect(segs.map((s) => s.kind)).toEqual(['primary', 'normal', ...Array(16).fill('shadow')]);
    const shadows = segs.slice(2), points = lamp.points();
    expect(shadows.map((s) => s.sample)).toEqual([...Array(16).keys()]);
    shadows.forEach((s, i) => { close(s.to, points[i]); expect(s.light).toBe(lamp); });
    expect(shadows.filter((s) => s.lit)).toHaveLength(seen);
    const blocked = shadows.filter((s) => !s.lit);
    expect(blocked).toHaveLength(16 - seen);
    for (const s of blocked) { // stopped on the ball, between the floor and the disc
      expect(distance(s.blockedAt, new Vec3(...BALL.center))).toBeCloseTo(BALL.radius, 6);
      expect(distance(s.from, s.blockedAt)).toBeLessThan(distance(s.from, s.to));
    }
    expect(pointsSeen(record.hit.point, record.hit.normal, lamp, scene.bias)).toBe(seen);
  });

  it('the disc\'s outline: on its rim, in its plane; the scene\'s lights each once', () => {
    expect(lightsOf(scene)).toEqual([lamp]);
    expect(lightsOf(classScene())).toEqual([]); // its lights are emissive spheres
    const [rim] = lamp.outlines(32);
    expect(rim).toHaveLength(32);
    for (const p of rim) {
      const d = sub(new Vec3(), p, lamp.center);
      expect(length(d)).toBeCloseTo(lamp.radius, 9);
      expect(dot(d, lamp.normal)).toBeCloseTo(0, 9);
    }
  });
});

describe('several rays per pixel in 3D: the sub-pixel rays', () => {
  it('one segment per sub-pixel ray, from the eye to its hit (or missLength out)', () => {
    const scene = classScene(), camera = new Camera({ width: 32, height: 24, samples: 9 });
    const record = inspectPixel(scene, camera, 16, 12);
    const segs = sampleSegments(record, { missLength: 25 });
    expect(segs).toHaveLength(9);
    segs.forEach((s, i) => {
      const sample = record.samples[i];
      expect(s).toMatchObject({ kind: 'sample', dx: sample.dx, dy: sample.dy, hit: sample.hit !== null });
      close(s.from, camera.position);
      close(dir(s.from, s.to), sample.ray.direction, 9);
      expect(distance(s.from, s.to)).toBeCloseTo(sample.t ?? 25, 9);
    });
    expect(new Set(segs.map((s) => `${s.to.x},${s.to.y}`)).size).toBe(9); // nine rays, nine ends
    const miss = sampleSegments(inspectPixel(new Scene(), camera, 0, 0), { missLength: 25 });
    expect(miss.every((s) => !s.hit && Math.abs(distance(s.from, s.to) - 25) < 1e-9)).toBe(true);
  });

  it('none with one ray per pixel', () => {
    expect(sampleSegments(inspectPixel(classScene(), new Camera({ width: 32, height: 24 }), 16, 12))).toEqual([]);
  });
});

describe('the geometric construction in 3D', () => {
  it('L, tca, d and thc end where the lesson says: tca·Rd, the centre, the hit', () => {
    const scene = classScene();
    const camera = new Camera({ width: 32, height: 24 });
    const record = inspectPixel(scene, camera, 17, 11);
    const test = record.tests.find((t) => t.sphere.name === 'pink');
    const g = intersectGeometric(record.ray, test.sphere);
    const parts = geometricConstruction(record.ray, test.sphere, g);
    expect(length(sub(new Vec3(), parts.L[1], parts.L[0]))).toBeCloseTo(Math.sqrt(dot(g.L, g.L)), 9);
    expect(distance(...parts.tca)).toBeCloseTo(g.tca, 9);
    expect(distance(...parts.d) ** 2).toBeCloseTo(g.d2, 6);
    expect(distance(...parts.thc)).toBeCloseTo(g.thc, 9);
    close(parts.thc[1], record.hit.point, 6);
  });
});

describe('the orbit camera', () => {
  it('looks at its target from the given distance; a screen ray through the middle goes to the target', () => {
    const target = new Vec3(1, 2, -10);
    const orbit = orbitCamera({ target, yaw: 35, pitch: 20, distance: 30 });
    expect(distance(orbit.eye, target)).toBeCloseTo(30, 9);
    expect(orbit.eye.y).toBeGreaterThan(target.y);
    const { direction } = screenRay(orbit, 200, 150, 400, 300, Math.PI / 3);
    close(direction, orbit.forward, 12);
  });
  it('projectToScreen undoes screenRay', () => {
    const orbit = orbitCamera({ target: new Vec3(0, 0, -20), yaw: -50, pitch: 30, distance: 40 });
    const { origin, direction } = screenRay(orbit, 123, 45, 480, 360, 0.9);
    const p = projectToScreen(orbit, new Vec3(origin.x + direction.x * 17, origin.y + direction.y * 17, origin.z + direction.z * 17), 480, 360, 0.9);
    expect(p.x).toBeCloseTo(123, 6); expect(p.y).toBeCloseTo(45, 6);
    expect(projectToScreen(orbit, new Vec3(orbit.eye.x - orbit.forward.x, orbit.eye.y - orbit.forward.y, orbit.eye.z - orbit.forward.z), 480, 360, 0.9)).toBeNull();
  });
  it('the class scene is framed without its ground', () => {
    const { center, radius } = sceneBounds(classScene(), new Camera({ width: 32, height: 24 }), 4);
    expect(radius).toBeLessThan(60);
    expect(center.z).toBeLessThan(0);
  });
});
