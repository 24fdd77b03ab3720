/**
 * The photon view: light-based tracing as a picture (lib/tracing/photons.js). Photons
 * leave the lights a batch per animation frame; the few that reach the eye
 * build the picture, under a live count ("of 1,000,000 rays from the light,
 * 58 reached the eye: 0.0058 %"). Once the photons are sent it hands a sample
 * of their paths to a 3D scene view. With reduced motion (the system's
 * setting) the picture and the count show once every photon is sent.
 *
 *   const view = p.createTracerView({ scene, camera });
 *   const photons = p.createPhotonView({ scene, camera, seed: 1968, link: view });
 *
 * The canvas is a traced picture of the page contract (data-tracer,
 * data-width, data-height); it holds the page in "rendering" while photons
 * are still on their way.
 */
import { PhotonTracer } from '../../tracing/photons.js';
import { checkOptions, positiveInteger, show } from '../../text/check.js';
import { registerView } from '../page/page-state.js';
import { useStyle, element, resolveParent, sketchNode } from '../dom.js';
import { RAY_COLORS } from '../scene-view/view.js';
import { arrowMove } from './input.js';
import { cappedScale, roomFor, watchRoom } from './layout.js';
import { describeScene } from '../../lesson/describe.js';
import { reducedMotion } from '../page/announce.js';

const OPTIONS = ['scene', 'camera', 'seed', 'eyeRadius', 'photons', 'samplePaths', 'scale', 'parent', 'label', 'budgetMs', 'link', 'sceneView'];

/**
 * @param {import('p5').default} p the sketch
 * @param {object} options
 * @param {import('../../scene/scene.js').Scene} options.scene
 * @param {import('../../math/camera.js').Camera} options.camera
 * @param {number} [options.seed=1] the photons' random sequence: the same seed, the same picture
 * @param {number} [options.eyeRadius=2] the pupil's radius in scene units
 * @param {number} [options.photons=1000000] photons per run (the "more" button sends as many again)
 * @param {number} [options.samplePaths=12] photon paths handed to the 3D view
 * @param {number} [options.scale=10] on-screen pixels per traced pixel with 16 px text (grown on a big screen, shrunk to a narrow one, as a tracer view's)
 * @param {HTMLElement|string|{elt: HTMLElement}} [options.parent] where to put it; default the sketch's node
 * @param {string} [options.label] a caption above the picture
 * @param {number} [options.budgetMs=12] photon time per animation frame
 * @param {import('./view.js').TracerView} [options.link] a tracer view: a click here selects the same pixel there
 * @param {import('../scene-view/view.js').SceneView} [options.sceneView] a 3D view to show sample photon paths in
 * @returns {PhotonView}
 */
export function createPhotonView(p, options) {
  return new PhotonView(p, options);
}

let ids = 0;

export class PhotonView {
  #tracer; #target; #ctx; #image; #page; #raf = 0; #destroyed = false; #unwatchRoom;

  constructor(p, options = {}) {
    const { scene, camera, seed = 1, eyeRadius = 2, photons = 1_000_000, samplePaths = 12, scale = 10, parent, label = 'From the light: photons', budgetMs = 12, link = null, sceneView = null } = checkOptions(options, OPTIONS, 'photon view');
    this.photonsPerRun = positiveInteger(photons, 'photons');
    if (!(typeof scale === 'number' && scale > 0 && Number.isFinite(scale))) throw new RangeError(`scale must be a number greater than 0, got ${show(scale)}`);
    if (!(typeof budgetMs === 'number' && budgetMs > 0 && Number.isFinite(budgetMs))) throw new RangeError(`budgetMs must be a number of milliseconds greater than 0, got ${show(budgetMs)}`);
    this.#tracer = new PhotonTracer({ scene, camera, seed, eyeRadius, samplePaths });
    this.#target = this.photonsPerRun;
    this.budgetMs = budgetMs;
    this.link = link;
    this.sceneView = sceneView;
    useStyle();
    this.#buildDom(p, parent, label, scale, camera, scene);
    this.#page = registerView(this);
    this.#schedule();
  }

  /** The photon tracer (its `emitted`, `reached`, `share`, `paths`). */
  get tracer() { return this.#tracer; }
  /** The `<canvas data-tracer>` with the photons' picture. */
  get canvas() { return this.canvasElement; }
  /** True once every photon asked for is sent. */
  get done() { return this.#tracer.emitted >= this.#target; }

  /** Sends `photonsPerRun` more photons (the picture keeps what it has). */
  more() {
    this.#target += this.photonsPerRun;
    this.#page.rendering();
    this.#schedule();
    return this;
  }

  /** Stops and leaves the page. */
  destroy() {
    if (this.#destroyed) return;
    this.#destroyed = true;
    cancelAnimationFrame(this.#raf);
    this.#unwatchRoom();
    this.#page.unregister();
    this.figure.remove();
  }

  #schedule() {
    if (!this.#raf && !this.#destroyed) this.#raf = requestAnimationFrame(this.#frame);
  }

  #frame = () => {
    this.#raf = 0;
    const t = this.#tracer, start = performance.now();
    while (t.emitted < this.#target && performance.now() - start < this.budgetMs) t.emit(Math.min(2000, this.#target - t.emitted));
    if (reducedMotion() && !this.done) return this.#schedule(); // less motion: no picture growing step by step, the last one at once
    t.writePicture(this.#image.data);
    this.#ctx.putImageData(this.#image, 0, 0);
    this.countText.textContent = `Of ${t.emitted.toLocaleString('en-US')} rays from the light, ${t.reached.toLocaleString('en-US')} reached the eye: ${percent(t.share)}.`;
    if (!this.done) return this.#schedule();
    this.sceneView?.setExtraRays(this.#pathRays());
    this.#page.done();
  };

  /** The sample photon paths as 3D rays: thick and orange for those that reached the eye. */
  #pathRays() {
    return this.#tracer.paths.flatMap(({ points, reached }) => points.slice(1).map((to, i) => ({
      from: points[i], to, color: reached ? RAY_COLORS.photon : '#f3b36b', weight: reached ? 2.5 : 1,
    })));
  }

  #buildDom(p, parent, label, scale, camera, scene) {
    const W = camera.width, H = camera.height;
    const described = element('p', { id: `rt-photon-description-${++ids}`, hidden: '', 'data-picture-description': '' },
      `${W} by ${H} pixels, made by photons from the lights. ${describeScene(scene, camera)}`);
    const c = this.canvasElement = element('canvas', {
      class: 'rt-photon-canvas', 'data-tracer': '', 'data-photons': '', 'data-width': W, 'data-height': H, width: W, height: H,
      role: 'img', tabindex: '0', 'aria-describedby': described.id,
      'aria-label': 'The picture made by the photons that reached the eye: click a pixel, or use the arrow keys, to select it in the other picture',
    });
    Object.assign(c.style, { imageRendering: 'pixelated', display: 'block', background: '#000', cursor: 'crosshair' });
    this.#ctx = c.getContext('2d');
    this.#image = this.#ctx.createImageData(W, H);
    this.countText = element('p', { class: 'rt-photon-count', 'data-photon-count': '' });
    const more = element('button', { type: 'button', class: 'rt-button', 'data-photons-more': '' }, `Send ${this.photonsPerRun.toLocaleString('en-US')} more`);
    more.addEventListener('click', () => this.more());
    this.figure = element('figure', { class: 'rt-view rt-photon-view' }, label ? element('figcaption', { class: 'rt-label' }, label) : null, c, this.countText, more, described);
    resolveParent(parent, sketchNode(p)).append(this.figure);
    const size = () => { // the room it has, as a tracer view's picture (tracer-layout.js)
      const s = cappedScale(scale, W, H, roomFor(this.figure));
      Object.assign(c.style, { width: `${W * s}px`, height: `${H * s}px` });
    };
    size();
    this.#unwatchRoom = watchRoom(this.figure, size);
    c.addEventListener('pointerdown', (e) => {
      if (!this.link) return;
      const box = c.getBoundingClientRect();
      const x = Math.min(W - 1, Math.max(0, Math.floor(((e.clientX - box.left) / box.width) * W)));
      const y = Math.min(H - 1, Math.max(0, Math.floor(((e.clientY - box.top) / box.height) * H)));
      this.link.select(x, y);
    });
    c.addEventListener('keydown', (e) => { // the same keys as the tracer view's: arrows, Shift for ten
      const next = this.link && arrowMove(e.key, e.shiftKey, this.link.selected, W, H);
      if (!next) return;
      e.preventDefault();
      this.link.select(next.x, next.y);
    });
  }
}

/** A share as a percentage with enough digits not to read 0 %. */
export function percent(share) {
  if (share === 0) return '0 %';
  const digits = Math.max(1, Math.min(4, 1 - Math.floor(Math.log10(share * 100))));
  return `${(share * 100).toFixed(digits)} %`;
}
