/**
 * 02 · The quadratic (slide "An implicit form describing a sphere").
 *
 * Put R(t) = Ro + Rd·t into (Xs − Xc)² + (Ys − Yc)² + (Zs − Zc)² = r² and you
 * get At² + Bt + C = 0 with
 *   A = Xd² + Yd² + Zd²,  B = 2[(Xo − Xc)Xd + (Yo − Yc)Yd + (Zo − Zc)Zd],
 *   C = (Xo − Xc)² + (Yo − Yc)² + (Zo − Zc)² − r².
 * B² − 4AC < 0: no hit; = 0: one (tangent); > 0: two, t = (−B ± √(B² − 4AC)) / 2A.
 * Three pictures of the same sphere: shaded, the discriminant of every pixel,
 * and how many roots it has. They share one selected pixel; the parabola
 * f(t) = At² + Bt + C below crosses zero at the roots.
 */
import p5 from 'p5';
import { Camera, Scene, Sphere, PointLight } from '../lib/index.js';
import { createAnnouncer } from '../lib/p5/index.js'; // and the sketchbook's p5 addon: p.createTracerView, p.createInspector, …
import { mapValue } from '../lib/p5/tracer/map-words.js';

// The sphere (the worksheet's: centre (0, 0, −20), radius 4) and the screen.
const SPHERE = { x: 0, y: 0, z: -20, r: 4 };
const COLOR = [1, 0.32, 0.36];
const LIGHT = [-10, 10, 10];
const WIDTH = 64, HEIGHT = 48, SCALE = 6;
const VIEWS = { shaded: 'Shaded', discriminant: 'Discriminant B² − 4AC', roots: 'Roots: 0, 1 or 2' }; // mode: label
const FIELDS = [ // [name, label, slider min, max, step]
  ['x', 'Centre x (Xc)', -15, 15, 0.5],
  ['y', 'Centre y (Yc)', -12, 12, 0.5],
  ['z', 'Centre z (Zc)', -40, 10, 0.5],
  ['r', 'Radius r', 0.5, 12, 0.5],
];

function makeScene({ x, y, z, r }) {
  const ball = new Sphere([x, y, z], r, { color: COLOR, name: 'pink' });
  return new Scene({ background: [0.93, 0.95, 0.98], ambient: 0.15 }).add(ball).add(new PointLight(LIGHT));
}

new p5((p) => {
  const good = { ...SPHERE }; // the last values that made a picture
  let views;

  p.setup = () => {
    const eye = new Camera({ width: WIDTH, height: HEIGHT });
    const scene = makeScene(good);
    views = Object.entries(VIEWS).map(([mode, label]) =>
      p.createTracerView({ scene, camera: eye, mode, scale: SCALE, parent: 'views', label }));
    // One selected pixel for all three pictures.
    for (const view of views) view.onSelect((s) => {
      for (const other of views) if (other.selected?.x !== s?.x || other.selected?.y !== s?.y) other.select(s ? s.x : null, s?.y);
      p.redraw();
    });

    const panel = p.createDiv('<h2>The sphere: drag a slider or type a number</h2>').class('card fields').parent('left');
    for (const [name, label, min, max, step] of FIELDS) {
      p.createSliderField({ parent: panel, name, label, min, max, step, value: good[name], use: (value) => setSphere(name, value) });
    }
    p.createCanvas(560, 380).parent('left');
    p.pixelDensity(1);
    p.createInspector({ view: views[0], parent: 'sketch' });
    sayDiscriminant(views[0]);
    views[0].select(WIDTH / 2, HEIGHT / 2);
    p.createTaskList({ page: '02', view: views[0] }); // the page's tasks, ticked off as they are done
    p.noLoop();
  };

  /**
   * The shaded picture says the selected pixel's discriminant too, after the pixel (the maps say
   * their own value): a student who cannot see the maps hears a miss from a graze on any picture.
   */
  function sayDiscriminant(view) {
    const voice = createAnnouncer({ name: 'discriminant', order: 1 });
    view.onSelect((s) => {
      if (s && document.activeElement === view.canvas) voice.say(mapValue('discriminant', view.scene, view.camera, s.x, s.y));
    });
  }

  /** A new number for the sphere: all three pictures are traced again. A bad radius throws, and nothing changes. */
  function setSphere(name, value) {
    const scene = makeScene({ ...good, [name]: value }); // the Sphere checks the radius
    good[name] = value;
    for (const view of views) view.setScene(scene);
  }

  p.draw = () => {
    const s = views[0].selected;
    const record = s && views[0].record; // the selected pixel's record, made once for the inspector, the tasks and this
    p.background('#f6f7f9');
    p.drawParabola({ record, x: 0, y: 0, w: 560, h: 380 });
  };
}, document.getElementById('sketch'));
