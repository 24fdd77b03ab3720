/**
 * 03 · The geometric approach (slides "Geometric Approach", after scratchapixel).
 *
 *   L = C − Ro,  tca = L·Rd,  d² = L·L − tca²,  thc = √(r² − d²),  t = tca ∓ thc.
 *   d > r: no hit. tca < 0: no hit — but only when the eye is outside the sphere!
 *
 * The construction is drawn for the selected pixel's ray, next to the same t
 * found by the quadratic. Tick "eye inside the sphere" to move the eye into
 * the sphere: the centre pixel then has tca < 0 and still hits, at tca + thc.
 */
import p5 from 'p5';
import { Camera, Scene, Sphere, PointLight, intersectQuadratic, intersectGeometric } from '../lib/index.js';
import { formatLabel, createAnnouncer } from '../lib/p5/index.js'; // and the sketchbook's p5 addon: p.createTracerView, …

// The worksheet's sphere, an eye outside it and an eye inside it (past its centre, a little high).
const SPHERE_CENTER = [0, 0, -20], SPHERE_RADIUS = 4, COLOR = [1, 0.32, 0.36];
const OUTSIDE = { position: [0, 0, 0], fov: 30 };
const INSIDE = { position: [0, 1.5, -22.5], fov: 90 };
const WIDTH = 64, HEIGHT = 48;
const FIRST_PIXEL = [40, 16]; // selected at the start: a ray that passes off the centre

function makeScene() {
  const ball = new Sphere(SPHERE_CENTER, SPHERE_RADIUS, { color: COLOR, name: 'pink' });
  const lamp = (position, name) => new PointLight(position, { name });
  return new Scene({ background: [0.93, 0.95, 0.98], ambient: 0.15 })
    .add(ball).add(lamp([-10, 10, 10], 'lamp outside')).add(lamp([2, 2, -19], 'lamp inside the sphere'));
}

new p5((p) => {
  let view, voice; // voice: the sentence below the picture, said with the pixel for a screen reader

  p.setup = () => {
    voice = createAnnouncer({ name: 'explain', order: 1 });
    view = p.createTracerView({ scene: makeScene(), camera: new Camera({ width: WIDTH, height: HEIGHT, ...OUTSIDE }), parent: 'picture', scale: 8, label: 'Click a pixel' });
    view.figure.parentElement.prepend(view.figure);
    p.createCanvas(620, 500).parent('diagram');
    p.pixelDensity(1);
    p.createElement('table').class('compare').id('compare').attribute('data-compare', '').parent('diagram');
    p.createInspector({ view, parent: 'sketch' });
    p.createSceneView({
      view, parent: 'diagram', width: 620, height: 420, planeDistance: 3, orbit: { yaw: -62, pitch: 14, distance: 24 },
      construction: view.scene.spheres[0], label: 'L, tca, d and thc in 3D: drag to turn',
    });
    p.select('#inside').changed(function () {
      view.setCamera(new Camera({ width: WIDTH, height: HEIGHT, ...(this.checked() ? INSIDE : OUTSIDE) }));
    });
    view.onSelect(() => p.redraw());
    view.select(...FIRST_PIXEL);
    p.createTaskList({ page: '03', view }); // the page's tasks, ticked off as they are done
    p.noLoop();
  };

  p.draw = () => {
    const s = view.selected;
    if (!s) return;
    const ray = view.camera.primaryRay(s.x, s.y).ray, ball = view.scene.spheres[0];
    const q = intersectQuadratic(ray, ball), g = intersectGeometric(ray, ball);
    p.background('#f6f7f9');
    p.drawGeometricConstruction({ sphere: ball, ray, result: g, x: 0, y: 0, w: 620, h: 500 });
    compare(q, g);
    explain(g);
  };

  /** The two routes side by side: the same t0, t1 and t (cells set as text, never parsed as HTML). */
  function compare(q, g) {
    const cell = (tag, text) => Object.assign(document.createElement(tag), { textContent: text });
    const row = (name, a, b, cls = '') => {
      const tr = Object.assign(document.createElement('tr'), { className: cls });
      const [qa, gb] = [cell('td', a), cell('td', b)];
      Object.assign(qa.dataset, { route: 'quadratic', field: name });
      Object.assign(gb.dataset, { route: 'geometric', field: name });
      tr.append(cell('th', name), qa, gb);
      return tr;
    };
    const head = document.createElement('tr');
    head.append(cell('th', ''), cell('th', 'quadratic'), cell('th', 'geometric'));
    p.select('#compare').elt.replaceChildren(cell('caption', 'The same ray, both routes'), head,
      row('hit if > 0', `B² − 4AC = ${formatLabel(q.discriminant, 2)}`, `r² − d² = ${formatLabel(SPHERE_RADIUS ** 2 - g.d2, 2)}`),
      row('t0', formatLabel(q.t0, 3), formatLabel(g.t0, 3)), row('t1', formatLabel(q.t1, 3), formatLabel(g.t1, 3)),
      row('t', formatLabel(q.t, 3), formatLabel(g.t, 3), 't'));
  }

  /** One sentence about this ray: which rule decides, with its numbers. */
  function explain(g) {
    const inside = g.d2 + g.tca * g.tca < SPHERE_RADIUS ** 2; // |L| < r
    const sentence = inside
      ? `The eye is inside the sphere (|L| < r). tca = ${formatLabel(g.tca, 2)}${g.tca < 0 ? ' < 0, yet' : ', and'} the ray hits at t = tca + thc = ${formatLabel(g.tca, 2)} + ${formatLabel(g.thc, 2)} = ${formatLabel(g.t, 2)}.`
      : g.tca < 0 ? `tca = ${formatLabel(g.tca, 2)} < 0 and the eye is outside: the sphere is behind the eye, no intersection.`
        : g.roots === 0 ? `d = ${formatLabel(Math.sqrt(g.d2), 2)} > r = ${SPHERE_RADIUS}: the ray passes the sphere by, no intersection.`
          : `tca = ${formatLabel(g.tca, 2)} ≥ 0 and d ≤ r: the ray hits first at t = tca − thc = ${formatLabel(g.t, 2)}.`;
    p.select('#now').elt.textContent = sentence;
    voice.say(sentence); // with the pixel, in the page's one message
  }
}, document.getElementById('sketch'));
