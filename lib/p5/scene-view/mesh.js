/**
 * The 3D view's still part as flat triangle lists: the shapes in their
 * colours, the lights and the eye, each vertex coloured with a fixed light
 * worked out once (so each frame draws them without p5's lights: software
 * WebGL lights every pixel in its shader, and that alone took a frame of the
 * class scene from 30 ms to 500 ms). No p5 here: scene-view-draw.js turns the
 * lists into a p5.Geometry.
 *
 * A list is `{ positions, colors, alpha }`: x, −y, z per vertex (p5's WEBGL y
 * points down) and r, g, b, a in 0–1, three vertices a triangle.
 */
import { ballOf } from '../../shapes/index.js';
import { Vec3, sub, dot, normalize, cross } from '../../math/vec3.js';
import { HUGE_RADIUS } from '../../lesson/rays3d.js';
import { lightsOf } from '../../lights/index.js';

/** Emissive shapes and point lights: a warm glow. */
export const GLOW = [1, 0.84, 0.3];
/** The fixed light the shapes are shaded by (from above, right, front) and how much light reaches everything. */
const SUN = normalize(new Vec3(), new Vec3(0.35, 0.85, 0.4));
const AMBIENT = 0.45;

/** A colour [0–1] as lit by SUN on a surface with normal n: 0–255 bytes. */
export function shade(rgb, n, lit = true) {
  const k = lit ? AMBIENT + (1 - AMBIENT) * Math.max(0, dot(n, SUN)) : 1;
  return [Math.round(255 * rgb[0] * k), Math.round(255 * rgb[1] * k), Math.round(255 * rgb[2] * k)];
}

/** How opaque glass of this transparency is drawn: clear glass stays faintly visible. */
export function glassAlpha(transparency) {
  return 1 - 0.75 * transparency;
}

function coloredVertex(mesh, p, col) {
  mesh.positions.push(p.x, -p.y, p.z);
  mesh.colors.push(col[0] / 255, col[1] / 255, col[2] / 255, mesh.alpha ?? 1);
}

/**
 * The still part of the view: `{ mesh, glass }`, glass (a material with
 * transparency) apart, to be drawn last and see-through. The construction
 * sphere is left out: it is drawn as a wire ball, the construction inside it.
 * @param {{ scene: object, camera: object, bounds: { center: Vec3, radius: number }, constructionSphere: object|null }} state
 */
export function buildMeshes(state) {
  return new MeshBuilder(state.bounds).build(state);
}

/** Builds the triangle lists for one framing (the scene's bounds). */
class MeshBuilder {
  #bounds;

  constructor(bounds) { this.#bounds = bounds; }

  build({ scene, camera, constructionSphere }) {
    const r = this.#bounds.radius;
    const mesh = { positions: [], colors: [], alpha: 1 }, glass = { positions: [], colors: [], alpha: 1 };
    for (const object of scene.objects) {
      const m = object.material;
      const rgb = m.isEmissive ? GLOW : m.color.map((c) => Math.min(1, c));
      if (object === constructionSphere) continue; // drawn as a wire ball: the construction is inside it
      const into = m.transparency > 0 && !m.isEmissive ? glass : mesh;
      into.alpha = into === glass ? glassAlpha(m.transparency) : 1;
      object.drawIn3D?.(this.#kit(), into, rgb); // the shape says which of the view's meshes it is
    }
    for (const light of scene.lights) if (!light.object) sphereMesh(mesh, light.position, r * 0.025, GLOW, false, 8, 12);
    sphereMesh(mesh, camera.position, r * 0.02, [0.11, 0.14, 0.2], true, 8, 12);
    return { mesh, glass };
  }

  /** The meshes a shape draws itself with (its drawIn3D): a ball (a huge one as a patch of ground), a ground patch, a box. */
  #kit() {
    return {
      ball: (into, center, radius, rgb, lit) => (radius > HUGE_RADIUS
        ? this.#groundPatch(into, center, sub(new Vec3(), this.#bounds.center, center), radius, rgb)
        : sphereMesh(into, center, radius, rgb, lit)),
      ground: (into, point, normal, radius, rgb) => this.#groundPatch(into, point, normal, radius, rgb),
      box: boxMesh,
      triangles: trianglesMesh,
    };
  }

  /** A huge sphere or a plane: a square patch of it under the scene, big enough to stand on. */
  #groundPatch(g, origin, towardScene, radius, rgb) {
    groundPatch(g, this.#bounds, origin, towardScene, radius, rgb);
  }
}

/**
 * What the still part depends on: the shapes (each says its own key, its
 * `viewKey()`; one without says its JSON), their colours, the lights (their
 * `viewKey()`), the eye and the framing.
 */
export function shapesKey({ scene, camera, bounds, constructionSphere }) {
  const parts = [camera.position.x, camera.position.y, camera.position.z, bounds.radius, constructionSphere ? 1 : 0];
  for (const o of scene.objects) {
    const m = o.material;
    parts.push(`${o.constructor.type}(${typeof o.viewKey === 'function' ? o.viewKey() : JSON.stringify(o.toJSON?.() ?? null)})`, ...m.color, m.isEmissive ? 1 : 0, m.transparency);
  }
  for (const light of lightsOf(scene)) parts.push(`${light.constructor.type}(${light.viewKey()})`);
  return parts.join(',');
}

/** Each light's outlines as it last gave them, with the key they were made for: `{ key, loops }`. */
const _outlines = new WeakMap();

/**
 * The loops of points the scene's lights draw of themselves in the 3D view,
 * beyond a glow per source: each light's `outlines()` (an area light's rim),
 * made again only when its `viewKey()` changes.
 * @returns {import('../../math/vec3.js').Vec3[][]}
 */
export function lightLoops(scene) {
  const loops = [];
  for (const light of lightsOf(scene)) {
    if (typeof light.outlines !== 'function') continue;
    const key = light.viewKey();
    if (_outlines.get(light)?.key !== key) _outlines.set(light, { key, loops: light.outlines() });
    loops.push(..._outlines.get(light).loops);
  }
  return loops;
}

/** A sphere as latitude/longitude triangles, each vertex coloured by its normal (flat glow when not lit). */
export function sphereMesh(g, c, r, rgb, lit = true, rings = 16, segments = 28) {
  const at = (i, j) => {
    const theta = (Math.PI * i) / rings, phi = (2 * Math.PI * j) / segments;
    const n = new Vec3(Math.sin(theta) * Math.cos(phi), Math.cos(theta), Math.sin(theta) * Math.sin(phi));
    return { p: new Vec3(c.x + r * n.x, c.y + r * n.y, c.z + r * n.z), col: shade(rgb, n, lit) };
  };
  for (let i = 0; i < rings; i++) {
    for (let j = 0; j < segments; j++) {
      const a = at(i, j), b = at(i + 1, j), d = at(i, j + 1), e = at(i + 1, j + 1);
      for (const v of [a, b, e, a, e, d]) coloredVertex(g, v.p, v.col);
    }
  }
}

/** A box: two triangles a face, each face shaded by its normal. */
export function boxMesh(g, min, max, rgb) {
  const P = (x, y, z) => new Vec3(x ? max.x : min.x, y ? max.y : min.y, z ? max.z : min.z);
  /** @type {Array<[import('../../math/vec3.js').Vec3, import('../../math/vec3.js').Vec3[]]>} a face: its normal and its four corners */
  const faces = [
    [new Vec3(1, 0, 0), [P(1, 0, 0), P(1, 1, 0), P(1, 1, 1), P(1, 0, 1)]], [new Vec3(-1, 0, 0), [P(0, 0, 0), P(0, 0, 1), P(0, 1, 1), P(0, 1, 0)]],
    [new Vec3(0, 1, 0), [P(0, 1, 0), P(0, 1, 1), P(1, 1, 1), P(1, 1, 0)]], [new Vec3(0, -1, 0), [P(0, 0, 0), P(1, 0, 0), P(1, 0, 1), P(0, 0, 1)]],
    [new Vec3(0, 0, 1), [P(0, 0, 1), P(1, 0, 1), P(1, 1, 1), P(0, 1, 1)]], [new Vec3(0, 0, -1), [P(0, 0, 0), P(0, 1, 0), P(1, 1, 0), P(1, 0, 0)]],
  ];
  for (const [n, [a, b, c, d]] of faces) {
    const col = shade(rgb, n);
    for (const v of [a, b, c, a, c, d]) coloredVertex(g, v, col);
  }
}

/** Triangles `[ax, ay, az, bx, …]` (lib/shapes/tessellate.js), each shaded by its own normal. */
export function trianglesMesh(g, corners, rgb) {
  const a = new Vec3(), b = new Vec3(), c = new Vec3(), e1 = new Vec3(), e2 = new Vec3(), n = new Vec3();
  for (let i = 0; i + 8 < corners.length; i += 9) {
    a.x = corners[i]; a.y = corners[i + 1]; a.z = corners[i + 2];
    b.x = corners[i + 3]; b.y = corners[i + 4]; b.z = corners[i + 5];
    c.x = corners[i + 6]; c.y = corners[i + 7]; c.z = corners[i + 8];
    cross(n, sub(e1, b, a), sub(e2, c, a));
    if (n.x === 0 && n.y === 0 && n.z === 0) continue;
    const col = shade(rgb, normalize(n, n));
    coloredVertex(g, a, col); coloredVertex(g, b, col); coloredVertex(g, c, col);
  }
}

/** A huge sphere or a plane: a square patch of it under the scene, big enough to stand on. */
export function groundPatch(g, bounds, origin, towardScene, radius, rgb) {
  const n = normalize(new Vec3(), towardScene);
  const c = bounds.center;
  // the patch's middle: on the surface, under the middle of the scene
  const base = radius > 0 ? new Vec3(origin.x + n.x * radius, origin.y + n.y * radius, origin.z + n.z * radius) : origin;
  const k = dot(sub(new Vec3(), c, base), n);
  const mid = new Vec3(c.x - n.x * k, c.y - n.y * k, c.z - n.z * k);
  const u = normalize(new Vec3(), cross(new Vec3(), n, Math.abs(n.x) < 0.9 ? new Vec3(1, 0, 0) : new Vec3(0, 0, 1)));
  const v = cross(new Vec3(), n, u);
  const h = bounds.radius * 1.1;
  const corner = (a, b) => new Vec3(mid.x + (u.x * a + v.x * b) * h, mid.y + (u.y * a + v.y * b) * h, mid.z + (u.z * a + v.z * b) * h);
  const [p, q, s, t] = [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)];
  const col = shade(rgb, n);
  for (const x of [p, q, s, p, s, t]) coloredVertex(g, x, col);
}

/** The distance along the view direction to the nearest shape in front of the eye (for the image plane to stay clear of it). */
export function nearestAhead(scene, camera) {
  let nearest = Infinity;
  for (const o of scene.objects) {
    const ball = ballOf(o);
    if (!ball || ball.radius > HUGE_RADIUS) continue;
    const along = dot(sub(new Vec3(), ball.center, camera.position), camera.forward) - ball.radius;
    if (along > 0) nearest = Math.min(nearest, along);
  }
  return Number.isFinite(nearest) ? nearest : 10;
}
