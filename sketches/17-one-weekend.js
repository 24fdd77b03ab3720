/**
 * 17 · One weekend's final scene: path tracing, the book's way.
 *
 * The last picture of Ray Tracing in One Weekend, small: a grey ground (a
 * huge ball), a grid of small balls, each of paint, metal or glass at random,
 * and three big ones: glass in the middle, paint behind, metal in front.
 * There is no lamp: a path that leaves the scene gathers the sky (white at
 * the horizon, blue above), so every ball is lit by the sky and by the
 * light the others throw back. The kit's materials are the book's: colour
 * alone is paint (a cosine-weighted bounce), reflection 1 is metal (the
 * mirror direction plus fuzz times a random point in the unit ball),
 * transparency 1 is glass (Schlick's share mirrored, the rest refracted).
 * The balls are placed by a seeded sequence: the same scene every time.
 */
import p5 from 'p5';
import { Scene, Sphere, PointLight, Camera } from '../lib/index.js';
import '../lib/p5/index.js'; // the sketchbook's p5 addon: p.createTracerView, p.createPathPanel, …

const SAMPLES = 64, SKY = { top: [0.5, 0.7, 1], bottom: [1, 1, 1] };
const GLASS = { color: [1, 1, 1], transparency: 1, ior: 1.5 };

/** A seeded sequence of numbers in [0, 1): the same balls every time (a linear congruential generator). */
function sequence(seed) {
  let state = seed;
  return () => { state = (Math.imul(state, 1664525) + 1013904223) >>> 0; return state / 2 ** 32; };
}

/** The book's final scene on a 10 × 10 grid; `fuzzy` false polishes the small metal balls (fuzz 0). */
function finalScene(fuzzy) {
  const random = sequence(7);
  const scene = new Scene({ background: [0.7, 0.8, 1] }); // Whitted's colour for a miss; the paths see SKY
  scene.add(new PointLight([20, 40, 10])); // for Whitted's record in the inspector: the paths see only the sky
  scene.add(new Sphere([0, -1000, 0], 1000, { color: [0.5, 0.5, 0.5], name: 'ground' }));
  for (let a = -5; a < 5; a++) {
    for (let b = -5; b < 5; b++) {
      const center = [a + 0.9 * random(), 0.2, b + 0.9 * random()], pick = random();
      const clear = [[4, 0], [0, 0], [-4, 0]].every(([x, z]) => Math.hypot(center[0] - x, center[2] - z) > 1.2); // not inside a big ball
      if (!clear) continue;
      if (pick < 0.8) scene.add(new Sphere(center, 0.2, { color: [random() * random(), random() * random(), random() * random()], name: 'small paint ball' }));
      else if (pick < 0.95) {
        const color = [0.5 + random() / 2, 0.5 + random() / 2, 0.5 + random() / 2], fuzz = random() / 2; // drawn either way: the same balls
        scene.add(new Sphere(center, 0.2, { color, reflection: 1, fuzz: fuzzy ? fuzz : 0, name: 'small metal ball' }));
      } else scene.add(new Sphere(center, 0.2, { ...GLASS, name: 'small glass ball' }));
    }
  }
  scene.add(new Sphere([0, 1, 0], 1, { ...GLASS, name: 'big glass ball' }));
  scene.add(new Sphere([-4, 1, 0], 1, { color: [0.4, 0.2, 0.1], name: 'big paint ball' }));
  scene.add(new Sphere([4, 1, 0], 1, { color: [0.7, 0.6, 0.5], reflection: 1, name: 'big metal ball' }));
  return scene;
}

new p5((p) => {
  p.setup = () => {
    p.noCanvas(); // the tracer view brings its own canvas
    // The book's camera: from (13, 2, 3) toward the origin, a 20° field of view.
    const camera = new Camera({ width: 90, height: 60, fov: 20, position: [13, 2, 3], yaw: -77, pitch: -8.5 });
    const view = p.createTracerView({ scene: finalScene(true), camera, parent: 'views', label: 'Path traced under the sky', path: { samples: SAMPLES, sky: SKY } });
    for (const input of document.querySelectorAll('#fuzz input')) {
      input.addEventListener('change', () => view.setScene(finalScene(input.value === '1')));
    }
    const pathPanel = p.createPathPanel({ view, parent: 'sketch' });
    p.createInspector({ view, parent: 'sketch' });
    p.createTaskList({ page: '17', view, parts: { pathPanel } }); // the page's tasks, ticked off as they are done
    view.select(45, 50); // the ground in front: where the sky's light, bounced, is all there is
  };
}, document.getElementById('sketch'));
