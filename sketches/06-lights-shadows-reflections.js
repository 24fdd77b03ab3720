/**
 * 06 · Lights, shadows and reflections (slides "Part 2: Coding": a scene of
 * spheres with materials — surface colour, reflection, transparency, emission —
 * and what colour is this pixel?). From each hit point the tracer sends a
 * shadow ray to each light; a mirror sends the ray on, glass bends it through.
 * One switch per idea; each one re-traces the picture.
 */
import p5 from 'p5';
import { Scene, Sphere, Plane, PointLight, Camera, EPSILON } from '../lib/index.js';
import '../lib/p5/index.js'; // the sketchbook's p5 addon: p.createTracerView, p.createInspector, …

const WIDTH = 160, HEIGHT = 120;    // traced pixels
const SMALL_OFFSET = 1e-4;          // ε: how far a shadow ray starts off the surface
const BIG_OFFSET = 0.3;             // far too far: shadows come loose from what casts them
const MAX_BOUNCES = 5;              // mirror and glass bounces (scene.maxDepth)
const GLASS = 0.9;                  // the glass sphere's transparency when it is on

/** A floor, a mirror, a red ball, a glass ball, a point light and a lamp (an emissive sphere). */
function makeScene() {
  const scene = new Scene({ background: [0.55, 0.7, 0.9], ambient: 0.2, maxDepth: MAX_BOUNCES });
  scene.add(new Plane([0, -1, 0], [0, 1, 0], { color: [0.8, 0.8, 0.76], name: 'floor' }));
  scene.add(new Sphere([-2.4, 0, -10], 1, { color: [0.95, 0.95, 0.95], reflection: 0.85, specular: 0.6, name: 'mirror' }));
  scene.add(new Sphere([0, 0, -11], 1, { color: [0.95, 0.25, 0.3], specular: 0.6, shininess: 40, name: 'red ball' }));
  scene.add(new Sphere([2.4, 0, -10], 1, { color: [0.95, 1, 0.97], transparency: GLASS, ior: 1.5, specular: 0.8, name: 'glass' }));
  scene.add(new PointLight([4, 8, -3], { intensity: 0.85, name: 'point light' }));
  scene.add(new Sphere([-4, 3, -16], 0.6, { color: [0, 0, 0], emission: [1, 0.8, 0.5], name: 'lamp' }));
  return scene;
}

new p5((p) => {
  const scene = makeScene();
  const glass = scene.objects.find((o) => o.name === 'glass');

  p.setup = () => {
    p.noCanvas(); // the tracer view brings its own canvas
    const column = p.createDiv().addClass('column'); // the picture, its switches below
    const view = p.createTracerView({ scene, camera: new Camera({ width: WIDTH, height: HEIGHT, position: [0, 1.6, 2], pitch: -9 }), parent: column });
    p.createInspector({ view, parent: 'sketch' });

    const panel = p.createSwitches({ parent: column, legend: 'One switch per idea' });
    const shadows = panel.toggle('shadows', 'a shadow ray from each hit point to each light: blocked means dark (scene.shadows).');
    const offset = panel.choice('shadow-ray offset', [[`${SMALL_OFFSET} (a small ε)`, SMALL_OFFSET], ['0 (none: acne)', 0], [`${BIG_OFFSET} (too big)`, BIG_OFFSET]],
      'a shadow or mirror ray starts this far off the surface, so that rounding cannot make it hit the very surface it starts on. ' +
      'At 0 (and with no smallest t either) the surfaces fill with dark speckles: "shadow acne". Too big, and shadows come loose ' +
      'from what casts them (scene.bias, scene.epsilon).');
    const bounces = panel.slider('mirror bounces', { min: 0, max: MAX_BOUNCES, value: MAX_BOUNCES },
      '0: mirrors and glass look like plain paint; each bounce lets the ray go on once more (scene.maxDepth).');
    const specular = panel.toggle('highlights', 'the shiny spot where a light is mirrored toward the eye (scene.specular).');
    const seeThrough = panel.toggle('glass', `the right ball lets ${GLASS * 100}% of the light through, bent (its material.transparency).`);

    // Any switch: read every switch into the scene and trace it again.
    panel.onChange(() => {
      scene.shadows = shadows.checked();
      scene.bias = Number(offset.value());
      scene.epsilon = scene.bias === 0 ? 0 : EPSILON; // no guard at all: acne shows
      scene.maxDepth = Number(bounces.value());
      scene.specular = specular.checked();
      glass.material.transparency = seeThrough.checked() ? GLASS : 0;
      view.restart();
    });
    p.createSceneView({ view, parent: column, width: 600, height: 400, label: 'In 3D: click a pixel to see its shadow rays and bounces' });
    p.createTaskList({ page: '06', view }); // the page's tasks, ticked off as they are done
  };
}, document.getElementById('sketch'));
