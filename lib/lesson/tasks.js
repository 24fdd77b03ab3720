/**
 * The tasks of each lesson page (00–14, 16, 17), each done by what the student does
 * on the page, never by a "done" button. A task is
 *
 *   { id, text, hint, done(event, memory) → boolean }
 *
 * where `event` is what just happened on the page (lib/p5/controls/task-list.js makes them):
 *   { type: 'select', record, scene, camera, … }  the student selected a pixel:
 *                                                 `record` is its inspectPixel record
 *   { type: 'state', scene, camera, … }           something changed (a box, a switch,
 *                                                 a new picture traced): look at the state
 *   { type: 'answer', ok, answer }                the activity's Check gave its verdict on
 *                                                 `answer`, the line in the slide's format
 *   { type: 'check', passed }                     a homework self-check ran
 * Every event also carries `mode` (visual), `order` (the render order; `renderMode`,
 * its old name, too) and `parts` (the page's other
 * views: `photons`, `sceneView`, `animation`). `memory` is the task's own
 * object for this visit to the page (for "two different answers").
 * Pure: runs in Node, so every task is tested against the real scenes.
 */
import { Ray } from '../math/ray.js';
import { readAnswerLine } from './activity.js';
import { EPSILON } from '../math/constants.js';
import { Vec3, set, sub, scaleAndAdd, normalize, length, dot, distance } from '../math/vec3.js';

/** |discriminant| below this share of its largest value (4A·r², the ray through the centre) counts as "about 0" in a task. */
export const NEAR_ZERO = 0.1;

/** Spheres larger than this are grounds, not objects that throw or catch a shadow in a task. */
const GROUND_RADIUS = 100;

const selected = (e) => e.type === 'select';
const hitName = (e) => e.record?.hit?.object?.name;

/** The sphere test of the record for the sphere named `name` (or the first sphere). */
export function sphereTest(record, name) {
  return record.tests.find((t) => t.sphere.name === name) ?? record.tests[0];
}

/** This test's discriminant is within NEAR_ZERO of 0, relative to its largest value 4A·r²: a grazing ray. */
export function nearZeroDiscriminant(test) {
  const { A, discriminant } = test.quadratic, r = test.sphere.radius;
  return Math.abs(discriminant) <= NEAR_ZERO * 4 * A * r * r;
}

/** The eye (a ray's origin) is inside the sphere: |L| < r. */
export function eyeInside(test) {
  const { d2, tca } = test.geometric;
  return d2 + tca * tca < test.sphere.radius ** 2;
}

/**
 * Shadow acne at this pixel: a light it faces counts as blocked, yet no other
 * shape stands between them: the surface shadowed itself (no shadow-ray offset).
 */
export function hasAcne(record, scene) {
  const hit = record.hit;
  return hit !== null && hit.lights.some((l) => l.facing && l.inShadow && blockers(scene, hit, l).length === 0);
}

/** The pixel's surface is in the shadow the shape called `name` throws. */
export function inShadowOf(record, scene, name) {
  const hit = record.hit;
  return hit !== null && hit.lights.some((l) => l.inShadow && blockers(scene, hit, l).some((o) => o.name === name));
}

/** The shapes between a hit point and a light, other than the hit shape itself (found as the tracer's shadow ray does). */
function blockers(scene, hit, light) {
  const toLight = sub(new Vec3(), light.position, hit.point);
  const reach = length(toLight);
  const ray = new Ray(hit.point, toLight);
  return scene.objects.filter((o) => o !== hit.object && o !== light.light && o.hit(ray, EPSILON) < reach);
}

/** Points on a unit sphere, spread evenly (a Fibonacci lattice): where shadowsOnOthers looks. */
const LATTICE = Array.from({ length: 400 }, (_, i) => {
  const y = 1 - (2 * (i + 0.5)) / 400, r = Math.sqrt(1 - y * y), a = i * Math.PI * (3 - Math.sqrt(5));
  return [r * Math.cos(a), y, r * Math.sin(a)];
});

/**
 * Which sphere throws a shadow on which other sphere, on a side the eye can
 * see: `['yellow→pink', …]` (lights and grounds left out). A point of the
 * receiver that faces the eye and a light, and whose shadow ray meets the caster first.
 */
export function shadowsOnOthers(scene, eye) {
  const balls = scene.spheres.filter((s) => !s.material.isEmissive && s.radius < GROUND_RADIUS);
  const pairs = new Set();
  const point = new Vec3(), normal = new Vec3(), toEye = new Vec3(), ray = new Ray();
  for (const receiver of balls) {
    for (const [nx, ny, nz] of LATTICE) {
      scaleAndAdd(point, receiver.center, set(normal, nx, ny, nz), receiver.radius);
      if (dot(sub(toEye, eye, point), normal) <= 0) continue; // the eye cannot see this side
      for (const light of scene.lights) {
        const reach = length(sub(ray.direction, light.position, point));
        if (dot(ray.direction, normal) <= 0) continue; // not lit from here anyway
        normalize(ray.direction, ray.direction);
        ray.origin = point;
        for (const caster of balls) {
          if (caster !== receiver && caster.hit(ray, EPSILON) < reach) pairs.add(`${caster.name ?? 'a sphere'}→${receiver.name ?? 'a sphere'}`);
        }
      }
    }
  }
  return [...pairs];
}

/* ---------------- the lessons ---------------- */

const selectAny = {
  id: 'select', text: 'Select any pixel: click it, or press an arrow key in the picture.',
  hint: 'Click anywhere on the picture. With the keyboard: Tab to the picture, then an arrow key.',
  done: selected,
};
const missAny = {
  id: 'miss', text: 'Find a pixel whose ray hits nothing.',
  hint: 'A ray that hits nothing gets the background colour: try the sky at the top of the picture.',
  done: (e) => selected(e) && e.record.hit === null,
};

/** @type {{ page: string, title: string, homework?: boolean, tasks: object[] }[]} */
export const LESSONS = [
  { page: '00', title: 'From the light or from the eye', tasks: [
    { ...selectAny, text: 'Select any pixel of the eye\'s picture: its ray shows in 3D.' },
    { ...missAny, text: 'Find a pixel whose eye ray hits nothing.' },
    { id: 'dark', text: 'Find a pixel the photons never reached (black on the left), though the eye sees it.',
      hint: 'Click a black pixel of the photons\' picture: the same pixel of the eye\'s picture is selected.',
      done: (e) => selected(e) && e.parts.photons !== undefined && photonsAt(e.parts.photons, e.record.x, e.record.y) === 0 },
    { id: 'more', text: 'Send more photons from the light and watch the count.',
      hint: 'The button under the photons\' picture sends as many again.',
      done: (e) => e.parts.photons !== undefined && e.parts.photons.tracer.emitted > e.parts.photons.photonsPerRun },
    { id: 'turn', text: 'Turn the 3D view to look at the rays from another side.',
      hint: 'Drag the 3D view with the mouse.',
      done: (e, memory) => turned(e.parts.sceneView, memory) },
  ] },
  { page: '01', title: 'Rays through pixels', tasks: [
    selectAny,
    missAny,
    { id: 'blue', text: 'Find a pixel whose ray hits the blue sphere.',
      hint: 'The blue sphere is further away, to the right of the pink one.', done: (e) => selected(e) && hitName(e) === 'blue' },
    { id: 'ahead', text: 'Find a pixel whose ray goes almost straight ahead: H and V both between −1° and 1°.',
      hint: 'The middle of the picture: the inspector\'s first line gives each pixel\'s H and V.',
      done: (e) => selected(e) && Math.abs(e.record.h) < 1 && Math.abs(e.record.v) < 1 },
    { id: 'shadow', text: 'Find a pixel of the ground in the pink sphere\'s shadow.',
      hint: 'The light is up on the left: the shadow falls on the ground to the right of and behind the pink sphere.',
      done: (e) => selected(e) && hitName(e) === 'ground' && inShadowOf(e.record, e.scene, 'pink') },
    { id: 'slow', text: 'Watch the rays one at a time: slow motion.',
      hint: 'Tick "Slow motion" under the picture.', done: (e) => e.order === 'slow' },
  ] },
  { page: '02', title: 'The quadratic', tasks: [
    { id: 'negative', text: 'Find a pixel whose discriminant B² − 4AC is negative: no hit.',
      hint: 'The discriminant map shows negative values in blue.', done: (e) => selected(e) && sphereTest(e.record).quadratic.discriminant < 0 && !nearZeroDiscriminant(sphereTest(e.record)) },
    { id: 'zero', text: 'Find a pixel whose discriminant is about 0 (within a tenth of 4r² of it): a ray that grazes the sphere.',
      hint: 'Look at the edge of the sphere in the discriminant map, where the colour is palest; the inspector gives the number.',
      done: (e) => selected(e) && nearZeroDiscriminant(sphereTest(e.record)) },
    { id: 'positive', text: 'Find a pixel whose discriminant is positive: two roots, two hits.',
      hint: 'Any pixel well inside the sphere; the roots map shows 2 there.', done: (e) => selected(e) && sphereTest(e.record).quadratic.discriminant > 0 && !nearZeroDiscriminant(sphereTest(e.record)) },
    { id: 'grow', text: 'Make the pink sphere bigger until pixel 10,12 hits it.',
      hint: 'Drag "Radius r" up, or type a bigger radius, a step at a time.',
      done: (e) => e.scene.spheres[0].radius > 4 && hitsAt(e, 10, 12) },
    { id: 'behind', text: 'Move the sphere behind the eye (Centre z > 0) and find a pixel whose discriminant is positive yet the ray hits nothing.',
      hint: 'Both roots t are negative then: the hits are behind the eye. Set "Centre z" to 10 and click the middle.',
      done: (e) => selected(e) && sphereTest(e.record).quadratic.roots === 2 && sphereTest(e.record).quadratic.t === null },
  ] },
  { page: '03', title: 'The geometric approach', tasks: [
    { id: 'pass-by', text: 'Find a pixel whose ray passes the sphere by: d > r.',
      hint: 'Any pixel off the sphere: the sentence under the checkbox says d > r.', done: (e) => selected(e) && sphereTest(e.record).geometric.roots === 0 },
    { id: 'hit', text: 'Find a pixel whose ray hits: tca ≥ 0, d ≤ r, t = tca − thc.',
      hint: 'A pixel of the sphere, with the eye outside it.', done: (e) => selected(e) && sphereTest(e.record).geometric.tca >= 0 && sphereTest(e.record).geometric.t !== null && !eyeInside(sphereTest(e.record)) },
    { id: 'inside', text: 'Put the eye inside the sphere.',
      hint: 'Tick "Eye inside the sphere".', done: (e) => e.camera.position && e.scene.spheres.some((s) => distance(e.camera.position, s.center) < s.radius) },
    { id: 'tca-negative', text: 'Find a pixel where tca < 0 but the ray still hits.',
      hint: 'With the eye inside, the sphere\'s centre is behind it: click the middle of the picture.',
      done: (e) => selected(e) && sphereTest(e.record).geometric.tca < 0 && sphereTest(e.record).geometric.t !== null },
  ] },
  { page: '04', title: 'Find the pink pixel', tasks: [
    { id: 'check', text: 'Check an answer: click a pixel, or type one and press Check.',
      hint: 'Click a pixel of the picture: its answer is checked at once.', done: (e) => e.type === 'answer' },
    { id: 'pink', text: 'Find a pink pixel: Check says ✔.',
      hint: 'The pink sphere is in the middle; a dark pixel of it is not pink. Tick the highlight to see every pink pixel.',
      done: (e) => e.type === 'answer' && e.ok },
    { id: 'turned', text: 'Find a pink pixel with the camera turned (H or V not 0).',
      hint: 'Type H: 10, press Check, and look for pink again: the picture moves left.',
      done: (e) => e.type === 'answer' && e.ok && cameraTurned(e.answer) },
    { id: 'two', text: 'Find two different right answers.',
      hint: 'More than one pixel is pink: any two of them.',
      done: (e, memory) => {
        if (e.type !== 'answer' || !e.ok) return false;
        (memory.right ??= new Set()).add(e.answer);
        return memory.right.size >= 2;
      } },
  ] },
  { page: '05', title: 'Value boxes', tasks: [
    selectAny,
    { id: 'glow', text: 'Make a sphere glow: give it an emission, and it becomes a light.',
      hint: 'Type 1 in a sphere\'s emission box (the pink one, say).',
      done: (e, memory) => lightCount(e.scene, memory) },
    { id: 'shadow', text: 'Move a sphere so that its shadow falls on another.',
      hint: 'The first light is high above the pink sphere: put a small sphere between them, e.g. the yellow one at x 0, y 7, z −20.',
      done: (e, memory) => newShadow(e, memory) },
  ] },
  { page: '06', title: 'Lights, shadows and reflections', tasks: [
    { id: 'in-shadow', text: 'Find a pixel in shadow: a light it faces is blocked.',
      hint: 'The floor beside a ball, on the side away from the light.',
      done: (e) => selected(e) && e.scene.shadows && (e.record.hit?.lights.some((l) => l.inShadow) ?? false) && !hasAcne(e.record, e.scene) },
    { id: 'acne', text: 'Set the shadow-ray offset to 0 and find a pixel with acne.',
      hint: 'Choose "0 (none: acne)", then click the dark speckles on the floor or a ball.',
      done: (e) => selected(e) && e.scene.bias === 0 && e.scene.shadows && hasAcne(e.record, e.scene) },
    { id: 'mirror', text: 'Find a pixel of the mirror that shows the red ball.',
      hint: 'The mirror is the left ball: look at its side toward the red one.',
      done: (e) => selected(e) && hitName(e) === 'mirror' && e.record.hit.reflection?.hit?.object.name === 'red ball' },
    { id: 'no-bounce', text: 'Set the mirror bounces to 0 and select the mirror: it looks like plain paint.',
      hint: 'Drag "mirror bounces" to 0, then click the left ball.',
      done: (e) => selected(e) && e.scene.maxDepth === 0 && hitName(e) === 'mirror' },
    { id: 'glass', text: 'Find a pixel where you see through the glass ball.',
      hint: 'The right ball: with "glass" ticked, click its middle.',
      done: (e) => selected(e) && hitName(e) === 'glass' && Boolean(e.record.hit.refraction?.hit) },
  ] },
  { page: '07', title: 'The original examples', tasks: [
    { id: 'still', text: 'Select a pixel of the still scene.',
      hint: 'Click the picture under the buttons.', done: (e) => selected(e) && !e.parts.animation?.thread && e.camera.width === 160 },
    { id: 'original', text: 'Open the original 640×480 example and select one of its pixels.',
      hint: 'The 640×480 button, then a click on the picture.', done: (e) => selected(e) && e.camera.width === 640 },
    { id: 'animated', text: 'Play the animated example on the page\'s own thread.',
      hint: 'The "animated" button.', done: (e) => e.parts.animation?.thread === 'main' && e.parts.animation.playing },
    { id: 'workers', text: 'Play it on Web Workers.',
      hint: 'The "workers" button: the frames are shared out.', done: (e) => e.parts.animation?.thread === 'workers' && e.parts.animation.playing },
    { id: 'frame', text: 'Pause an animation and select a pixel of its frame.',
      hint: 'Pause, then click the picture.', done: (e) => selected(e) && Boolean(e.parts.animation?.thread) && !e.parts.animation.playing },
  ] },
  homeworkLesson('08', 'Homework 1: a traffic signal', 'three lights'),
  homeworkLesson('09', 'Homework 2: a car\'s two rear lights', 'two rear lights'),
  { page: '10', title: 'Playground', tasks: [
    selectAny,
    { id: 'own', text: 'Add a sphere of your own to the code and select one of its pixels.',
      hint: 'Copy the scene.add(new Sphere(…)) line, change its centre (e.g. [6, 1, -26]) and radius, save or Run, then click it.',
      done: (e) => selected(e) && e.record.hit !== null && e.scene.objects.indexOf(e.record.hit.object) > 0 },
    { id: 'glow', text: 'Add a light you can see: a sphere with an emission.',
      hint: 'Give a sphere { color: [0, 0, 0], emission: 1 }: it shines on the others.', done: (e) => e.scene.spheres.some((s) => s.material.isEmissive) },
    { id: 'mirror', text: 'Make a sphere a mirror and find a pixel of it that shows another shape.',
      hint: 'Add reflection: 0.8 to a sphere\'s material; then click its side toward another sphere.',
      done: (e) => selected(e) && Boolean(e.record.hit?.reflection?.hit) },
  ] },
  { page: '11', title: 'Several rays per pixel', tasks: [
    { id: 'edge', text: 'Find an edge pixel: its rays do not all hit the same thing.',
      hint: 'Click the rim of the pink sphere in the right-hand picture: the panel lists each ray and what it hit.',
      done: (e) => selected(e) && e.record.samples !== undefined && new Set(e.record.samples.map((s) => s.hit)).size > 1 },
    { id: 'sixteen', text: 'Trace 16 rays per pixel: the smoothest edge.', hint: 'Choose 16 above the pictures.', done: (e) => e.camera.samples === 16 },
    { id: 'one', text: 'Choose 1 ray per pixel: the right-hand picture is as jagged as the left.', hint: 'Choose 1 above the pictures.', done: (e) => e.camera.samples === 1 },
  ] },
  { page: '12', title: 'Cylinders, cones and triangles', tasks: [
    { id: 'side', text: 'Find a pixel on the cylinder\'s side: a root of its quadratic within its height.',
      hint: 'The pink cylinder on the left; the panel\'s "Other shapes" row says which part was hit.', done: (e) => partHit(e, 'side') && hitName(e) === 'pink cylinder' },
    { id: 'cone', text: 'Find a pixel of the yellow cone: its radius shrinks as y goes up, so y is back in A, B and C.',
      hint: 'The cone stands in the middle.', done: (e) => selected(e) && hitName(e) === 'yellow cone' },
    { id: 'triangle', text: 'Find a pixel of the green triangle: u ≥ 0, v ≥ 0, u + v ≤ 1.', hint: 'The triangle is on the right.', done: (e) => selected(e) && hitName(e) === 'green triangle' },
    { id: 'beside', text: 'Find a ray that passes just beside the triangle: u or v a little below 0, or u + v a little over 1.',
      hint: 'Click a pixel touching the triangle\'s edge, outside it: the panel\'s u and v say by how much it missed.', done: (e) => selected(e) && besideTriangle(e.record) },
  ] },
  { page: '13', title: 'Meshes and a BVH', tasks: [
    { id: 'bunny', text: 'Select a pixel of the bunny: how many triangles did its ray test?', hint: 'Click the bunny; the panel gives its box and triangle tests.',
      done: (e) => selected(e) && hitName(e) === 'bunny' },
    { id: 'loose', text: 'Find a ray that misses the bunny yet tests some of its triangles: it entered a box the bunny does not fill.',
      hint: 'Click just beside the bunny\'s outline, between its ears or under its chin.',
      done: (e) => selected(e) && hitName(e) !== 'bunny' && meshRecord(e.record)?.triangleTests > 0 },
    { id: 'skip', text: 'Find a ray that misses the bunny\'s bounding box: no triangle tested at all.',
      hint: 'Any pixel of the sky or floor far from the bunny.', done: (e) => selected(e) && meshRecord(e.record)?.triangleTests === 0 },
    { id: 'shadow', text: 'Find a pixel of the floor in the bunny\'s shadow.', hint: 'The light is up on the left, in front: the shadow falls behind the bunny, to the right.',
      done: (e) => selected(e) && hitName(e) === 'floor' && inShadowOf(e.record, e.scene, 'bunny') },
  ] },
  { page: '14', title: 'Spot and area lights, soft shadows', tasks: [
    { id: 'penumbra', text: 'Find a pixel of the penumbra: some of the disc\'s shadow rays reach it, not all.',
      hint: 'The rim of the ball\'s soft shadow on the floor; the panel says "N of 16 shadow rays reached it".',
      done: (e) => selected(e) && (e.record.hit?.areaLights ?? []).some((g) => g.reached > 0 && g.reached < g.samples) },
    { id: 'umbra', text: 'Find a pixel in the full shadow: none of the disc\'s shadow rays reach it.',
      hint: 'The middle of the ball\'s shadow, right under it.', done: (e) => selected(e) && (e.record.hit?.areaLights ?? []).some((g) => g.samples > 1 && g.reached === 0) },
    { id: 'cone', text: 'Find a pixel of the floor outside the spot\'s cone.', hint: 'Away from the warm circle of light around the blue cylinder.',
      done: (e) => selected(e) && hitName(e) === 'floor' && e.record.hit.lights.some((l) => l.beam === 0) },
    { id: 'one-ray', text: 'Give the disc 1 shadow ray and select a pixel: the shadow is hard again.',
      hint: 'Choose 1 under "shadow rays", then click the floor.', done: (e) => selected(e) && (e.record.hit?.areaLights ?? []).some((g) => g.samples === 1) },
  ] },
  { page: '16', title: 'Light that bounces', tasks: [
    { id: 'path', text: 'Select a pixel and read one of its paths, bounce by bounce.',
      hint: 'Click either picture: the path panel lists where the path went and what it gathered.', done: (e) => selected(e) },
    { id: 'bleed', text: 'Find colour bleeding: a pixel of the white floor, ceiling or back wall that the path tracer paints redder or greener than Whitted\'s tracer.',
      hint: 'Wait until the path-traced picture has all its samples, then click the floor close to the red wall.',
      done: (e) => selected(e) && WHITE_SURFACES.includes(hitName(e)) && bleeds(e) },
    { id: 'direct', text: 'Switch to 1 bounce: direct light only. Which parts of the room go dark?',
      hint: 'Choose "1 bounce" above the pictures.', done: (e) => e.parts.paths?.pathState?.options.maxBounces === 1 },
    { id: 'lamp', text: 'Find a path that bounced and then reached the lamp.',
      hint: 'Select a pixel of the floor, then press "Next sample" until a row below the first says "lamp".',
      done: (e) => (e.parts.pathPanel?.path?.bounces.findIndex((b) => b.name === 'lamp') ?? -1) > 0 },
    { id: 'settled', text: 'Wait for every sample, then select a pixel: its standard error is the noise left.',
      hint: 'The line under the path-traced picture counts the samples; at the last one, click a pixel.',
      done: (e) => selected(e) && e.parts.paths?.done === true && e.parts.paths.pathState !== null },
  ] },
  { page: '17', title: 'One weekend\'s final scene', tasks: [
    { id: 'glass', text: 'Select a pixel of the big glass ball: the world seen through it is upside down.',
      hint: 'The big ball in the middle of the picture.', done: (e) => selected(e) && hitName(e) === 'big glass ball' },
    { id: 'through', text: 'Find a path that went through glass: a row of the path that says "glass, through".',
      hint: 'Select a pixel of the big glass ball, then press "Next sample" until a row says "glass, through".',
      done: (e) => (e.parts.pathPanel?.path?.bounces ?? []).some((b) => b.lobe === 'glass, through') },
    { id: 'fuzzy', text: 'Find a small metal ball with fuzz: what it mirrors is blurred.',
      hint: 'The small balls that shine; the inspector names each "small metal ball".', done: (e) => selected(e) && hitName(e) === 'small metal ball' && e.record.hit.object.material.fuzz > 0 },
    { id: 'polished', text: 'Polish the small metal balls (fuzz 0) and select one again: a sharp reflection.',
      hint: 'Choose "polished" above the picture, then click a small metal ball.', done: (e) => selected(e) && hitName(e) === 'small metal ball' && e.record.hit.object.material.fuzz === 0 },
    { id: 'sky', text: 'Find a pixel of the sky: a path that hits nothing gathers the sky\'s light.',
      hint: 'The top of the picture.', done: (e) => selected(e) && e.record.hit === null },
  ] },
];

/** The white surfaces of sketch 16's room, where colour bleeding shows. */
const WHITE_SURFACES = ['floor', 'ceiling', 'back wall', 'tall block'];

/** Colour bleeding at the selected pixel: its path-traced colour leans more to red or green than Whitted's, by a margin (bytes). */
function bleeds(e) {
  const view = e.parts.paths;
  if (!view?.done) return false;
  const i = (e.record.y * view.width + e.record.x) * 4, path = view.buffer, whitted = e.record.color;
  return Math.abs(path[i] - path[i + 1]) - Math.abs(whitted[0] - whitted[1]) >= BLEED_MARGIN;
}
const BLEED_MARGIN = 8;

/** A homework page's tasks: run the self-check, show a light of your own, pass. */
function homeworkLesson(page, title, lights) {
  return { page, title, homework: true, tasks: [
    { id: 'check', text: 'Run the self-check.', hint: 'The "Check my scene" button under the picture.', done: (e) => e.type === 'check' },
    { id: 'light', text: 'Select a pixel of a light you added.',
      hint: `Write the ${lights} in addLights() in the code under the picture, press Run, then click one of them in the picture.`,
      done: (e) => selected(e) && (e.record.hit?.object.material.isEmissive ?? false) },
    { id: 'pass', text: 'Pass the self-check.', hint: 'Fix each line marked ✗ in the code, press Run, and check again.', done: (e) => e.type === 'check' && e.passed },
  ] };
}

/** The lesson of page `page` ('01'), or undefined. */
export function lessonOf(page) {
  return LESSONS.find((l) => l.page === page);
}

/* ---------------- helpers of the tasks ---------------- */

/** The selected pixel's ray hit a cylinder's or cone's `part` ('side', 'top', 'bottom'). */
function partHit(e, part) {
  return selected(e) && e.record.hit !== null && e.record.records.some((r) => r.object === e.record.hit.object && r.record.part === part);
}

/** Barycentric coordinates this far out of range count as "just beside" a triangle. */
const BESIDE = 0.1;

/** A triangle's plane was met just outside the triangle: u or v a little below 0, or u + v a little over 1. */
function besideTriangle(record) {
  return record.records.some(({ record: r }) => {
    if (r.parallel !== false || r.u === null) return false;
    const out = Math.max(-r.u, r.u - 1, r.v === null ? 0 : Math.max(-r.v, r.u + r.v - 1));
    return out > 0 && out < BESIDE;
  });
}

/** The mesh's record of this pixel's ray (box and triangle tests), or undefined. */
function meshRecord(record) {
  return record.records.find((r) => r.record.triangleTests !== undefined)?.record;
}

/** How much light the photons brought to pixel (x, y) so far. */
function photonsAt(photonView, x, y) {
  const light = photonView.tracer.light, i = (y * photonView.tracer.camera.width + x) * 3;
  return light[i] + light[i + 1] + light[i + 2];
}

/** The 3D view is turned away from where it was first seen. */
function turned(sceneView, memory) {
  if (!sceneView) return false;
  const { yaw, pitch } = sceneView.orbit;
  memory.first ??= { yaw, pitch };
  return Math.abs(yaw - memory.first.yaw) > 1 || Math.abs(pitch - memory.first.pitch) > 1;
}

/** Pixel (x, y)'s ray hits the first sphere of the scene (either route's t). */
function hitsAt(e, x, y) {
  if (x >= e.camera.width || y >= e.camera.height) return false;
  const { ray } = e.camera.primaryRay(x, y);
  return Number.isFinite(e.scene.spheres[0].hit(ray));
}

/** The answer line's camera H or V is not 0. */
function cameraTurned(answer) {
  const values = readAnswerLine(answer);
  return values !== null && (Number(values.h) !== 0 || Number(values.v) !== 0);
}

/** More emissive spheres than when the page was first seen. */
function lightCount(scene, memory) {
  const count = scene.spheres.filter((s) => s.material.isEmissive).length;
  memory.first ??= count;
  return count > memory.first;
}

/** Shadows are looked for among this many spheres at most: a class's scene, not a 1,000-sphere one (the look is pairs × 400 points). */
const MAX_SHADOW_SPHERES = 16;

/** A sphere's shadow on another that was not there when the page was first seen. */
function newShadow(e, memory) {
  if (e.scene.spheres.length > MAX_SHADOW_SPHERES) return false;
  const pairs = shadowsOnOthers(e.scene, e.camera.position);
  memory.first ??= new Set(pairs);
  return pairs.some((pair) => !memory.first.has(pair));
}
