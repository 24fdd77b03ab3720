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
import '../lib/p5/index.js'; // the sketchbook's p5 addon: p.createTracerView, p.createPhotonView, …

// Try other numbers: the picture's size, the photons per run, the eye's size, the random seed.
const WIDTH = 32;
const HEIGHT = 24;
const PHOTONS = 1_000_000;
const EYE_RADIUS = 2; // the pupil, much enlarged: with a real one hardly any photon would arrive
const SEED = 1968;

new p5((p) => {
  p.setup = () => {
    p.noCanvas();
    const scene = classScene();
    const camera = new Camera({ width: WIDTH, height: HEIGHT });

    const view = p.createTracerView({ scene, camera, parent: 'eye', scale: 10, grid: true, label: 'From the eye: one ray per pixel' });
    p.createInspector({ view, parent: 'eye' });
    const sceneView = p.createSceneView({
      view, parent: 'three', orbit: { yaw: -60, pitch: 25 },
      label: 'In 3D: some photons (orange; thick: reached the eye) and the eye ray of the selected pixel',
    });
    const photons = p.createPhotonView({ scene, camera, seed: SEED, eyeRadius: EYE_RADIUS, photons: PHOTONS, parent: 'light', link: view, sceneView });
    view.select(16, 14);
    p.createTaskList({ page: '00', view, parts: { photons, sceneView } }); // the page's tasks, ticked off as they are done
  };
}, document.getElementById('sketch'));
