/**
 * Random scenes and cameras for the tests that hold the fast paths to one
 * picture: every shape (spheres, planes, boxes, cylinders, cones, triangles,
 * meshes), every light (point, spot, area, attenuation, emissive shapes),
 * mirrors, glass, the scene's switches. tests/unit/same-bytes.test.js (kernel
 * = trace.js) and tests/e2e/gpu.spec.js (GPU ≈ render) draw from them.
 */
import fc from 'fast-check';
import { Camera, Scene, Sphere, Plane, Box, Cylinder, Cone, Triangle, Mesh, PointLight, SpotLight, AreaLight } from '../../lib/index.js';
import { shapeClass } from '../../lib/shapes/index.js';
import { lightClass } from '../../lib/lights/index.js';

/**
 * The entries of a table of generators by type whose type is listed, in the
 * table's order: fast-check draws by place, so the tables keep the order the
 * GPU spec's seed has always drawn from, and a listed class with no entry
 * fails same-bytes.test.js ('has a random one of every listed shape and light').
 */
const listedOnly = (table, listed) => Object.entries(table).filter(([type]) => listed(type)).map(([, entry]) => entry);

/**
 * A number in [min, max]: half the time fast-check's own double, drawn to the
 * ends and to tiny values (0, 1, 5e-324), half the time spread evenly, so that
 * colours and places in between, where a last bit shows in a byte, come up too.
 */
export const between = (min, max) => fc.oneof(
  fc.double({ min, max, noNaN: true }),
  fc.noBias(fc.integer({ min: 0, max: 2 ** 53 - 1 })).map((n) => Math.min(max, min + (max - min) * (n / 2 ** 53))),
);
export const coord = (size) => between(-size, size);
export const point = (size) => fc.tuple(coord(size), coord(size), coord(size));
/** Anywhere near the eye, or ahead of it (down −z, where a camera that looks ahead sees it small). */
export const place = fc.oneof(point(15), fc.tuple(coord(10), coord(8), between(-40, -3)));
export const unit = between(0, 1);
/** Zero half the time: most surfaces are plain, some mirror, some glass, some shine. */
export const sometimes = (value) => fc.oneof(fc.constant(0), value);
export const color = fc.tuple(unit, unit, unit);

export const material = fc.record({
  color,
  emission: fc.oneof({ weight: 3, arbitrary: fc.constant(0) }, { weight: 1, arbitrary: fc.tuple(unit, unit, unit).map((c) => c.map((v) => 2 * v)) }),
  reflection: sometimes(unit),
  transparency: sometimes(unit),
  ior: between(1, 2.5),
  specular: sometimes(unit),
  shininess: between(1, 200),
});

export const sphere = fc.tuple(place, fc.oneof(
  { weight: 4, arbitrary: between(0.05, 1.5) }, // small: many tiles leave it out
  { weight: 2, arbitrary: between(0.05, 8) },
  { weight: 1, arbitrary: between(100, 10000) }, // a ground or a wall
), material).map(([center, radius, m]) => new Sphere(center, radius, m));

export const direction = point(1).filter(([x, y, z]) => x * x + y * y + z * z > 0.01);
export const plane = fc.tuple(point(10), direction, material).map(([p, normal, m]) => new Plane(p, normal, m));

export const size = between(0.1, 4);
export const box = fc.tuple(place, size, size, size, material)
  .map(([[x, y, z], dx, dy, dz, m]) => new Box([x, y, z], [x + dx, y + dy, z + dz], m));

/** Lights fade with distance now and then (attenuation 0: not at all). */
export const attenuation = fc.oneof({ weight: 2, arbitrary: fc.constant(0) }, { weight: 1, arbitrary: between(0, 0.5) });
export const pointLight = fc.tuple(point(20), color, between(0, 2), attenuation)
  .map(([position, c, intensity, k]) => (k === 0 ? new PointLight(position, c, intensity) : new PointLight(position, { color: c, intensity, attenuation: k })));
export const spotLight = fc.tuple(point(20), point(10), between(1, 89), color, between(0, 2), attenuation)
  .filter(([p, t]) => p.some((v, i) => v !== t[i]))
  .map(([position, target, angle, c, intensity, k]) => new SpotLight(position, target, { angle, color: c, intensity, attenuation: k }));
export const areaLight = fc.tuple(point(20), between(0.1, 4), fc.constantFrom(1, 4, 9), direction, color, between(0, 2), attenuation)
  .map(([center, radius, samples, normal, c, intensity, k]) => new AreaLight(center, radius, { samples, normal, color: c, intensity, attenuation: k }));

/**
 * A random one of each listed light class, by its type. The scenes below draw
 * from every class of the list (lib/lights/index.js), so a light is in the
 * property the day it is listed; one listed with no entry here fails the test
 * 'has a random one of every listed shape and light' (same-bytes.test.js) until it has one.
 */
export const LIGHTS = { pointLight: { weight: 3, arbitrary: pointLight }, spotLight: { weight: 1, arbitrary: spotLight }, areaLight: { weight: 1, arbitrary: areaLight } };
export const light = fc.oneof(...listedOnly(LIGHTS, lightClass));

/** Cylinders and cones, capped and open. */
export const axial = (Shape) => fc.tuple(place, between(0.1, 3), between(0.1, 4), fc.boolean(), material)
  .map(([center, radius, height, capped, m]) => new Shape(center, radius, height, { ...m, capped }));
export const cylinder = axial(Cylinder), cone = axial(Cone);

/** Three corners near a place, kept only when they span an area (a Triangle refuses a flat one). */
export const corners = fc.tuple(place, point(3), point(3)).filter(([, u, v]) => {
  const cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2], cz = u[0] * v[1] - u[1] * v[0];
  return Math.hypot(cx, cy, cz) > 1e-3 * Math.hypot(...u) * Math.hypot(...v) && Math.hypot(...u) > 0.05 && Math.hypot(...v) > 0.05;
}).map(([[x, y, z], u, v]) => [[x, y, z], [x + u[0], y + u[1], z + u[2]], [x + v[0], y + v[1], z + v[2]]]);
export const triangle = fc.tuple(corners, material).map(([[a, b, c], m]) => new Triangle(a, b, c, m));

/** A small mesh: a tetrahedron scaled and placed, or a few separate triangles (enough for the tree to split). */
export const tetrahedron = fc.tuple(place, between(0.2, 3), material).map(([[x, y, z], r, m]) => new Mesh({
  positions: [[x, y, z], [x + r, y, z], [x, y + r, z], [x, y, z + r]], cells: [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
}, m));
export const soup = fc.tuple(fc.array(corners, { minLength: 1, maxLength: 12 }), material).map(([list, m]) => new Mesh({
  positions: list.flat(), cells: list.map((_, i) => [3 * i, 3 * i + 1, 3 * i + 2]),
}, m));
export const mesh = fc.oneof(tetrahedron, soup);

/** A scene's switches, and its items drawn from `item`. */
export const sceneOf = (item) => fc.record({
  background: color,
  ambient: sometimes(unit),
  shadows: fc.boolean(),
  specular: fc.boolean(),
  maxDepth: fc.integer({ min: 0, max: 4 }),
  bias: fc.constantFrom(1e-4, 0, 0.01),
  epsilon: fc.constantFrom(1e-6, 0),
  items: fc.array(item, { minLength: 1, maxLength: 7 }),
  again: fc.oneof({ weight: 9, arbitrary: fc.constant(null) }, { weight: 1, arbitrary: fc.nat() }), // now and then one item added twice
}).map(({ items, again, ...options }) => [...items, ...(again === null ? [] : [items[again % items.length]])]
  .reduce((s, it) => s.add(it), new Scene(options)));

export const scene = sceneOf(fc.oneof({ weight: 5, arbitrary: sphere }, { weight: 1, arbitrary: plane }, { weight: 3, arbitrary: box }, { weight: 2, arbitrary: light }));
/**
 * A random one of each listed shape class, by its type, as LIGHTS: the scenes
 * of every listed shape draw from the list (lib/shapes/index.js).
 */
export const SHAPES = {
  sphere: { weight: 2, arbitrary: sphere }, plane: { weight: 1, arbitrary: plane }, box: { weight: 1, arbitrary: box },
  cylinder: { weight: 2, arbitrary: cylinder }, cone: { weight: 2, arbitrary: cone }, triangle: { weight: 2, arbitrary: triangle }, mesh: { weight: 2, arbitrary: mesh },
};
/** Every listed shape (the course's cylinders, cones, triangles and small meshes among spheres, planes and boxes) and every listed light. */
export const shapeScene = sceneOf(fc.oneof(...listedOnly(SHAPES, shapeClass).toSpliced(3, 0, { weight: 2, arbitrary: light }))); // the lights after the boxes, where the seeds have drawn them
/** The lesson's scenes: spheres only (the fast path then skips asking each shape its kind), lit by their glow and point lights. */
export const sphereScene = sceneOf(fc.oneof({ weight: 3, arbitrary: sphere }, { weight: 1, arbitrary: light }));

/** Small frames of a few tiles (16 px), rarely whole ones; from anywhere looking anywhere, or from near the origin looking ahead. */
export const camera = fc.record({
  width: fc.integer({ min: 1, max: 48 }),
  height: fc.integer({ min: 1, max: 36 }),
  fov: fc.oneof(between(10, 60), between(10, 150)),
  yaw: fc.oneof(between(-30, 30), between(-180, 180)),
  pitch: fc.oneof(between(-20, 20), between(-89, 89)),
  position: fc.oneof(point(2), point(6)),
}).map((options) => new Camera(options));
