/**
 * Homework self-checks: does the scene a student built look like the task?
 * Each check looks at the scene (where the lights are, what colour they give
 * off) and at the picture the camera sees (traced with the library itself),
 * and says what is right or what to fix, in a student's words.
 *
 *   checkTrafficSignal(scene, camera) // Task 1: red over yellow over green
 *   checkRearLights(scene, camera)    // Task 2: two red lights side by side
 *
 * Both return `{ passed, checks: [{ label, passed, detail, skipped?, bonus? }] }`;
 * their hints write code the way the page does: `{ prefix: 'RT.' }` gives
 * `new RT.Sphere(…)`, as a global-mode sketch (the one-file build) writes it.
 * `passed` is true when every check that is not a bonus passed. A check that
 * needs an earlier one (say, the lights' order needs three lights) is
 * `skipped` (and not passed) until that one passes.
 */
import { Camera } from '../math/camera.js';
import { ballOf } from '../shapes/index.js';
import { PointLight } from '../lights/point-light.js';
import { Ray } from '../math/ray.js';
import { nearestHit } from '../tracing/trace.js';
import { render } from '../tracing/render.js';
import { rgbToHsl } from '../math/color.js';
import { show, checkOptions } from '../text/check.js';

/** The picture the checks look at is at most this many pixels wide (smaller: faster). */
const SAMPLE_MAX_WIDTH = 320;
/**
 * Shapes bigger than this (a ground sphere, say) are not part of a car body.
 * Not modes.js's isHuge (a sphere of radius ≥ 100 stands for a ground): this
 * one also measures boxes, and asks a smaller question — could this be a part
 * of a car a few units wide? Anything 50 across is scenery.
 */
const HUGE = 50;

/* ======================= Task 1: the traffic signal ======================= */

const SIGNAL = ['red', 'yellow', 'green']; // top to bottom

/** The labels of Task 1's checks, in order. */
export const SIGNAL_CHECKS = {
  three: 'Three lights',
  colors: 'One red, one yellow, one green',
  column: 'Stacked in one column (same x and z)',
  order: 'Red on top, yellow in the middle, green at the bottom',
  seen: 'The camera sees all three',
  picture: 'In the picture: red, yellow, green from top to bottom',
};

/**
 * Task 1: three lights (emissive spheres) stacked vertically, red over
 * yellow over green, at about the same x and z, all in the camera's view.
 * @param {object} [options]
 * @param {string} [options.prefix] written before the library's names in hints: '' (default) or 'RT.'
 * @example
 * const { passed, checks } = checkTrafficSignal(classScene(), new Camera({ width: 64, height: 48 }));
 * // passed: false; checks: [{ label: 'Three lights', passed: false, detail: '…' }, …]
 */
export function checkTrafficSignal(scene, camera, options) {
  checkArguments(scene, camera);
  const { prefix = '' } = checkOptions(options, ['prefix'], 'checkTrafficSignal');
  const lights = findLights(scene);
  const checks = [];
  const add = (check) => (checks.push(check), check.passed);

  const three = add(threeLights(lights, scene, prefix));
  const byColor = three ? oneOfEach(lights, SIGNAL) : null;
  const colors = add(three ? colorsCheck(lights, byColor) : waiting(SIGNAL_CHECKS.colors, 'three lights'));
  const stack = colors ? SIGNAL.map((name) => byColor[name]) : null;
  add(colors ? sameColumn(stack) : waiting(SIGNAL_CHECKS.column, 'the three colours'));
  const ordered = add(colors ? topToBottom(stack) : waiting(SIGNAL_CHECKS.order, 'the three colours'));
  const seen = colors ? lookAt(scene, camera, stack) : null;
  const visible = add(colors ? allVisible(seen, camera) : waiting(SIGNAL_CHECKS.seen, 'the three colours'));
  add(visible ? pictureOrder(seen, ordered) : waiting(SIGNAL_CHECKS.picture, 'all three in view'));
  return result(checks);
}

function threeLights(lights, scene, prefix) {
  const label = SIGNAL_CHECKS.three;
  if (lights.length === 3) return pass(label, `Three lights: ${listNames(lights)}.`);
  if (lights.length === 0) return fail(label, noLightsYet(scene, prefix));
  return fail(label, `Found ${count(lights.length, 'light')} (${listNames(lights)}); a traffic signal has 3: red, yellow and green.`);
}

function colorsCheck(lights, byColor) {
  const label = SIGNAL_CHECKS.colors;
  if (byColor) return pass(label, 'Red, yellow and green: the three colours of a traffic signal.');
  const missing = SIGNAL.filter((name) => !lights.some((l) => l.color === name));
  return fail(label, `Your lights are ${listNames(lights)}: ${andList(missing)} ${missing.length > 1 ? 'are' : 'is'} missing. ` +
    'The colour of a light is its emission, e.g. emission: [1, 0.8, 0] for yellow.');
}

/** Roughly the same x and z: no further apart than the smallest light's radius. */
function sameColumn(stack) {
  const label = SIGNAL_CHECKS.column;
  const tolerance = Math.min(...stack.map((l) => l.radius));
  const [top] = stack;
  for (const light of stack.slice(1)) {
    const dx = light.center.x - top.center.x, dz = light.center.z - top.center.z;
    if (Math.abs(dx) > tolerance) {
      return fail(label, `The ${light.color} light is ${formatLabel(Math.abs(dx))} to the ${dx > 0 ? 'right' : 'left'} of the red one ` +
        `(x = ${formatLabel(light.center.x)}, red x = ${formatLabel(top.center.x)}): give all three the same x.`);
    }
    if (Math.abs(dz) > tolerance) {
      return fail(label, `The ${light.color} light is ${formatLabel(Math.abs(dz))} ${dz > 0 ? 'in front of' : 'behind'} the red one ` +
        `(z = ${formatLabel(light.center.z)}, red z = ${formatLabel(top.center.z)}): give all three the same z.`);
    }
  }
  return pass(label, `All three at x ≈ ${formatLabel(top.center.x)}, z ≈ ${formatLabel(top.center.z)}.`);
}

/** Red highest, then yellow, then green; no two overlapping. */
function topToBottom(stack) {
  const label = SIGNAL_CHECKS.order;
  const heights = stack.map((l) => `${l.color} y = ${formatLabel(l.center.y)}`).join(', ');
  const order = [...stack].sort((a, b) => b.center.y - a.center.y).map((l) => l.color);
  if (order.join() !== SIGNAL.join()) {
    return fail(label, `From top to bottom your lights are ${order.join(', ')} (${heights}). Red goes on top, green at the bottom: a larger y is higher.`);
  }
  for (let i = 0; i + 1 < stack.length; i++) {
    const upper = stack[i], lower = stack[i + 1];
    if (upper.center.y - lower.center.y < upper.radius + lower.radius - 1e-9) {
      return fail(label, `The ${upper.color} and ${lower.color} lights overlap (${heights}): move them further apart, ` +
        `at least ${formatLabel(upper.radius + lower.radius)} (the two radii added).`);
    }
  }
  return pass(label, `Top to bottom: ${heights}.`);
}

/** Where each light shows in the picture, in screen order (`ordered`: is the scene's order right?). */
function pictureOrder(seen, ordered) {
  const label = SIGNAL_CHECKS.picture;
  const order = [...seen].sort((a, b) => a.row - b.row).map((s) => s.light.color);
  if (order.join() !== SIGNAL.join()) {
    const why = ordered ? 'Is the camera looking straight up or down at them?' : 'Fix the order of the lights (above) and this follows.';
    return fail(label, `In the picture, from the top: ${order.join(', ')}. ${why}`);
  }
  const off = seen.find((s) => s.seenAs !== s.light.color);
  if (off) return fail(label, `The ${off.light.color} light looks ${off.seenAs} in the picture: is another light or a reflection changing its colour?`);
  return pass(label, `Seen from the top: ${seen.map((s) => `${s.light.color} (row ${Math.round(s.row)})`).join(', ')}.`);
}

/* ======================= Task 2: a car's rear lights ====================== */

/** The labels of Task 2's checks, in order. */
export const CAR_CHECKS = {
  two: 'Two red lights',
  height: 'At the same height (same y)',
  side: 'Side by side (apart in x, same z)',
  seen: 'The camera sees both, red',
  bonus: 'Bonus: symmetric about the middle of the car',
};

/**
 * Task 2: two red lights side by side at the same height (same y, apart in
 * x, same z), both in the camera's view. Bonus: placed symmetrically about
 * the middle of the car's body (every shape that is not a light, a plane or
 * huge). Options as for checkTrafficSignal.
 * @param {object} [options]
 * @param {string} [options.prefix] written before the library's names in hints: '' (default) or 'RT.'
 * @example
 * const scene = new Scene()
 *   .add(new Sphere([-1, 1, -10], 0.3, { color: [0, 0, 0], emission: [1, 0, 0] }))
 *   .add(new Sphere([1, 1, -10], 0.3, { color: [0, 0, 0], emission: [1, 0, 0] }));
 * checkRearLights(scene, new Camera({ width: 64, height: 48 })).checks.map((c) => c.passed);
 */
export function checkRearLights(scene, camera, options) {
  checkArguments(scene, camera);
  const { prefix = '' } = checkOptions(options, ['prefix'], 'checkRearLights');
  const lights = findLights(scene);
  const red = lights.filter((l) => l.color === 'red');
  const checks = [];
  const add = (check) => (checks.push(check), check.passed);

  const two = add(twoRedLights(lights, red, scene, prefix));
  const pair = two ? [...red].sort((a, b) => a.center.x - b.center.x).map((l, i) => ({ ...l, role: i ? 'right' : 'left' })) : null;
  add(two ? sameHeight(pair) : waiting(CAR_CHECKS.height, 'two red lights'));
  add(two ? sideBySide(pair) : waiting(CAR_CHECKS.side, 'two red lights'));
  add(two ? bothVisible(lookAt(scene, camera, pair), camera) : waiting(CAR_CHECKS.seen, 'two red lights'));
  checks.push(two ? symmetric(pair, carBody(scene)) : { ...waiting(CAR_CHECKS.bonus, 'two red lights'), bonus: true });
  return result(checks);
}

function twoRedLights(lights, red, scene, prefix) {
  const label = CAR_CHECKS.two;
  if (red.length === 2) return pass(label, lights.length > 2 ? `Two red lights (and ${listNames(lights.filter((l) => l.color !== 'red'))}).` : 'Two red lights.');
  if (lights.length === 0) return fail(label, noLightsYet(scene, prefix));
  if (red.length === 0) return fail(label, `Your ${count(lights.length, 'light')} ${lights.length > 1 ? 'are' : 'is'} ${listNames(lights)}: rear lights are red, e.g. emission: [1, 0, 0].`);
  return fail(label, `Found ${count(red.length, 'red light')}; a car has 2 rear lights, one on each side.`);
}

/**
 * @typedef {{ center: { x: number, y: number, z: number }, radius: number }} PlacedLight
 * A light found in the scene (see findLights), where the checks look at it.
 */

/** Same y within a quarter of the smaller radius. @param {PlacedLight[]} pair left, right */
function sameHeight([left, right]) {
  const label = CAR_CHECKS.height;
  const dy = right.center.y - left.center.y;
  const tolerance = Math.min(left.radius, right.radius) / 4;
  if (Math.abs(dy) > tolerance) {
    const [higher, lower] = dy > 0 ? ['right', 'left'] : ['left', 'right'];
    return fail(label, `The ${higher} light is ${formatLabel(Math.abs(dy))} higher than the ${lower} one ` +
      `(y = ${formatLabel(left.center.y)} and ${formatLabel(right.center.y)}): give both the same y.`);
  }
  return pass(label, `Both at y ≈ ${formatLabel(left.center.y)}.`);
}

/** Apart in x (not overlapping) and at about the same z. @param {PlacedLight[]} pair left, right */
function sideBySide([left, right]) {
  const label = CAR_CHECKS.side;
  const gap = right.center.x - left.center.x, dz = right.center.z - left.center.z;
  if (gap < left.radius + right.radius) {
    return fail(label, `The two lights are only ${formatLabel(gap)} apart in x (x = ${formatLabel(left.center.x)} and ${formatLabel(right.center.x)}): ` +
      'put one on the left of the car and one on the right.');
  }
  if (Math.abs(dz) > Math.min(left.radius, right.radius)) {
    return fail(label, `One light is ${formatLabel(Math.abs(dz))} further back than the other (z = ${formatLabel(left.center.z)} and ${formatLabel(right.center.z)}): give both the same z.`);
  }
  return pass(label, `Left at x = ${formatLabel(left.center.x)}, right at x = ${formatLabel(right.center.x)}, ${formatLabel(gap)} apart.`);
}

function bothVisible(seen, camera) {
  const check = allVisible(seen, camera);
  return { ...check, label: CAR_CHECKS.seen };
}

/**
 * Bonus: the lights' midpoint is the car body's middle (in x).
 * @param {PlacedLight[]} pair left, right
 * @param {?{ middle: number }} body
 */
function symmetric([left, right], body) {
  const label = CAR_CHECKS.bonus;
  if (!body) return { ...fail(label, 'No car body found (boxes or spheres that are not lights).'), bonus: true };
  const middle = (left.center.x + right.center.x) / 2;
  const off = middle - body.middle;
  const tolerance = Math.min(left.radius, right.radius) / 4;
  if (Math.abs(off) > tolerance) {
    return { ...fail(label, `The car's middle is x = ${formatLabel(body.middle)}, but halfway between your lights is x = ${formatLabel(middle)}: ` +
      `move both ${formatLabel(Math.abs(off))} to the ${off > 0 ? 'left' : 'right'}.`), bonus: true };
  }
  return { ...pass(label, `Halfway between the lights is x = ${formatLabel(middle)}, the middle of the car.`), bonus: true };
}

/** The middle (in x) of every shape that is not a light, a plane or huge; null when none. */
function carBody(scene) {
  let min = Infinity, max = -Infinity;
  for (const o of scene.objects) {
    if (o.material.isEmissive) continue;
    const ball = ballOf(o), box = o.bounds();
    if (box && (ball ? ball.radius < HUGE : box.max.x - box.min.x < HUGE)) {
      min = Math.min(min, box.min.x); max = Math.max(max, box.max.x);
    }
  }
  return min <= max ? { min, max, middle: (min + max) / 2 } : null;
}

/* ============================ shared checks =============================== */

/** How to make a light, in the page's own names (`prefix`: '' or 'RT.'), and why a PointLight does not count. */
function noLightsYet(scene, prefix) {
  return `No lights yet. A light is a sphere that gives off light, e.g. new ${prefix}Sphere([0, 1, -10], 0.5, { color: [0, 0, 0], emission: [1, 0, 0] }) is a red one.` +
    pointLightHint(scene, prefix);
}

/** Every light must show up in the picture, in its own colour. */
function allVisible(seen, camera) {
  const label = SIGNAL_CHECKS.seen;
  const role = (s) => s.light.role ?? s.light.color; // 'red' … or 'left', 'right'
  for (const s of seen) {
    const name = `The ${role(s)} light`;
    if (s.pixels === 0) return fail(label, `${name} is not in the picture: ${whereIsIt(s.light, camera)}`);
    if (s.seenAs !== s.light.color) {
      return fail(label, `${name} looks ${s.seenAs} in the picture, not ${s.light.color}: is something in front of it, or is its surface colour mixing in? Use color: [0, 0, 0].`);
    }
  }
  return pass(label, seen.map((s) => `${role(s)}: ${count(s.pixels, 'pixel')}`).join(', ') + '.');
}

/** Why a light's sphere covers no pixel: behind the eye, off the picture, or hidden. */
function whereIsIt(light, camera) {
  const p = camera.project(light.center);
  if (p.depth <= 0) return 'it is behind the camera (the camera looks toward −z: give it a smaller z).';
  const side = p.x < 0 ? 'left of' : p.x >= camera.width ? 'right of' : p.y < 0 ? 'above' : p.y >= camera.height ? 'below' : null;
  if (side) return `it is ${side} the picture (it would be at pixel ${Math.round(p.x)},${Math.round(p.y)}).`;
  return 'something hides it. Is it inside a box? Move it toward the camera (a larger z).';
}

/* ============================== sampling ================================== */

/**
 * The scene's lights: emissive spheres, each with its centre, radius and
 * colour name ('red', 'yellow', 'green', 'blue', 'purple', 'white').
 */
export function findLights(scene) {
  return scene.objects
    .filter((o) => ballOf(o) && o.material.isEmissive)
    .map((sphere) => ({ sphere, center: ballOf(sphere).center, radius: ballOf(sphere).radius, color: lightColor(sphere.material.emission) }));
}

/**
 * The name of a light's colour from its hue (any brightness): traffic-light
 * names, so an amber [1, 0.6, 0] counts as yellow and a blue-green as green.
 * Colours with little saturation are 'white'; [0, 0, 0] is 'off'.
 */
export function lightColor([r, g, b]) {
  const max = Math.max(r, g, b);
  if (!(max > 0)) return 'off';
  const { h } = rgbToHsl(r / max, g / max, b / max);
  if ((max - Math.min(r, g, b)) / max < 0.3) return 'white';
  if (h < 20 || h >= 330) return 'red';
  if (h < 75) return 'yellow';
  if (h < 190) return 'green';
  if (h < 260) return 'blue';
  return 'purple';
}

/**
 * Traces the scene through the camera (a smaller copy for big cameras) and,
 * for each light, finds the pixels it covers: how many, their mean row, and
 * the colour name of their mean colour.
 */
export function lookAt(scene, camera, lights) {
  const cam = sampleCamera(camera);
  const pixels = render(scene, cam);
  const ray = new Ray(cam.position), hit = { object: null, t: Infinity };
  const seen = lights.map((light) => ({ light, pixels: 0, rowSum: 0, rgb: [0, 0, 0] }));
  for (let y = 0, i = 0; y < cam.height; y++) {
    for (let x = 0; x < cam.width; x++, i += 4) {
      cam.directionAt(x, y, ray.direction);
      if (!nearestHit(scene.objects, ray, hit)) continue;
      const s = seen.find((e) => e.light.sphere === hit.object);
      if (!s) continue;
      s.pixels++;
      s.rowSum += y;
      for (let c = 0; c < 3; c++) s.rgb[c] += pixels[i + c];
    }
  }
  const toCamera = camera.height / cam.height; // rows and pixel counts in the student's camera's units
  return seen.map((s) => ({
    light: s.light,
    pixels: Math.round(s.pixels * toCamera * toCamera),
    row: s.pixels ? (s.rowSum / s.pixels + 0.5) * toCamera - 0.5 : null,
    seenAs: s.pixels ? lightColor(s.rgb.map((c) => c / s.pixels / 255)) : null,
  }));
}

function sampleCamera(camera) {
  if (camera.width <= SAMPLE_MAX_WIDTH) return camera;
  const k = SAMPLE_MAX_WIDTH / camera.width;
  const { fov, position, yaw, pitch } = camera;
  return new Camera({ width: SAMPLE_MAX_WIDTH, height: Math.max(1, Math.round(camera.height * k)), fov, position, yaw, pitch });
}

/* ============================== helpers =================================== */

/** `{ red: light, yellow: light, … }` when each name has exactly one light, else null. */
function oneOfEach(lights, names) {
  const byColor = {};
  for (const name of names) {
    const matches = lights.filter((l) => l.color === name);
    if (matches.length !== 1) return null;
    byColor[name] = matches[0];
  }
  return byColor;
}

/** A hint for students who used a PointLight, which lights the scene but cannot be seen. */
function pointLightHint(scene, prefix) {
  const colored = scene.lights.some((l) => l.source instanceof PointLight && lightColor(l.emission) !== 'white');
  return colored ? ` (A ${prefix}PointLight cannot be seen in the picture: use a sphere with an emission.)` : '';
}

function checkArguments(scene, camera) {
  if (!scene || !Array.isArray(scene.objects)) throw new TypeError(`scene must be a Scene, got ${show(scene)}`);
  if (!(camera instanceof Camera)) throw new TypeError(`camera must be a Camera, got ${show(camera)}`);
}

function result(checks) {
  return { passed: checks.every((c) => c.passed || c.bonus), checks };
}

const pass = (label, detail) => ({ label, passed: true, detail });
const fail = (label, detail) => ({ label, passed: false, detail });
const waiting = (label, what) => ({ label, passed: false, skipped: true, detail: `Checked once you have ${what}.` });
const listNames = (lights) => lights.map((l) => l.color).join(', ');
const andList = (words) => words.length > 1 ? `${words.slice(0, -1).join(', ')} and ${words.at(-1)}` : words[0];
const count = (n, word) => `${n} ${word}${n === 1 ? '' : 's'}`;
const formatLabel = (n) => String(Math.round(n * 100) / 100);

/* ============================ the check panel ============================= */

/**
 * Reads `?solution=` from a page's query string: '1' shows the reference
 * solution, '0' (or no parameter) the student's scene. Any other value gives
 * the student's scene and a message saying what the parameter takes.
 * @returns {{ solution: boolean, message: string|null }}
 * @example
 * solutionParameter('?solution=1'); // { solution: true, message: null }
 * solutionParameter('');            // { solution: false, message: null }
 */
export function solutionParameter(search) {
  const value = new URLSearchParams(search).get('solution');
  if (value === null || value === '0') return { solution: false, message: null };
  if (value === '1') return { solution: true, message: null };
  return { solution: false, message: `?solution= takes 1 (show the reference solution) or 0 (your scene), got ${show(value)}: showing your scene.` };
}

/**
 * Each homework page's self-check, by its number ('08'): a page whose code
 * runs in a sandboxed frame judges the scene it read from the frame with
 * this, whatever check the code itself names.
 */
export const HOMEWORK_CHECKS = Object.freeze({ '08': checkTrafficSignal, '09': checkRearLights });
