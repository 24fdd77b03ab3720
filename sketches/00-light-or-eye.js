/**
 * 00 · From the light or from the eye (slide "Light-based Ray Tracing in
 * Nature / Eye-based Ray Tracing in Image Rendering").
 *
 * Left, light-based: photons leave the lights in random directions and
 * bounce diffusely off the class scene, taking each surface's colour; only
 * the few that pass through the eye land on the picture, so it builds up
 * slowly and stays full of holes. Right, eye-based: one ray per pixel, from
 * the eye, done at once. The 3D view shows some photon paths (orange; the
 * thick ones reached the eye) and the eye ray of the selected pixel.
 * The photons are random but repeatable: the same SEED gives the same picture.
 */
import p5 from 'p5';
import { Camera, classScene } from '../lib/index.js';
import { PhotonTracer } from '../lib/photons.js';
import { createTracerView, createInspector, createSceneView, registerView } from '../lib/p5/index.js';
import { RAY_COLORS } from '../lib/p5/scene-view.js';

// Try other numbers: the picture's size, the photons per run, the eye's size, the random seed.
const WIDTH = 32;
const HEIGHT = 24;
const PHOTONS = 1_000_000;
const EYE_RADIUS = 2; // the pupil, much enlarged: with a real one hardly any photon would arrive
const SEED = 1968;
const BUDGET_MS = 12; // photon time per frame
const PATHS_SHOWN = 12; // photon paths in the 3D view: the first ones sent, and as many that reached the eye

new p5((p) => {
  let photons, picture, ctx, image, count, page, target = PHOTONS, sceneView;

  p.setup = () => {
    p.noCanvas();
    const scene = classScene();
    const camera = new Camera({ width: WIDTH, height: HEIGHT });
    photons = new PhotonTracer({ scene, camera, seed: SEED, eyeRadius: EYE_RADIUS, samplePaths: PATHS_SHOWN });

    // The light-based picture: a canvas of its own, a traced picture like the tracer view's.
    const caption = p.createElement('h2', 'From the light: photons').parent('light');
    caption.class('rt-label');
    picture = p.createElement('canvas').parent('light').class('photon-canvas').elt;
    Object.assign(picture, { width: WIDTH, height: HEIGHT });
    picture.style.width = `${WIDTH * 10}px`;
    picture.style.height = `${HEIGHT * 10}px`;
    picture.setAttribute('data-tracer', '');
    picture.setAttribute('data-width', String(WIDTH));
    picture.setAttribute('data-height', String(HEIGHT));
    picture.setAttribute('aria-label', 'The picture made by the photons that reached the eye');
    ctx = picture.getContext('2d');
    image = ctx.createImageData(WIDTH, HEIGHT);
    count = p.createP('').parent('light').class('count').elt;
    const more = p.createButton('').parent('light').class('rt-button');
    more.elt.textContent = `Send ${PHOTONS.toLocaleString('en-US')} more`;
    more.mousePressed(() => { target += PHOTONS; page.rendering(); });
    page = registerView(picture);

    // The eye-based picture, and the 3D view of both kinds of ray.
    const view = createTracerView(p, { scene, camera, parent: 'eye', scale: 10, grid: true, label: 'From the eye: one ray per pixel' });
    createInspector({ view, parent: 'eye' });
    sceneView = createSceneView(p, { view, parent: 'light', label: 'In 3D: some photons (orange; thick: reached the eye) and the eye ray of the selected pixel', orbit: { yaw: -60, pitch: 25 } });
    view.select(16, 14);
    // A click on the photon picture selects the same pixel on the right.
    picture.addEventListener('pointerdown', (e) => {
      const box = picture.getBoundingClientRect();
      view.select(Math.min(WIDTH - 1, Math.floor(((e.clientX - box.left) / box.width) * WIDTH)), Math.min(HEIGHT - 1, Math.floor(((e.clientY - box.top) / box.height) * HEIGHT)));
    });
  };

  p.draw = () => {
    if (photons.emitted >= target) return;
    const start = performance.now();
    while (photons.emitted < target && performance.now() - start < BUDGET_MS) photons.emit(Math.min(2000, target - photons.emitted));
    photons.writePicture(image.data);
    ctx.putImageData(image, 0, 0);
    count.textContent = `Of ${photons.emitted.toLocaleString('en-US')} rays from the light, ${photons.reached.toLocaleString('en-US')} reached the eye: ${percent(photons.share)}.`;
    if (photons.emitted >= target) {
      sceneView.setExtraRays(photons.paths.flatMap(({ points, reached }) => points.slice(1).map((to, i) => ({ from: points[i], to, color: reached ? RAY_COLORS.photon : '#f3b36b', weight: reached ? 2.5 : 1 }))));
      page.done();
    }
  };
}, document.getElementById('sketch'));

/** A share as a percentage with enough digits to not read 0 %. */
function percent(share) {
  if (share === 0) return '0 %';
  const digits = Math.max(1, Math.min(4, 1 - Math.floor(Math.log10(share * 100))));
  return `${(share * 100).toFixed(digits)} %`;
}
