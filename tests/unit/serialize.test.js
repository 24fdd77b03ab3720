import { describe, it, expect } from 'vitest';
import { sceneToJSON, sceneFromJSON, cameraToJSON, cameraFromJSON, sceneToCode } from '../../lib/scene/json.js';
import { render, Camera, Scene, Sphere, Plane, Box, PointLight, classScene } from '../../lib/index.js';
import { shapeClasses } from '../../lib/shapes/index.js';
import { lightClasses } from '../../lib/lights/index.js';

/** Every type scene JSON takes, as its message lists them: the listed shapes', then the listed lights' (a new class joins by being listed). */
const LISTED_TYPES = [...shapeClasses(), ...lightClasses()].map((Kind) => `"${Kind.type}"`).join(', ');

/** A plane, a box, glass, an emissive sphere and point lights added between shapes. */
function roomScene() {
  const scene = new Scene({ background: '#87ceeb', ambient: 0.05, bias: 1e-3, maxDepth: 3, specular: false });
  scene.add(new PointLight([5, 8, 0], [1, 1, 0.9], 1.2));
  scene.add(Object.assign(new Plane([0, -2, 0], [0.1, 1, 0.05], { color: [0.8, 0.8, 0.8], reflection: 0.3 }), { name: 'floor' }));
  scene.add(new Box([-3, -2, -14], [-1, 0, -12], { color: 'orange', specular: 0.4, shininess: 20 }));
  scene.add(new Sphere([1.5, -0.5, -12], 1.5, { color: 'pink', transparency: 0.6, ior: 1.5 }));
  scene.add(new PointLight([-6, 4, -2], 'skyblue', 0.5));
  scene.add(Object.assign(new Sphere([0, 6, -18], 1, { color: [0, 0, 0], emission: [2, 1.5, 1] }), { name: 'lamp' }));
  scene.add(new PointLight([0, 2, 5]));
  return scene;
}

const CAMERA = new Camera({ width: 48, height: 36, fov: 45, position: [0, 1, 2], yaw: 5, pitch: -8 });

/** The scene's whole state as plain values, to compare two scenes. */
function state(scene) {
  return JSON.parse(JSON.stringify({ scene, lights: scene.lights.map((l) => ({ ...l, object: l.object && scene.objects.indexOf(l.object), source: null })) }));
}

describe('scene JSON round trip', () => {
  for (const [name, make] of [['class scene', () => classScene()], ['class scene, full shading', () => classScene({ full: true })], ['room with plane, box and point lights', roomScene]]) {
    it(`${name}: same scene, same picture byte for byte, through JSON text`, () => {
      const scene = make();
      const text = JSON.stringify(sceneToJSON(scene));
      const back = sceneFromJSON(text);
      expect(state(back)).toEqual(state(scene));
      expect(back.objects.map((o) => o.constructor)).toEqual(scene.objects.map((o) => o.constructor));
      expect(render(back, CAMERA)).toEqual(render(scene, CAMERA));
      expect(sceneToJSON(back)).toEqual(JSON.parse(text));
    });
  }

  it('writes the documented shape', () => {
    const json = sceneToJSON(roomScene());
    expect(Object.keys(json)).toEqual(['background', 'ambient', 'shadows', 'bias', 'epsilon', 'maxDepth', 'specular', 'objects']);
    expect(json.objects.map((o) => o.type)).toEqual(['plane', 'box', 'sphere', 'pointLight', 'pointLight', 'sphere', 'pointLight']);
    const [floor, box, glass, light] = json.objects;
    expect(floor.name).toBe('floor');
    expect(Object.keys(floor)).toEqual(['type', 'name', 'point', 'normal', 'material']);
    expect(box.min).toEqual([-3, -2, -14]);
    expect(glass.material).toEqual({ color: [1, 192 / 255, 203 / 255], emission: [0, 0, 0], reflection: 0, transparency: 0.6, ior: 1.5, specular: 0, shininess: 50 });
    expect(light).toEqual({ type: 'pointLight', name: '', position: [5, 8, 0], color: [1, 1, 0.9], intensity: 1.2 });
  });

  it('keeps the order lights are summed in, whatever order they were added', () => {
    const scene = roomScene();
    const back = sceneFromJSON(sceneToJSON(scene));
    expect(back.lights.map((l) => l.position)).toEqual(scene.lights.map((l) => l.position));
  });

  it('fills in defaults for fields left out', () => {
    const scene = sceneFromJSON({ objects: [{ type: 'sphere', center: [0, 0, -5], radius: 1 }] });
    expect(scene.background).toEqual([0, 0, 0]);
    expect(scene.objects[0].material.color).toEqual([1, 1, 1]);
    expect(scene.objects[0].name).toBe('');
    expect(sceneFromJSON('{}').objects).toEqual([]);
  });

  it('refuses to write objects it cannot read back', () => {
    const scene = classScene();
    scene.objects.push({ hit: () => Infinity, material: { isEmissive: false } });
    expect(() => sceneToJSON(scene)).toThrow(/scene objects must be spheres, planes, boxes or point lights/);
    expect(() => sceneToJSON({ objects: [] })).toThrow(/scene must be a Scene/);
  });
});

describe('bad scene JSON names the field', () => {
  const sphere = (extra) => ({ type: 'sphere', center: [0, 0, -5], radius: 1, ...extra });
  const cases = [
    [{ objects: [sphere(), sphere(), sphere({ radius: -1 })] }, RangeError, 'objects[2].radius must be greater than 0, got -1'],
    [{ objects: [sphere({ radius: '2' })] }, TypeError, 'objects[0].radius must be a finite number, got "2"'],
    [{ objects: [sphere({ center: [0, NaN, 0] })] }, TypeError, 'objects[0].center.y must be a finite number'],
    [{ objects: [sphere({ center: [0, 0] })] }, TypeError, 'objects[0].center must have 3 numbers'],
    [{ objects: [sphere({ center: undefined })] }, TypeError, 'objects[0].center must be [x, y, z]'],
    [{ objects: [sphere({ material: { color: [1, 'a', 0] } })] }, TypeError, 'objects[0].material.color[1] must be a finite number, got "a"'],
    [{ objects: [sphere({ material: { color: 'blurple' } })] }, TypeError, 'objects[0].material.color must be a colour'],
    [{ objects: [sphere({ material: { reflection: 2 } })] }, RangeError, 'objects[0].material.reflection must be between 0 and 1, got 2'],
    [{ objects: [sphere({ material: { transparency: -0.5 } })] }, RangeError, 'objects[0].material.transparency must be between 0 and 1'],
    [{ objects: [sphere({ material: { ior: 0.5 } })] }, RangeError, 'objects[0].material.ior must be between 1 and 4'],
    [{ objects: [sphere({ material: { emission: [-1, 0, 0] } })] }, RangeError, 'objects[0].material.emission[0] must not be negative'],
    [{ objects: [sphere({ material: { specular: 'yes' } })] }, TypeError, 'objects[0].material.specular must be a finite number'],
    [{ objects: [sphere({ material: { shininess: 0 } })] }, RangeError, 'objects[0].material.shininess must be between 1 and 10000'],
    [{ objects: [sphere({ material: { colour: [1, 0, 0] } })] }, TypeError, 'objects[0].material has no field "colour"'],
    [{ objects: [sphere({ material: 'red' })] }, TypeError, 'objects[0].material must be an object, got "red"'],
    [{ objects: [sphere({ radious: 2 })] }, TypeError, 'objects[0] has no field "radious"'],
    [{ objects: [sphere({ name: 7 })] }, TypeError, 'objects[0].name must be a string, got 7'],
    [{ objects: [sphere(), { type: 'cube' }] }, TypeError, `objects[1].type must be one of ${LISTED_TYPES}, got "cube"`],
    [{ objects: [{ type: 'constructor' }] }, TypeError, 'objects[0].type must be one of'],
    [{ objects: [sphere(), null] }, TypeError, 'objects[1] must be an object, got null'],
    [{ objects: [{ type: 'plane', normal: [0, 0, 0] }] }, RangeError, 'objects[0].normal must not be zero-length'],
    [{ objects: [{ type: 'plane', point: 'here' }] }, TypeError, 'objects[0].point must be [x, y, z]'],
    [{ objects: [{ type: 'box', min: [0, 0, 0], max: [1, 0, 1] }] }, RangeError, 'objects[0].max.y must be greater than min.y'],
    [{ objects: [{ type: 'pointLight', position: [0, 1, 0], intensity: -2 }] }, RangeError, 'objects[0].intensity must not be negative, got -2'],
    [{ objects: [{ type: 'pointLight', position: [0, 1, 0], color: [1, 1] }] }, TypeError, 'objects[0].color must have 3 numbers'],
    [{ objects: [{ type: 'pointLight', position: [0, 1, 0], material: {} }] }, TypeError, 'objects[0] has no field "material"'],
    [{ objects: 'spheres' }, TypeError, 'objects must be an array, got "spheres"'],
    [{ ambient: 3 }, RangeError, 'ambient must be between 0 and 1, got 3'],
    [{ background: [0, 0] }, TypeError, 'background must have 3 numbers'],
    [{ shadows: 'no' }, TypeError, 'shadows must be true or false, got "no"'],
    [{ maxDepth: 99 }, RangeError, 'maxDepth must be between 0 and 16, got 99'],
    [{ lights: [] }, TypeError, 'scene has no field "lights"'],
    [[], TypeError, 'scene must be an object'],
    [null, TypeError, 'scene must be an object, got null'],
    ['{"objects": [', TypeError, 'scene is not valid JSON'],
  ];
  for (const [json, kind, message] of cases) {
    it(message, () => {
      expect(() => sceneFromJSON(json)).toThrow(kind);
      let said = '';
      try { sceneFromJSON(json); } catch (error) { said = error.message; }
      expect(said.startsWith(message), said).toBe(true); // the path once, in front (not "objects[0].material.objects[0].material …")
    });
  }
});

describe('camera JSON', () => {
  it('round trips every field, and the picture', () => {
    const json = cameraToJSON(CAMERA);
    expect(json).toEqual({ width: 48, height: 36, fov: 45, position: [0, 1, 2], yaw: 5, pitch: -8 });
    const back = cameraFromJSON(JSON.stringify(json));
    expect(back).toBeInstanceOf(Camera);
    expect(render(classScene(), back)).toEqual(render(classScene(), CAMERA));
  });

  it('names a bad field', () => {
    expect(() => cameraFromJSON({ width: 0, height: 10 })).toThrow(/^width must be a positive whole number, got 0$/);
    expect(() => cameraFromJSON({ width: 10, height: 10, fov: 200 })).toThrow(RangeError);
    expect(() => cameraFromJSON({ width: 10, height: 10, position: [0, 'up', 0] })).toThrow('position.y must be a finite number');
    expect(() => cameraFromJSON({ width: 10, height: 10, zoom: 2 })).toThrow('camera has no field "zoom"');
    expect(() => cameraFromJSON('nope')).toThrow('camera is not valid JSON');
    expect(() => cameraToJSON({ width: 1 })).toThrow(/camera must be a Camera/);
  });
});

describe('sceneToCode', () => {
  /** Runs the generated code with the library's classes in place of its import line. */
  function run(code) {
    const [importLine, ...rest] = code.split('\n');
    expect(importLine).toMatch(/^import \{ [\w, ]+ \} from '\.\.\/lib\/index\.js';$/);
    return new Function('Scene', 'Sphere', 'Plane', 'Box', 'PointLight', `${rest.join('\n')}\nreturn scene;`)(Scene, Sphere, Plane, Box, PointLight);
  }

  for (const [name, make] of [['class scene', () => classScene({ full: true })], ['room', roomScene]]) {
    it(`${name}: the code rebuilds the same scene and picture`, () => {
      const scene = make();
      const back = run(sceneToCode(scene));
      expect(state(back)).toEqual(state(scene));
      expect(render(back, CAMERA)).toEqual(render(scene, CAMERA));
    });
  }

  it('reads like the lesson\'s code: names as variables, defaults left out', () => {
    const code = sceneToCode(classScene());
    expect(code).toContain("import { Scene, Sphere } from '../lib/index.js';");
    expect(code).toContain('const scene = new Scene({ background: [2, 2, 2] });');
    expect(code).toContain("const pink = new Sphere([0, 0, -20], 4, { color: [1, 0.32, 0.36] });\npink.name = 'pink';\nscene.add(pink);");
    expect(code).toContain("const light1 = new Sphere([0, 20, -30], 3, { color: [0, 0, 0], emission: 1.2 });\nlight1.name = 'light 1';");
    const room = sceneToCode(roomScene(), { importFrom: 'raytracing-sketchbook' });
    expect(room).toContain("import { Scene, Sphere, Plane, Box, PointLight } from 'raytracing-sketchbook';");
    expect(room).toContain("{ color: '#ffa500', specular: 0.4, shininess: 20 }"); // whole-byte colours print short
    expect(room).toContain('scene.add(new PointLight([0, 2, 5]));');
  });

  it('makes safe, distinct variable names from any object name', () => {
    const scene = new Scene();
    for (const name of ['ball', 'ball', 'new', '3rd ball', "it's \"odd\"", 'scene']) {
      scene.add(Object.assign(new Sphere([0, 0, -5], 1), { name }));
    }
    const back = run(sceneToCode(scene));
    expect(back.objects.map((o) => o.name)).toEqual(['ball', 'ball', 'new', '3rd ball', "it's \"odd\"", 'scene']);
  });
});
