/**
 * What the 3D view draws with its p5 (WEBGL) instance: the still part as a
 * p5.Geometry, the image plane textured with the traced picture, the frustum,
 * ray segments, lines and dots. Scene points are drawn with y negated (p5's
 * WEBGL y points down).
 */
import p5 from 'p5';
import { Vec3, sub, dot } from '../../math/vec3.js';
import { imagePlane } from '../../lesson/rays3d.js';
import { buildMeshes, shapesKey, lightLoops } from './mesh.js';
import { INK, MUTED, RAY, NORMAL, LIT, SHADOW, CONSTRUCT } from '../diagrams/style.js';

/** Colours of the kinds of ray (shadow rays as in the 2D diagrams). */
export const RAY_COLORS = { primary: RAY, normal: NORMAL, lit: LIT, shadow: SHADOW, away: MUTED, reflection: CONSTRUCT, refraction: '#0f8b8d', photon: '#e07b00', sample: '#7b3fbf', area: '#b7791f' };
/** Texels per traced pixel on the image plane's texture, at most. */
const MAX_TEXTURE = 512;

/**
 * A p5.Geometry from flat triangle lists (x, −y, z per vertex; r, g, b, a),
 * filled in directly: building it through fill() and vertex() parses a colour
 * per vertex, a second for the class scene's 20,000 vertices.
 */
export function toGeometry(g, { positions, colors }) {
  // p5's types know neither this constructor's renderer argument nor vertexColors, which p5 2.3 has.
  const Geometry = /** @type {any} */ (p5.Geometry);
  return new Geometry(1, 1, /** @this {any} the geometry being built */ function () {
    const n = positions.length / 3;
    for (let i = 0; i < n; i++) {
      this.vertices.push(g.createVector(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]));
      this.vertexNormals.push(g.createVector(0, 0, 1));
    }
    for (let i = 0; i < n; i += 3) this.faces.push([i, i + 1, i + 2]);
    this.vertexColors = colors;
  }, g._renderer);
}

/**
 * Everything that does not move (shapes, lights, the eye) as one p5.Geometry,
 * built again only when what it shows changed (scene-view-mesh.js); glass goes
 * into a second geometry, drawn last and see-through.
 */
export class StillGeometry {
  #key = ''; #solid = null; #glass = null;

  /**
   * Draws the solid part.
   * @param {{ scene: object, camera: object, bounds: object, constructionSphere: object|null }} state
   */
  drawSolid(g, state) {
    const key = shapesKey(state);
    if (!this.#solid || this.#key !== key) {
      for (const old of [this.#solid, this.#glass]) if (old) g.freeGeometry(old);
      const { mesh, glass } = buildMeshes(state);
      this.#solid = toGeometry(g, mesh);
      this.#glass = glass.positions.length > 0 ? toGeometry(g, glass) : null;
      this.#key = key;
    }
    g.model(this.#solid);
  }

  /**
   * The glass, after everything else: see-through, so the rays it bends show
   * inside it. It is tested against what is nearer but hides nothing behind
   * it (no depth writes), so its far side and what lies beyond show too.
   */
  drawGlass(g) {
    if (!this.#glass) return;
    const gl = g.drawingContext;
    gl.depthMask(false);
    g.model(this.#glass);
    gl.depthMask(true);
  }
}

/** A sphere as a few circles (three great circles and two latitudes), so what is inside it shows. */
export function wireSphere(g, sphere) {
  const c = sphere.center, r = sphere.radius, m = sphere.material.color, n = 48;
  g.push();
  g.noFill();
  g.stroke(Math.round(255 * Math.min(1, m[0])), Math.round(255 * Math.min(1, m[1])), Math.round(255 * Math.min(1, m[2])));
  g.strokeWeight(1.5);
  g.beginShape(g.LINES);
  const circle = (point) => {
    for (let i = 0; i < n; i++) {
      const a = point((2 * Math.PI * i) / n), b = point((2 * Math.PI * (i + 1)) / n);
      g.vertex(c.x + a[0] * r, -(c.y + a[1] * r), c.z + a[2] * r);
      g.vertex(c.x + b[0] * r, -(c.y + b[1] * r), c.z + b[2] * r);
    }
  };
  circle((t) => [Math.cos(t), Math.sin(t), 0]);
  circle((t) => [Math.cos(t), 0, Math.sin(t)]);
  circle((t) => [0, Math.cos(t), Math.sin(t)]);
  for (const y of [-0.6, 0.6]) { const k = Math.sqrt(1 - y * y); circle((t) => [k * Math.cos(t), y, k * Math.sin(t)]); }
  g.endShape();
  g.pop();
}

/** p5 coordinates of a scene point: y negated (p5's WEBGL y points down). */
function vertexUV(g, p, u, v) { g.vertex(p.x, -p.y, p.z, u, v); }

export function line3(g, a, b, color, weight) {
  g.push();
  g.stroke(color);
  g.strokeWeight(weight);
  g.line(a.x, -a.y, a.z, b.x, -b.y, b.z);
  g.pop();
}

function outline(g, pts, color, weight) {
  for (let i = 0; i < pts.length; i++) line3(g, pts[i], pts[(i + 1) % pts.length], color, weight);
}

function dot3(g, at, color, r) {
  g.push();
  g.noStroke();
  g.noLights();
  g.fill(color);
  g.translate(at.x, -at.y, at.z);
  g.sphere(r, 10, 6);
  g.pop();
}

/** One segment of a pixel's story (lib/lesson/rays3d.js raySegments) in its colour; `radius` is the scene's, for the dots. */
export function drawSegment(g, s, radius) {
  if (s.kind === 'shadow') {
    if (!s.facing) return line3(g, s.from, s.to, RAY_COLORS.away, 1);
    if (s.lit) return line3(g, s.from, s.to, RAY_COLORS.lit, 2.5);
    const stop = s.blockedAt ?? s.to;
    line3(g, s.from, stop, RAY_COLORS.shadow, 2.5);
    if (s.blockedAt) { line3(g, stop, s.to, RAY_COLORS.shadow, 0.75); dot3(g, stop, RAY_COLORS.shadow, radius * 0.012); }
    return;
  }
  const color = RAY_COLORS[s.kind];
  if (s.kind === 'sample') { // a sub-pixel ray: thin and violet, so the centre ray stays the one that stands out
    line3(g, s.from, s.to, color, 1);
    if (s.hit) dot3(g, s.to, color, radius * 0.007);
    return;
  }
  line3(g, s.from, s.to, color, s.kind === 'normal' ? 2.5 : s.depth === 0 ? 3 : 2);
  if (s.hit) dot3(g, s.to, color, radius * 0.012);
}

/** What each light of the scene draws of itself beyond a glow per source (lightLoops: an area light's rim). */
export function drawLightOutlines(g, scene) {
  for (const loop of lightLoops(scene)) outline(g, loop, RAY_COLORS.area, 2);
}

/** The image plane at `planeDistance`, textured with `picture` (a p5.Graphics), and its outline. */
export function drawImagePlane(g, camera, planeDistance, picture) {
  const [tl, tr, br, bl] = imagePlane(camera, planeDistance).corners;
  g.push();
  g.noLights();
  g.textureMode(g.NORMAL);
  g.texture(picture);
  g.beginShape(g.TRIANGLES);
  vertexUV(g, tl, 0, 0); vertexUV(g, tr, 1, 0); vertexUV(g, br, 1, 1);
  vertexUV(g, tl, 0, 0); vertexUV(g, br, 1, 1); vertexUV(g, bl, 0, 1);
  g.endShape();
  g.pop();
  outline(g, [tl, tr, br, bl], INK, 1.5);
}

/** The view frustum: from the eye past the image plane to a little beyond the middle of the scene. */
export function drawFrustum(g, camera, planeDistance, bounds) {
  const far = Math.max(planeDistance * 2, dot(sub(new Vec3(), bounds.center, camera.position), camera.forward) + bounds.radius * 0.5);
  const corners = imagePlane(camera, far).corners;
  for (const c of corners) line3(g, camera.position, c, MUTED, 1);
  outline(g, corners, MUTED, 1);
}

/** Texels per traced pixel on the image plane's texture: as many as fit in MAX_TEXTURE, at least 1. */
export function texelsPerPixel(width, height) {
  return Math.max(1, Math.floor(MAX_TEXTURE / Math.max(width, height)));
}

/**
 * Paints the image plane's texture: the traced pixels of `source` (a
 * W × H canvas) as blocks of k × k texels, the grid between them (when the
 * blocks are big enough to show it) and the selected pixel outlined.
 * @param {CanvasRenderingContext2D} ctx the texture's context, already W·k × H·k
 */
export function paintPicture(ctx, source, W, H, k, selected) {
  const c = ctx.canvas;
  ctx.fillStyle = '#e4e7ec'; // not traced yet
  ctx.fillRect(0, 0, c.width, c.height);
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(source, 0, 0, c.width, c.height);
  if (k >= 4) {
    ctx.beginPath();
    for (let x = 1; x < W; x++) { ctx.moveTo(x * k + 0.5, 0); ctx.lineTo(x * k + 0.5, c.height); }
    for (let y = 1; y < H; y++) { ctx.moveTo(0, y * k + 0.5); ctx.lineTo(c.width, y * k + 0.5); }
    ctx.strokeStyle = 'rgba(0, 0, 0, 0.25)';
    ctx.lineWidth = 1;
    ctx.stroke();
  }
  const s = selected;
  if (s) {
    const w = Math.max(2, Math.round(k / 5));
    ctx.lineWidth = w + 2; ctx.strokeStyle = 'rgba(0, 0, 0, 0.85)';
    ctx.strokeRect(s.x * k - w / 2, s.y * k - w / 2, k + w, k + w);
    ctx.lineWidth = w; ctx.strokeStyle = '#ffffff';
    ctx.strokeRect(s.x * k - w / 2, s.y * k - w / 2, k + w, k + w);
  }
}

/** The image plane's texture: a 2D p5.Graphics, painted again (paintPicture) only when the picture or the selection changed. */
export class PlaneTexture {
  #graphics; #ctx; #key = '';

  /** @param {any} q the 3D view's p5 instance */
  constructor(q) {
    this.#graphics = q.createGraphics(16, 16);
    this.#graphics.pixelDensity(1);
    this.#ctx = this.#graphics.drawingContext; // drawn through its own context
  }

  /** The p5.Graphics to texture the plane with. */
  get graphics() { return this.#graphics; }

  /** The traced picture changed: paint it again when next asked. */
  stale() { this.#key = ''; }

  /** Paints the W × H picture on `source` (a canvas) with `selected` outlined, unless it shows just that already. */
  update(source, W, H, selected) {
    const key = `${W}x${H}:${selected?.x},${selected?.y}`;
    if (this.#key === key) return;
    this.#key = key;
    const k = texelsPerPixel(W, H), pic = this.#graphics;
    if (pic.width !== W * k || pic.height !== H * k) { pic.resizeCanvas(W * k, H * k); this.#ctx = pic.drawingContext; }
    paintPicture(this.#ctx, source, W, H, k, selected);
  }

  /** Takes the hidden canvas off the page (p5's remove() leaves a p5.Graphics' behind). */
  remove() { this.#graphics.remove(); }
}
