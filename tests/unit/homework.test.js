// The homework self-checks: the reference solutions pass, the starters fail
// with the right message, and each kind of mistake fails on its own check.
import { describe, test, expect, vi } from 'vitest';
import { Sphere, Camera, Scene, PointLight, sceneToJSON, trafficSignalScene, trafficSignalCamera, rearLightsScene, rearLightsCamera } from '../../lib/index.js';
import { checkTrafficSignal, checkRearLights, lightColor, findLights, solutionParameter } from '../../lib/lesson/homework.js';

// The sketches are p5 sketches; their scenes are plain library code. Without
// a browser, p5 and the adapter are stand-ins that do nothing.
vi.mock('p5', () => ({ default: class {} }));
vi.mock('../../lib/p5/index.js', () => ({}));
const signal = await import('../../sketches/08-homework-traffic-signal.js');
const signalSolution = await import('../../sketches/solutions/08-traffic-signal.js');
const car = await import('../../sketches/09-homework-rear-lights.js');
const carSolution = await import('../../sketches/solutions/09-rear-lights.js');

const RED = [1, 0.1, 0.05], YELLOW = [1, 0.8, 0], GREEN = [0.1, 1, 0.3];
const light = (center, emission, radius = 0.5) => new Sphere(center, radius, { color: [0, 0, 0], emission });

/** The traffic-signal street with these lights: `[[x, y, z], emission], …`. */
const signalWith = (...lights) => signal.makeScene((scene) => lights.forEach(([c, e, r]) => scene.add(light(c, e, r))));
const carWith = (...lights) => car.makeScene((scene) => lights.forEach(([c, e, r = 0.14]) => scene.add(light(c, e, r))));

/** The check with this label (labels are part of what a student reads). */
const check = (result, label) => {
  const found = result.checks.find((c) => c.label.startsWith(label));
  if (!found) throw new Error(`no check labelled "${label}" in ${result.checks.map((c) => c.label).join(' | ')}`);
  return found;
};
const failedLabels = (result) => result.checks.filter((c) => !c.passed && !c.skipped).map((c) => c.label);

describe('checkTrafficSignal', () => {
  test('the reference solution passes every check', () => {
    const result = checkTrafficSignal(signal.makeScene(signalSolution.addLights), signal.makeCamera());
    expect(result.passed).toBe(true);
    expect(result.checks).toHaveLength(6);
    for (const c of result.checks) expect(c, c.label).toMatchObject({ passed: true });
    expect(check(result, 'Red on top').detail).toBe('Top to bottom: red y = 6.6, yellow y = 5.4, green y = 4.2.');
  });

  test('the starter fails: no lights yet, the rest waits for them', () => {
    const result = checkTrafficSignal(signal.makeScene(), signal.makeCamera());
    expect(result.passed).toBe(false);
    expect(failedLabels(result)).toEqual(['Three lights']);
    expect(check(result, 'Three lights').detail).toMatch(/^No lights yet\. A light is a sphere that gives off light/);
    for (const c of result.checks.slice(1)) expect(c, c.label).toMatchObject({ passed: false, skipped: true });
  });

  test('only one light fails on "Three lights", naming what it found', () => {
    const result = checkTrafficSignal(signalWith([[0, 6.6, -16], RED]), signal.makeCamera());
    expect(result.passed).toBe(false);
    expect(failedLabels(result)).toEqual(['Three lights']);
    expect(check(result, 'Three lights').detail).toBe('Found 1 light (red); a traffic signal has 3: red, yellow and green.');
  });

  test('green on top fails on the order, in the scene and in the picture', () => {
    const result = checkTrafficSignal(signalWith([[0, 6.6, -16], GREEN], [[0, 5.4, -16], YELLOW], [[0, 4.2, -16], RED]), signal.makeCamera());
    expect(result.passed).toBe(false);
    expect(failedLabels(result)).toEqual([
      'Red on top, yellow in the middle, green at the bottom',
      'In the picture: red, yellow, green from top to bottom',
    ]);
    expect(check(result, 'Red on top').detail).toMatch(/^From top to bottom your lights are green, yellow, red \(red y = 4\.2, yellow y = 5\.4, green y = 6\.6\)/);
    expect(check(result, 'In the picture').detail).toBe('In the picture, from the top: green, yellow, red. Fix the order of the lights (above) and this follows.');
    expect(check(result, 'Stacked in one column').passed).toBe(true);
  });

  test('a missing colour fails on the colours, saying which one', () => {
    const result = checkTrafficSignal(signalWith([[0, 6.6, -16], RED], [[0, 5.4, -16], RED], [[0, 4.2, -16], GREEN]), signal.makeCamera());
    expect(failedLabels(result)).toEqual(['One red, one yellow, one green']);
    expect(check(result, 'One red').detail).toMatch(/^Your lights are red, red, green: yellow is missing\./);
  });

  test('white lights: every colour is missing, and the check says how to colour a light', () => {
    const white = [1, 1, 1];
    const result = checkTrafficSignal(signalWith([[0, 6.6, -16], white], [[0, 5.4, -16], white], [[0, 4.2, -16], white]), signal.makeCamera());
    expect(check(result, 'One red').detail).toBe('Your lights are white, white, white: red, yellow and green are missing. ' +
      'The colour of a light is its emission, e.g. emission: [1, 0.8, 0] for yellow.');
  });

  test('a light out of the column fails on "Stacked", saying which way it is off', () => {
    const result = checkTrafficSignal(signalWith([[0, 6.6, -16], RED], [[1.5, 5.4, -16], YELLOW], [[0, 4.2, -16], GREEN]), signal.makeCamera());
    expect(failedLabels(result)).toEqual(['Stacked in one column (same x and z)']);
    expect(check(result, 'Stacked').detail).toMatch(/^The yellow light is 1\.5 to the right of the red one/);
  });

  test('overlapping lights fail on the order check', () => {
    const result = checkTrafficSignal(signalWith([[0, 6, -16], RED], [[0, 5.6, -16], YELLOW], [[0, 4.2, -16], GREEN]), signal.makeCamera());
    expect(check(result, 'Red on top').passed).toBe(false);
    expect(check(result, 'Red on top').detail).toMatch(/^The red and yellow lights overlap/);
  });

  test('a light hidden inside the housing is not seen, and the check says why', () => {
    const hidden = [[0, 5.4, -16.5], YELLOW, 0.25]; // inside the box from z = -16.8 to -16.2
    const result = checkTrafficSignal(signalWith([[0, 6.6, -16.5], RED, 0.25], hidden, [[0, 4.2, -16.5], GREEN, 0.25]), signal.makeCamera());
    expect(failedLabels(result)).toEqual(['The camera sees all three']);
    expect(check(result, 'The camera sees').detail).toMatch(/^The red light is not in the picture: something hides it\./);
    expect(check(result, 'In the picture').skipped).toBe(true);
  });

  test('a signal outside the picture fails on the camera check, saying where it is', () => {
    const result = checkTrafficSignal(signalWith([[12, 6.6, -16], RED], [[12, 5.4, -16], YELLOW], [[12, 4.2, -16], GREEN]), signal.makeCamera());
    expect(failedLabels(result)).toEqual(['The camera sees all three']);
    expect(check(result, 'The camera sees').detail).toMatch(/^The red light is not in the picture: it is right of the picture/);
    const behind = checkTrafficSignal(signalWith([[0, 6.6, 5], RED], [[0, 5.4, 5], YELLOW], [[0, 4.2, 5], GREEN]), signal.makeCamera());
    expect(check(behind, 'The camera sees').detail).toMatch(/behind the camera/);
  });

  test('a big camera is sampled at a smaller size and gives the same verdict', () => {
    const big = new Camera({ width: 1280, height: 960, fov: 35, position: [0, 1.6, 0], pitch: 7 });
    const result = checkTrafficSignal(signal.makeScene(signalSolution.addLights), big);
    expect(result.passed).toBe(true);
    expect(check(result, 'In the picture').detail).toMatch(/red \(row \d+\), yellow/);
  });

  test('bad arguments are named', () => {
    expect(() => checkTrafficSignal(null, signal.makeCamera())).toThrow(/scene must be a Scene/);
    expect(() => checkTrafficSignal(new Scene(), { width: 10 })).toThrow(/camera must be a Camera/);
  });
});

describe('checkRearLights', () => {
  test('the reference solution passes every check, the bonus too', () => {
    const result = checkRearLights(car.makeScene(carSolution.addLights), car.makeCamera());
    expect(result.passed).toBe(true);
    for (const c of result.checks) expect(c, c.label).toMatchObject({ passed: true });
    expect(check(result, 'Bonus').bonus).toBe(true);
    expect(check(result, 'The camera sees both').detail).toMatch(/^left: \d+ pixels, right: \d+ pixels\.$/);
  });

  test('the starter fails: no lights yet', () => {
    const result = checkRearLights(car.makeScene(), car.makeCamera());
    expect(result.passed).toBe(false);
    expect(failedLabels(result)).toEqual(['Two red lights']);
    expect(check(result, 'Two red lights').detail).toMatch(/^No lights yet\./);
  });

  test('only one light fails on "Two red lights"', () => {
    const result = checkRearLights(carWith([[-0.72, 0.8, -6.5], RED]), car.makeCamera());
    expect(failedLabels(result)).toEqual(['Two red lights']);
    expect(check(result, 'Two red lights').detail).toBe('Found 1 red light; a car has 2 rear lights, one on each side.');
  });

  test('lights at different heights fail on "same height", saying which is higher', () => {
    const result = checkRearLights(carWith([[-0.72, 0.8, -6.5], RED], [[0.72, 0.5, -6.5], RED]), car.makeCamera());
    expect(result.passed).toBe(false);
    expect(failedLabels(result)).toEqual(['At the same height (same y)']);
    expect(check(result, 'At the same height').detail).toBe('The left light is 0.3 higher than the right one (y = 0.8 and 0.5): give both the same y.');
  });

  test('lights of another colour fail, saying rear lights are red', () => {
    const result = checkRearLights(carWith([[-0.72, 0.8, -6.5], [1, 1, 1]], [[0.72, 0.8, -6.5], [1, 1, 1]]), car.makeCamera());
    expect(failedLabels(result)).toEqual(['Two red lights']);
    expect(check(result, 'Two red lights').detail).toMatch(/^Your 2 lights are white, white: rear lights are red/);
  });

  test('two lights on top of each other are not side by side', () => {
    const result = checkRearLights(carWith([[0.6, 0.8, -6.5], RED], [[0.72, 0.8, -6.5], RED]), car.makeCamera());
    expect(failedLabels(result)).toContain('Side by side (apart in x, same z)');
  });

  test('off-centre lights still pass; only the bonus says so', () => {
    const result = checkRearLights(carWith([[-0.5, 0.8, -6.5], RED], [[0.9, 0.8, -6.5], RED]), car.makeCamera());
    expect(result.passed).toBe(true);
    expect(check(result, 'Bonus')).toMatchObject({ passed: false, bonus: true });
    expect(check(result, 'Bonus').detail).toMatch(/^The car's middle is x = 0, but halfway between your lights is x = 0\.2: move both 0\.2 to the left\.$/);
  });
});

describe('light colours', () => {
  test('traffic-light names from the hue, whatever the brightness', () => {
    expect(lightColor([1, 0.1, 0.05])).toBe('red');
    expect(lightColor([2, 0.2, 0.1])).toBe('red');
    expect(lightColor([1, 0.6, 0])).toBe('yellow'); // amber counts as yellow
    expect(lightColor([1, 0.8, 0])).toBe('yellow');
    expect(lightColor([0, 1, 0.6])).toBe('green');
    expect(lightColor([0, 0, 1])).toBe('blue');
    expect(lightColor([1, 1, 1])).toBe('white');
    expect(lightColor([1, 0.9, 0.85])).toBe('white');
    expect(lightColor([0, 0, 0])).toBe('off');
  });

  test('findLights lists emissive spheres only', () => {
    const scene = new Scene().add(light([0, 0, -5], RED)).add(new Sphere([1, 0, -5], 1, { color: [1, 0, 0] }));
    expect(findLights(scene).map((l) => l.color)).toEqual(['red']);
  });
});

describe('the homework scenes in the library (a page without Node has them too)', () => {
  test('are the sketches\' scenes and cameras, with no lights: both checks fail on the lights', () => {
    expect(sceneToJSON(trafficSignalScene())).toEqual(sceneToJSON(signal.makeScene()));
    expect(sceneToJSON(rearLightsScene())).toEqual(sceneToJSON(car.makeScene()));
    expect(trafficSignalCamera()).toEqual(signal.makeCamera());
    expect(rearLightsCamera()).toEqual(car.makeCamera());
    expect(failedLabels(checkTrafficSignal(trafficSignalScene(), trafficSignalCamera()))).toEqual(['Three lights']);
    expect(failedLabels(checkRearLights(rearLightsScene(), rearLightsCamera()))).toEqual(['Two red lights']);
  });

  test('with the reference solutions\' lights, both pass', () => {
    const signalScene = trafficSignalScene(), carScene = rearLightsScene();
    signalSolution.addLights(signalScene);
    carSolution.addLights(carScene);
    expect(checkTrafficSignal(signalScene, trafficSignalCamera()).passed).toBe(true);
    expect(checkRearLights(carScene, rearLightsCamera()).passed).toBe(true);
  });
});

describe('hints write code the way the page does', () => {
  test('a module page: new Sphere(…); a global-mode page ({ prefix: "RT." }): new RT.Sphere(…)', () => {
    expect(check(checkTrafficSignal(trafficSignalScene(), trafficSignalCamera()), 'Three lights').detail).toContain('e.g. new Sphere([0, 1, -10], 0.5,');
    const global = check(checkTrafficSignal(trafficSignalScene(), trafficSignalCamera(), { prefix: 'RT.' }), 'Three lights').detail;
    expect(global).toContain('e.g. new RT.Sphere([0, 1, -10], 0.5, { color: [0, 0, 0], emission: [1, 0, 0] }) is a red one.');
    const withPointLight = rearLightsScene().add(new PointLight([0, 2, -5], { color: [1, 0, 0] }));
    expect(check(checkRearLights(withPointLight, rearLightsCamera(), { prefix: 'RT.' }), 'Two red lights').detail)
      .toMatch(/new RT\.Sphere\(.*\(A RT\.PointLight cannot be seen in the picture/);
  });

  test('an unknown option is refused by name', () => {
    expect(() => checkTrafficSignal(trafficSignalScene(), trafficSignalCamera(), { prefx: 'RT.' }))
      .toThrow('unknown checkTrafficSignal option "prefx" (did you mean "prefix"?)');
    expect(() => checkRearLights(rearLightsScene(), rearLightsCamera(), { names: 'RT.' })).toThrow(/unknown checkRearLights option "names"/);
  });
});

describe('solutionParameter', () => {
  test('?solution=1 shows the solution; none or 0 the student\'s scene', () => {
    expect(solutionParameter('?solution=1')).toEqual({ solution: true, message: null });
    expect(solutionParameter('?solution=0')).toEqual({ solution: false, message: null });
    expect(solutionParameter('')).toEqual({ solution: false, message: null });
  });

  test('another value shows the student\'s scene and says what the parameter takes', () => {
    const { solution, message } = solutionParameter('?solution=yes');
    expect(solution).toBe(false);
    expect(message).toMatch(/^\?solution= takes 1 \(show the reference solution\) or 0 \(your scene\), got .*yes.*: showing your scene\.$/);
  });
});
