/**
 * 14 · Spot and area lights, soft shadows.
 *
 * A point light: a hit point either sees it or does not, so a shadow is all or
 * nothing and its edge is hard. An area light is a disc: the hit point sends a
 * shadow ray to each of its `samples` points (an n × n grid mapped onto the
 * disc) and gets that share of its light. Where the ball hides some of the
 * points and not others, the share is between 0 and 1: that ring is the
 * penumbra. Left: the same ball under a point light at the disc's centre.
 * Right: under the disc, with 1, 4 or 16 shadow rays per hit (1 is a point again).
 *
 * A spot light is a point light that shines in a cone of half-angle `angle`:
 * full strength inside, none outside, and a smooth rim between, smoothstep
 * over the outer 20 % of the angle, so its circle on the floor is soft-edged.
 * It also fades with distance d, by 1 / (1 + k·d²) with k its `attenuation`.
 * Click a pixel: the inspector says how many of the disc's shadow rays reached
 * it, whether it is outside the spot's cone, and the spot's falloff there.
 */
import p5 from 'p5';
import { Scene, Sphere, Plane, Cylinder, PointLight, AreaLight, SpotLight, Camera } from '../lib/index.js';
import '../lib/p5/index.js'; // the sketchbook's p5 addon: p.createTracerView, p.createInspector, …

const WIDTH = 96, HEIGHT = 72, SCALE = 4;
const LAMP = [-7, 12, -13], LAMP_RADIUS = 5; // the disc, and the point light at its centre
const SAMPLES = [1, 4, 16], ANGLES = [12, 20, 30];
const START = { samples: 16, angle: 20 };

/** The floor, a ball, a cylinder in a spot light's circle, and either a point light or a disc of light over the ball. */
function makeScene({ lamp, samples, angle }) {
  const scene = new Scene({ background: [0.82, 0.9, 1], ambient: 0.1 });
  scene.add(new Plane([0, -4, 0], [0, 1, 0], { color: [0.85, 0.85, 0.85], name: 'floor' }));
  scene.add(new Sphere([2, -1, -20], 3, { color: [1, 0.32, 0.36], name: 'pink ball' }));
  scene.add(new Cylinder([-7, -2, -24], 1.5, 4, { color: [0.3, 0.6, 1], name: 'blue cylinder' })); // center, radius, height
  scene.add(new SpotLight([-7, 12, -18], [-7, -4, -23], { angle, color: [1, 0.85, 0.5], intensity: 0.7, attenuation: 0.002, name: 'spot' }));
  scene.add(lamp === 'point' ? new PointLight(LAMP, { intensity: 0.8, name: 'bulb' })
    : new AreaLight(LAMP, LAMP_RADIUS, { samples, intensity: 0.8, name: 'disc' }));
  return scene;
}

/** The page's key line for the selected pixel `s`: how many of the disc's shadow rays reached it (from the view's record of that pixel). */
function shadowRaysLine(view, s) {
  const hit = s && view.record?.hit, disc = hit?.areaLights?.[0];
  if (!s || !disc) return s ? `Pixel ${s.x},${s.y}: ${hit ? 'no shadow ray to the disc (it faces away)' : 'its ray hits nothing'}.` : '';
  const rays = `${disc.reached} of ${disc.samples} shadow ray${disc.samples === 1 ? '' : 's'}`;
  return `Pixel ${s.x},${s.y}: ${rays} reached it (${Math.round((100 * disc.reached) / disc.samples)} % of the disc seen).`;
}

const discLabel = (n) => n === 1 ? 'A disc with 1 shadow ray: a point again' : `A disc of light, ${n} shadow rays: a soft shadow`;

new p5((p) => {
  p.setup = () => {
    p.noCanvas(); // the tracer views bring their own canvases
    const state = { ...START };
    const camera = new Camera({ width: WIDTH, height: HEIGHT, fov: 45, position: [0, 5, 2], pitch: -20 });
    const hard = p.createTracerView({ scene: makeScene({ ...state, lamp: 'point' }), camera, scale: SCALE, parent: 'views', label: 'A point light: a hard shadow' });
    const soft = p.createTracerView({ scene: makeScene({ ...state, lamp: 'disc' }), camera, scale: SCALE, parent: 'views', label: discLabel(state.samples) });
    const views = [hard, soft];
    for (const view of views) view.onSelect((s) => { // one selected pixel for both pictures
      for (const other of views) if (other.selected?.x !== s?.x || other.selected?.y !== s?.y) other.select(s ? s.x : null, s?.y);
    });
    const retrace = () => {
      hard.setScene(makeScene({ ...state, lamp: 'point' }));
      soft.setScene(makeScene({ ...state, lamp: 'disc' }));
      soft.figure.querySelector('figcaption.rt-label')?.replaceChildren(discLabel(state.samples));
    };
    addChoices('samples', SAMPLES, state, retrace, (n) => ` ${n}`);
    addChoices('angle', ANGLES, state, retrace, (n) => ` ${n}°`);
    p.createInspector({ view: soft, parent: 'sketch' });
    p.createSceneView({ view: soft, parent: 'sketch', orbit: { yaw: 55, pitch: 22, distance: 30 }, planeDistance: 3 }); // from the side: the disc, the ball and the pixel's shadow rays
    const keyLine = document.getElementById('shadow-rays'); // under the pictures: the panel's lines are further down
    soft.onSelect((s) => { keyLine.textContent = shadowRaysLine(soft, s); });
    soft.select(73, 33); // on the floor at the rim of the ball's shadow: half the disc's points hidden
    p.createTaskList({ page: '14', view: soft }); // the page's tasks, ticked off as they are done
  };

  /** Radio buttons for one setting; a change traces both pictures again. */
  function addChoices(key, values, state, retrace, text) {
    const box = document.getElementById(key);
    for (const n of values) {
      const input = Object.assign(document.createElement('input'), { type: 'radio', name: key, value: String(n), checked: n === state[key] });
      input.addEventListener('change', () => { state[key] = n; retrace(); });
      const label = document.createElement('label');
      label.append(input, text(n));
      box.append(label);
    }
  }
}, document.getElementById('sketch'));
