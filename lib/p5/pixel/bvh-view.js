/**
 * A mesh's bounding volume hierarchy in 3D, beside a tracer view: the boxes
 * at one depth of the tree, the boxes the selected pixel's ray entered, the
 * triangle it hit, and in words what that cost beside a loop over every
 * triangle (mesh.walk). Drawn on a 2D canvas, seen along a turning axis
 * (orthographic: boxes keep their true proportions). Arrow keys or the
 * buttons turn it; the slider chooses the depth.
 */
import { element, useStyle } from '../dom.js';
import { createAnnouncer } from '../page/announce.js';
import { checkOptions, show } from '../../text/check.js';
import { Mesh } from '../../shapes/mesh.js';

const STEP = Math.PI / 12; // one key press or button: 15°
const COLORS = { level: 'rgba(40, 90, 170, 0.55)', entered: '#d9480f', hit: '#c2255c', ray: '#212529', ground: '#868e96' };

/**
 * `p.createBvhView({ view, mesh, parent?, size?, depth? })`: the panel of
 * the mesh's tree beside the view (the options as BvhView's below).
 * @param {import('p5').default} _p the sketch (unused: the panel is plain DOM)
 * @param {object} options
 * @example
 * const view = p.createTracerView({ scene, camera });
 * p.createBvhView({ view, mesh }); // mesh: the Mesh in the view's scene
 */
export function createBvhView(_p, options) {
  const checked = checkOptions(options, ['view', 'mesh', 'parent', 'size', 'depth'], 'createBvhView');
  if (!checked.view || typeof checked.view.onSelect !== 'function') throw new TypeError(`view must be a tracer view (createTracerView), got ${show(checked.view)}`);
  if (!(checked.mesh instanceof Mesh)) throw new TypeError(`mesh must be a Mesh (new Mesh(…) or Mesh.fromOBJ(…)), got ${show(checked.mesh)}`);
  return new BvhView(checked);
}

export class BvhView {
  /**
   * @param {object} options
   * @param {import('../tracer/view.js').TracerView} options.view the tracer view whose selected pixel's ray is walked
   * @param {import('../../shapes/mesh.js').Mesh} options.mesh the mesh, as it is in the view's scene
   * @param {string|HTMLElement} [options.parent] where the panel goes (an id or an element; the page's end else)
   * @param {number} [options.size=320] the 3D view's width in CSS pixels (its height is ¾ of it)
   * @param {number} [options.depth=3] the depth whose boxes are shown at first (the root is depth 0)
   */
  constructor({ view, mesh, parent, size = 320, depth = 3 }) {
    useStyle();
    this.view = view;
    this.mesh = mesh;
    this.yaw = -Math.PI / 6;
    this.pitch = Math.PI / 9;
    this.walk = null;
    this.pixel = null;
    this.levels = levelsOf(mesh.bvh);
    this.depth = Math.min(depth, this.levels.length - 1);
    this.#build(parent, size);
    this.#unwatch = view.onSelect((pixel) => this.#select(pixel));
    this.#select(view.selected);
  }

  #unwatch;
  /** The counts are said by the page's one voice, after the pixel they belong to: a status of their own was a second message per key. */
  #voice = createAnnouncer({ name: 'bvh', order: 1 });

  /** The selected pixel's ray walked down the tree (null clears it). */
  #select(pixel) {
    this.pixel = pixel;
    this.walk = pixel ? this.mesh.walk(this.view.camera.primaryRay(pixel.x, pixel.y).ray) : null;
    this.counts.textContent = countsText(pixel, this.walk, this.mesh.triangleCount);
    if (pixel) this.#voice.say(this.counts.textContent); // with the pixel, in the page's one message
    this.draw();
  }

  /** Turns the view by `yaw` and `pitch` radians (pitch kept within ±80°). */
  turn(yaw, pitch = 0) {
    this.yaw += yaw;
    this.pitch = Math.max(-1.4, Math.min(1.4, this.pitch + pitch));
    this.draw();
  }

  /** Shows the boxes at depth `d` (0: the root box). */
  setDepth(d) {
    this.depth = Math.max(0, Math.min(this.levels.length - 1, Math.round(d)));
    this.slider.value = String(this.depth);
    this.depthText.textContent = `${this.depth}`;
    this.draw();
  }

  #build(parent, size) {
    const dpr = globalThis.devicePixelRatio || 1;
    this.canvas = element('canvas', { 'data-bvh-view': '', role: 'img', tabindex: 0, width: Math.round(size * dpr), height: Math.round(0.75 * size * dpr) });
    this.canvas.style.width = `${size}px`;
    this.canvas.style.maxWidth = '100%'; // a phone's narrow window: smaller, not wider than the page
    this.canvas.style.height = 'auto';
    this.canvas.addEventListener('keydown', (e) => this.#key(e));
    this.counts = element('p', { 'data-bvh-counts': '' });
    this.slider = element('input', { type: 'range', min: 0, max: this.levels.length - 1, value: this.depth, id: 'rt-bvh-depth' });
    this.slider.addEventListener('input', () => this.setDepth(Number(this.slider.value)));
    this.depthText = element('output', { for: 'rt-bvh-depth' }, `${this.depth}`);
    const button = (text, label, yaw, pitch) => {
      const b = element('button', { type: 'button', 'aria-label': label }, text);
      b.addEventListener('click', () => this.turn(yaw, pitch));
      return b;
    };
    this.panel = element('section', { class: 'card rt-bvh', 'data-bvh': '', 'aria-label': 'The bounding volume hierarchy' },
      element('h2', {}, 'The BVH: boxes within boxes'),
      this.counts,
      this.canvas,
      element('div', { class: 'controls' },
        element('label', { for: 'rt-bvh-depth' }, 'Boxes at depth '), this.slider, this.depthText,
        button('◀', 'Turn left', -STEP, 0), button('▶', 'Turn right', STEP, 0),
        button('▲', 'Tilt up', 0, STEP), button('▼', 'Tilt down', 0, -STEP)),
      element('p', { class: 'rt-note' }, 'Blue: the boxes at that depth. Orange: the boxes the ray went into. Red: the triangle it hit. Arrow keys turn the view.'));
    const into = typeof parent === 'string' ? document.getElementById(parent) : parent;
    (into ?? document.body).append(this.panel);
  }

  #key(e) {
    const turns = { ArrowLeft: [-STEP, 0], ArrowRight: [STEP, 0], ArrowUp: [0, STEP], ArrowDown: [0, -STEP] };
    if (turns[e.key]) { e.preventDefault(); this.turn(...turns[e.key]); } else if (e.key === '+' || e.key === '-') { e.preventDefault(); this.setDepth(this.depth + (e.key === '+' ? 1 : -1)); }
  }

  /** Draws the mesh, the boxes of the chosen depth, the boxes entered, the hit triangle and the ray. */
  draw() {
    const ctx = this.canvas.getContext('2d'), { width, height } = this.canvas;
    const project = projector(this.mesh.bounds(), this.yaw, this.pitch, width, height);
    ctx.clearRect(0, 0, width, height);
    ctx.fillStyle = '#f8f9fa';
    ctx.fillRect(0, 0, width, height);
    drawMesh(ctx, this.mesh, project);
    const lineWidth = width / 320;
    const boxes = (nodes, color, w) => {
      ctx.strokeStyle = color; ctx.lineWidth = w * lineWidth;
      for (const node of nodes) drawBox(ctx, this.mesh.bvh.box(node), project);
    };
    boxes(this.levels[this.depth], COLORS.level, 1);
    const walk = this.walk;
    if (walk) {
      boxes(walk.boxesEntered, COLORS.entered, 1.5);
      if (walk.triangle >= 0) drawTriangle(ctx, this.mesh, walk.triangle, project, lineWidth);
      this.#drawRay(ctx, project, lineWidth);
    }
    this.canvas.setAttribute('aria-label', this.#label());
  }

  #drawRay(ctx, project, lineWidth) {
    const { ray } = this.view.camera.primaryRay(this.pixel.x, this.pixel.y);
    const { min, max } = this.mesh.bounds();
    const reach = this.walk.t !== Infinity ? this.walk.t : distance(ray.origin, { x: (min.x + max.x) / 2, y: (min.y + max.y) / 2, z: (min.z + max.z) / 2 }) * 1.5;
    const at = (t) => project({ x: ray.origin.x + t * ray.direction.x, y: ray.origin.y + t * ray.direction.y, z: ray.origin.z + t * ray.direction.z });
    ctx.strokeStyle = COLORS.ray; ctx.lineWidth = 1.5 * lineWidth;
    ctx.setLineDash([4 * lineWidth, 3 * lineWidth]);
    line(ctx, at(0), at(reach));
    ctx.setLineDash([]);
    if (this.walk.t === Infinity) return;
    const hit = at(this.walk.t); // the hit point, ringed: a triangle of the bunny is small
    ctx.strokeStyle = COLORS.hit; ctx.lineWidth = 2 * lineWidth;
    ctx.beginPath(); ctx.arc(hit.x, hit.y, 6 * lineWidth, 0, 2 * Math.PI); ctx.stroke();
  }

  #label() {
    const n = this.levels[this.depth].length;
    let text = `The bunny's bounding volume hierarchy in 3D: ${n} box${n === 1 ? '' : 'es'} at depth ${this.depth} of ${this.levels.length - 1}`;
    if (this.walk) {
      const k = this.walk.boxesEntered.length;
      text += k === 0 ? `; the ray of pixel ${this.pixel.x},${this.pixel.y} misses the root box` : `; the ${k} box${k === 1 ? '' : 'es'} the ray of pixel ${this.pixel.x},${this.pixel.y} entered`;
      if (k > 0) text += this.walk.triangle >= 0 ? ` and the triangle it hit, number ${this.walk.triangle}` : ', and no triangle hit';
    }
    return `${text}.`;
  }

  /** Stops following the tracer view and takes the panel off the page. */
  remove() {
    this.#unwatch();
    this.#voice.destroy();
    this.panel.remove();
  }
}

/** The inspector's sentence for a ray's walk. */
export function countsText(pixel, walk, triangleCount) {
  const loop = `a loop over every triangle: ${triangleCount.toLocaleString('en-US')} tests`;
  if (!pixel || !walk) return `Click a pixel: its ray's walk down the tree, beside ${loop}.`;
  const at = `Pixel ${pixel.x},${pixel.y}: `;
  if (walk.boxesEntered.length === 0) return `${at}the ray missed the root box: 1 box test, no triangle tested; ${loop}.`;
  const tests = `the ray tested ${plural(walk.boxTests, 'box', 'boxes')} and ${plural(walk.triangleTests, 'triangle', 'triangles')}`;
  const hit = walk.triangle >= 0 ? `, and hit triangle ${walk.triangle}` : ', and hit none';
  return `${at}${tests}${hit}; ${loop}.`;
}

const plural = (n, one, many) => `${n.toLocaleString('en-US')} ${n === 1 ? one : many}`;

/** The tree's nodes by depth: levels[d] lists the nodes d steps below the root. */
function levelsOf(bvh) {
  const levels = [];
  let level = [0];
  while (level.length) {
    levels.push(level);
    const next = [];
    for (const node of level) if (bvh.nodes[2 * node + 1] === 0) next.push(bvh.nodes[2 * node], bvh.nodes[2 * node] + 1);
    level = next;
  }
  return levels;
}

/**
 * A function from a world point to the canvas (x, y and a depth, nearer is
 * larger): turned by yaw about y and pitch about x around the box's centre,
 * scaled so that the box fills about 70% of the canvas.
 */
function projector({ min, max }, yaw, pitch, width, height) {
  const cx = (min.x + max.x) / 2, cy = (min.y + max.y) / 2, cz = (min.z + max.z) / 2;
  const radius = Math.hypot(max.x - min.x, max.y - min.y, max.z - min.z) / 2;
  const k = (0.7 * Math.min(width, height)) / (2 * radius);
  const cosY = Math.cos(yaw), sinY = Math.sin(yaw), cosP = Math.cos(pitch), sinP = Math.sin(pitch);
  return ({ x, y, z }) => {
    const dx = x - cx, dy = y - cy, dz = z - cz;
    const x1 = cosY * dx + sinY * dz, z1 = -sinY * dx + cosY * dz;
    const y2 = cosP * dy - sinP * z1, z2 = sinP * dy + cosP * z1;
    return { x: width / 2 + k * x1, y: height / 2 - k * y2, depth: z2 };
  };
}

/** The mesh as light grey triangles, far ones first, shaded by how squarely they face the viewer. */
function drawMesh(ctx, mesh, project) {
  const points = mesh.positions.map(([x, y, z]) => project({ x, y, z }));
  const order = mesh.cells.map((cell, i) => i);
  const depth = mesh.cells.map(([a, b, c]) => points[a].depth + points[b].depth + points[c].depth);
  order.sort((i, j) => depth[i] - depth[j]);
  for (const i of order) {
    const [a, b, c] = mesh.cells[i].map((v) => points[v]);
    const cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    const area = Math.abs(cross) / 2, edge = Math.hypot(b.x - a.x, b.y - a.y) * Math.hypot(c.x - a.x, c.y - a.y);
    const facing = edge > 0 ? Math.min(1, (2 * area) / edge) : 0;
    const shade = Math.round(150 + 80 * facing);
    ctx.fillStyle = `rgb(${shade}, ${shade - 4}, ${shade - 12})`;
    ctx.beginPath(); ctx.moveTo(a.x, a.y); ctx.lineTo(b.x, b.y); ctx.lineTo(c.x, c.y); ctx.closePath(); ctx.fill();
  }
}

function drawTriangle(ctx, mesh, index, project, lineWidth) {
  const [a, b, c] = mesh.cells[index].map((v) => { const [x, y, z] = mesh.positions[v]; return project({ x, y, z }); });
  ctx.fillStyle = COLORS.hit; ctx.strokeStyle = COLORS.hit; ctx.lineWidth = 2 * lineWidth;
  ctx.beginPath(); ctx.moveTo(a.x, a.y); ctx.lineTo(b.x, b.y); ctx.lineTo(c.x, c.y); ctx.closePath(); ctx.fill(); ctx.stroke();
}

/** A box's 12 edges. */
function drawBox(ctx, { min, max }, project) {
  const corner = (i) => project({ x: i & 1 ? max.x : min.x, y: i & 2 ? max.y : min.y, z: i & 4 ? max.z : min.z });
  const c = Array.from({ length: 8 }, (_, i) => corner(i));
  ctx.beginPath();
  for (let i = 0; i < 8; i++) {
    for (const bit of [1, 2, 4]) if (!(i & bit)) { ctx.moveTo(c[i].x, c[i].y); ctx.lineTo(c[i | bit].x, c[i | bit].y); }
  }
  ctx.stroke();
}

function line(ctx, a, b) {
  ctx.beginPath(); ctx.moveTo(a.x, a.y); ctx.lineTo(b.x, b.y); ctx.stroke();
}

function distance(a, b) {
  return Math.hypot(a.x - b.x, a.y - b.y, a.z - b.z);
}
