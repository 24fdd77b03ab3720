/**
 * A scene and a camera as plain JSON and back, every field checked, so a scene
 * can travel to a Web Worker, sit in a page's URL, or be pasted by a student;
 * and a scene as readable code that rebuilds it with the public API.
 *
 * Scene JSON: `{ background, ambient, shadows, bias, epsilon, maxDepth, specular, objects }`,
 * `objects` in the order they were added, each one a shape's own `toJSON()`
 * (lib/shapes/: its `type`, `name`, the fields its class lists, `material`), e.g.
 *   `{ type: 'sphere', name, center, radius, material }`
 *   `{ type: 'plane', name, point, normal, material }`
 *   `{ type: 'box', name, min, max, material }`
 * or a light's own `toJSON()` (lib/lights/index.js), e.g. `{ type: 'pointLight', name, position, color, intensity }`,
 * with `material` = `{ color, emission, reflection, transparency, ior, specular, shininess }`.
 */
import { Scene } from './scene.js';
import { Camera } from '../math/camera.js';
import { Material, MATERIAL_FIELDS } from '../shapes/material.js';
import { tooDeepAt } from './json-depth.js';
import { checkWork } from './work.js';
import { lightClass, lightClasses, lightClassOf } from '../lights/index.js';
import { shapeClass, shapeClasses, codeNameOf } from '../shapes/index.js';
import { vector } from '../shapes/json.js';
import { checkOptions, show, withPath as named } from '../text/check.js';

const SCENE_FIELDS = ['background', 'ambient', 'shadows', 'bias', 'epsilon', 'maxDepth', 'specular', 'objects'];
const MATERIAL_NAMES = MATERIAL_FIELDS.map((field) => field.name);
const CAMERA_FIELDS = ['width', 'height', 'fov', 'position', 'yaw', 'pitch', 'samples'];

/** The class a JSON `type` names: a listed light or shape class; undefined for none. */
function kindOfType(type) {
  return lightClass(type) ?? shapeClass(type);
}

/**
 * The scene as plain JSON-ready data (numbers, booleans, strings, arrays).
 * @example
 * const text = JSON.stringify(sceneToJSON(classScene())); // save it, share it, send it to a worker
 */
export function sceneToJSON(scene) {
  if (!(scene instanceof Scene)) throw new TypeError(`scene must be a Scene, got ${show(scene)}`);
  return { ...sceneFieldsOf(scene), objects: addOrder(scene).map(objectToJSON) };
}

/**
 * A Scene from JSON data or text, checked field by field: a bad value throws
 * a TypeError or RangeError whose message starts with its path, e.g.
 * "objects[2].radius must be greater than 0, got -1".
 * @example
 * const copy = sceneFromJSON(JSON.stringify(sceneToJSON(classScene())));
 * copy.objects.length; // as many shapes as the original
 * @param {object|string} json
 * @param {object} [options]
 * @param {number} [options.maxObjects=Infinity] more objects than this is a RangeError naming the limit
 *   (scenes from a link or a paste: MAX_SCENE_OBJECTS, lib/scene/codec.js)
 * @param {boolean} [options.limitWork=false] refuse more work than lib/scene/work.js allows (shadow rays, rays a pixel, triangles)
 */
export function sceneFromJSON(json, options) {
  const { maxObjects = Infinity, limitWork = false } = checkOptions(options, ['maxObjects', 'limitWork'], 'sceneFromJSON');
  const { objects = [], ...sceneOptions } = onlyFields(parse(json, 'scene'), SCENE_FIELDS, 'scene');
  const scene = new Scene(sceneOptions);
  if (!Array.isArray(objects)) throw new TypeError(`objects must be an array, got ${show(objects)}`);
  if (objects.length > maxObjects) {
    throw new RangeError(`the scene has ${objects.length.toLocaleString('en')} objects, more than the ${maxObjects.toLocaleString('en')} a scene from a link or a paste may have`);
  }
  if (limitWork) checkWork(objects, sceneOptions);
  objects.forEach((o, i) => scene.add(objectFromJSON(o, `objects[${i}]`)));
  return scene;
}

/** The camera as plain JSON-ready data. */
export function cameraToJSON(camera) {
  if (!(camera instanceof Camera)) throw new TypeError(`camera must be a Camera, got ${show(camera)}`);
  const { width, height, fov, position, yaw, pitch, samples } = camera;
  const json = { width, height, fov, position: vector(position), yaw, pitch };
  if (samples !== 1) json.samples = samples; // one ray per pixel, the usual: links and files stay as they were
  return json;
}

/** A Camera from JSON data or text, checked; errors name the field. */
export function cameraFromJSON(json) {
  return new Camera(onlyFields(parse(json, 'camera'), CAMERA_FIELDS, 'camera'));
}

/**
 * JavaScript source that rebuilds the scene with the public API, for a
 * "copy the scene as code" button: an import line, then `const scene = …`
 * and one `scene.add(…)` per object. Colours that are whole bytes and would
 * print long (like 0.3176470588235294) are written as '#rrggbb'.
 * @param {Scene} scene
 * @param {object} [options]
 * @param {string} [options.importFrom='../lib/index.js'] where the code imports the library from
 * @example
 * const code = sceneToCode(classScene()); // "import { Scene, Sphere } from '../lib/index.js'; const scene = new Scene(…"
 */
export function sceneToCode(scene, options) {
  return [...sceneCodeLines(scene, options)].join('');
}

/**
 * sceneToCode's text, a line (with its line break) at a time, each object's
 * line made when it is read: big scenes' code is built in slices
 * (joinInSlices, lib/text/slices.js) with no long task.
 * @param {Scene} scene
 * @param {{ importFrom?: string }} [options]
 * @returns {Generator<string>}
 * @example
 * const lines = [...sceneCodeLines(classScene())]; // sceneToCode's lines; joinInSlices(sceneCodeLines(scene)) builds its text with no long task
 */
export function* sceneCodeLines(scene, { importFrom = '../lib/index.js' } = {}) {
  if (!(scene instanceof Scene)) throw new TypeError(`scene must be a Scene, got ${show(scene)}`);
  const items = addOrder(scene);
  const used = new Set(['Scene', ...items.map(itemClassName)]);
  const order = ['Scene', ...[...shapeClasses(), ...lightClasses()].map(codeNameOf)].filter((n) => used.has(n));
  const fields = sceneFieldsOf(scene);
  yield `import { ${order.join(', ')} } from ${quote(importFrom)};\n`;
  yield '\n';
  yield `const scene = new Scene(${literal(sceneOptions(fields))});\n`;
  const names = new Set(['scene']);
  for (const item of items) {
    const o = objectToJSON(item);
    const call = constructorCall(o);
    if (!o.name) {
      yield `scene.add(${call});\n`;
      continue;
    }
    const id = identifier(o.name, names);
    yield `const ${id} = ${call};\n${id}.name = ${quote(o.name)};\nscene.add(${id});\n`;
  }
}

/** The class an item is built with in the code ('Sphere', 'PointLight'), read without writing its JSON where its class says it. */
function itemClassName(item) {
  const Light = lightClassOf(item);
  if (Light) return codeNameOf(Light);
  return codeNameOf(shapeClasses().includes(item?.constructor) ? item.constructor : shapeClass(objectToJSON(item).type));
}

/** A scene's own fields as JSON (all but its objects). */
function sceneFieldsOf(scene) {
  const { background, ambient, shadows, bias, epsilon, maxDepth, specular } = scene;
  return { background: [...background], ambient, shadows, bias, epsilon, maxDepth, specular };
}

/* ---- to JSON ---- */

/**
 * Shapes and point lights in an order that rebuilds both lists exactly: the
 * lights' order decides the order light is summed in, which a pixel's last
 * bit can depend on. A point light goes just before the first emissive shape
 * that comes after it among the scene's lights.
 */
export function addOrder(scene) {
  const items = [];
  let next = 0; // the next of scene.lights not yet placed
  const placePointLights = () => {
    while (next < scene.lights.length && scene.lights[next].object === null) {
      const { source } = scene.lights[next++];
      if (items.at(-1) !== source) items.push(source); // an area light is several entries, one object
    }
  };
  for (const shape of scene.objects) {
    if (shape.material.isEmissive) {
      placePointLights();
      next++; // this shape's own light entry
    }
    items.push(shape);
  }
  placePointLights();
  return items;
}

/** One shape's or light's JSON, as sceneToJSON writes it. */
export function objectToJSON(item) {
  if (lightClassOf(item)) return item.toJSON();
  const json = typeof item?.toJSON === 'function' ? item.toJSON() : null;
  if (json && shapeClass(json.type)) return json;
  throw new TypeError(`scene objects must be spheres, planes, boxes or point lights (or other listed shapes, with a toJSON), got ${show(item)}`);
}

/* ---- from JSON ---- */

/** Scene JSON is 5 levels deep (objects[0].material.color[0]); deeper than this is no scene. */
export const MAX_JSON_DEPTH = 32;

function parse(json, what) {
  let data = json;
  if (typeof json === 'string') {
    const deep = tooDeepAt(json, MAX_JSON_DEPTH); // before JSON.parse builds every level
    if (deep !== null) throw new RangeError(`${what} is nested more than ${MAX_JSON_DEPTH} levels deep, at ${deep}`);
    try {
      data = JSON.parse(json);
    } catch (error) {
      throw new TypeError(`${what} is not valid JSON: ${error.message.slice(0, 160)}`, { cause: error });
    }
  }
  if (data === null || typeof data !== 'object' || Array.isArray(data)) {
    throw new TypeError(`${what} must be an object, got ${show(data)}`);
  }
  if (typeof json !== 'string') checkDepth(data, what); // text was measured before it was parsed: no walk of 50,000 arrays again
  return data;
}

/**
 * A RangeError naming the path where `data` nests deeper than MAX_JSON_DEPTH
 * (a hostile 10,000-level array would overflow the stack of any recursive
 * check). Walks with its own stack, not recursion.
 */
function checkDepth(data, what) {
  const stack = [[data, 0, null]]; // [value, depth, parent entry] — the path is rebuilt only on failure
  while (stack.length) {
    const entry = stack.pop();
    const [value, depth] = entry;
    if (value === null || typeof value !== 'object') continue;
    if (depth >= MAX_JSON_DEPTH) {
      throw new RangeError(`${what} is nested more than ${MAX_JSON_DEPTH} levels deep, at ${pathOf(entry)}`);
    }
    if (Array.isArray(value)) {
      for (let i = 0; i < value.length; i++) if (value[i] !== null && typeof value[i] === 'object') stack.push([value[i], depth + 1, entry, `[${i}]`]);
    } else {
      for (const key of Object.keys(value)) if (value[key] !== null && typeof value[key] === 'object') stack.push([value[key], depth + 1, entry, `.${key.slice(0, 40)}`]);
    }
  }
}

/** 'objects[0].material.color[0]…' from a checkDepth entry's chain of parents. */
function pathOf(entry) {
  const parts = [];
  for (let e = entry; e && e[3] !== undefined; e = e[2]) parts.push(e[3]);
  const path = parts.reverse().join('').replace(/^\./, '');
  return path.length > 120 ? `${path.slice(0, 119)}…` : path;
}

/** A misspelt field would silently fall back to its default: name it instead. */
function onlyFields(data, allowed, path) {
  const own = Object.create(null); // read fields from this: nothing set on Object.prototype is a field
  for (const key of Object.keys(data)) {
    if (!allowed.includes(key)) {
      throw new TypeError(`${path} has no field ${show(key)} (its fields: ${allowed.join(', ')})`);
    }
    own[key] = data[key];
  }
  return own;
}

/**
 * One object of scene JSON as a shape or point light, with sceneFromJSON's
 * checks and messages: `path` ('objects[2]') starts them.
 */
export function objectFromJSON(given, path) {
  if (given === null || typeof given !== 'object' || Array.isArray(given)) throw new TypeError(`${path} must be an object, got ${show(given)}`);
  const type = Object.hasOwn(given, 'type') ? given.type : undefined;
  const kind = typeof type === 'string' ? kindOfType(type) : undefined; // ["sphere"] is not "sphere"
  if (!kind) {
    const types = [...shapeClasses(), ...lightClasses()].map((Kind) => Kind.type);
    throw new TypeError(`${path}.type must be one of ${types.map((t) => `"${t}"`).join(', ')}, got ${show(type)}`);
  }
  const o = onlyFields(given, ['type', 'name', ...kind.fields], path);
  if (o.name !== undefined && typeof o.name !== 'string') throw new TypeError(`${path}.name must be a string, got ${show(o.name)}`);
  let material;
  if (kind.fields.includes('material') && o.material !== undefined) {
    if (o.material === null || typeof o.material !== 'object' || Array.isArray(o.material)) {
      throw new TypeError(`${path}.material must be an object, got ${show(o.material)}`);
    }
    const fields = onlyFields(o.material, MATERIAL_NAMES, `${path}.material`); // its message has the path already
    material = named(() => new Material(fields), `${path}.material.`);
  }
  const item = named(() => kind.build(o, material), `${path}.`);
  item.name = o.name ?? '';
  return item;
}

/* ---- to code ---- */

const SCENE_DEFAULTS = { background: [0, 0, 0], ambient: 0, shadows: true, bias: 1e-4, epsilon: 1e-6, maxDepth: 5, specular: true };
const MATERIAL_DEFAULTS = Object.fromEntries(MATERIAL_FIELDS.map(({ name, value }) => [name, value]));

function sceneOptions(data) {
  return withoutDefaults(data, SCENE_DEFAULTS);
}

/** `new Sphere(…)` for one object's JSON: its class's own code name and arguments (a light's `codeArguments`; a shape's, else its fields in order), defaults left out. */
function constructorCall(o) {
  const Kind = /** @type {any} */ (kindOfType(o.type));
  const args = lightClass(o.type) ? Kind.codeArguments(o, CODE) : shapeArguments(Kind, o);
  while (args.length && args.at(-1) === undefined) args.pop();
  return `new ${codeNameOf(Kind)}(${args.map((a) => literal(a)).join(', ')})`;
}

/** Source text as it stands, for an argument its class wants written a particular way. */
class Code {
  constructor(text) { this.text = text; }
}

/** What a light's `codeArguments` may ask of the code: a colour argument written as colours are ('#ff5160' when that says it exactly). */
const CODE = { color: (rgb) => new Code(colorLiteral(rgb)) };

/** A shape's constructor arguments: its class's own `codeArguments`, else its fields in order. */
function shapeArguments(Shape, o) {
  if (typeof Shape.codeArguments === 'function') return Shape.codeArguments(o, materialArgument(o.material));
  if (!Shape.fields.includes('material')) return Shape.fields.map((field) => o[field]);
  return Shape.fields.map((field) => (field === 'material' ? materialArgument(o.material) : o[field]));
}

/** A material as the code writes it: only what differs from the defaults, or nothing. */
function materialArgument(material) {
  if (!material) return undefined;
  const m = withoutDefaults(material, MATERIAL_DEFAULTS);
  return Object.keys(m).length ? m : undefined;
}

const isGrey = (c) => c[0] === c[1] && c[1] === c[2];

function withoutDefaults(data, defaults) {
  const out = {};
  for (const [key, value] of Object.entries(defaults)) {
    if (data[key] !== undefined && !same(data[key], value)) out[key] = data[key]; // (a field left out of the JSON: its default)
  }
  return out;
}

/** Equal values, −0 not 0 (JSON.stringify would say they are the same). */
const same = (a, b) => (Array.isArray(a) && Array.isArray(b) ? a.length === b.length && a.every((x, i) => same(x, b[i])) : Object.is(a, b));

const COLOR_KEYS = new Set(['background', 'color', 'emission']);

/** Source text for a value: numbers exact, objects on one line like `{ color: [1, 0, 0] }`. */
function literal(value, isColor = false) {
  if (value instanceof Code) return value.text;
  if (Array.isArray(value)) return isColor ? colorLiteral(value) : `[${value.map((v) => literal(v)).join(', ')}]`;
  if (value && typeof value === 'object') {
    const entries = Object.entries(value).map(([k, v]) => `${k}: ${k === 'emission' && isGrey(v) ? literal(v[0]) : literal(v, COLOR_KEYS.has(k))}`);
    return entries.length ? `{ ${entries.join(', ')} }` : '{}';
  }
  if (typeof value === 'string') return quote(value);
  return Object.is(value, -0) ? '-0' : String(value); // String(-0) is '0'
}

/** A string literal in single quotes. */
function quote(text) {
  return `'${JSON.stringify(text).slice(1, -1).replace(/\\"/g, '"').replace(/'/g, "\\'")}'`;
}

/** '#rrggbb' when it says the same number more shortly, else [r, g, b]. */
function colorLiteral(rgb) {
  const plain = `[${rgb.map((c) => literal(c)).join(', ')}]`;
  const bytes = rgb.map((c) => Math.round(c * 255));
  const exact = bytes.every((b, i) => b <= 255 && b / 255 === rgb[i]);
  if (!exact || rgb.some((c) => Object.is(c, -0)) || rgb.every((c) => String(c).length <= 5)) return plain;
  return "'#" + bytes.map((b) => b.toString(16).padStart(2, '0')).join('') + "'";
}

/** A JavaScript name from an object's name: 'light 1' → light1; unique in `taken`. */
function identifier(name, taken) {
  const words = name.replace(/[^A-Za-z0-9_$ ]+/g, ' ').trim().split(/\s+/).filter(Boolean);
  let id = words.map((w, i) => (i ? w[0].toUpperCase() + w.slice(1) : w.toLowerCase())).join('') || 'object';
  if (/^[0-9]/.test(id) || RESERVED.has(id) || [...shapeClasses(), ...lightClasses()].some((Kind) => codeNameOf(Kind) === id)) id = `_${id}`;
  let unique = id;
  for (let n = 2; taken.has(unique); n++) unique = `${id}${n}`;
  taken.add(unique);
  return unique;
}

// Every word a strict-mode (module) binding may not be, and the names the code itself uses.
const RESERVED = new Set(['implements', 'interface', 'package', 'private', 'protected', 'public', 'eval', 'arguments',
  'break', 'case', 'catch', 'class', 'const', 'continue', 'debugger', 'default', 'delete', 'do',
  'else', 'export', 'extends', 'false', 'finally', 'for', 'function', 'if', 'import', 'in', 'instanceof', 'let', 'new',
  'null', 'return', 'static', 'super', 'switch', 'this', 'throw', 'true', 'try', 'typeof', 'var', 'void', 'while',
  'with', 'yield', 'await', 'enum', 'Scene', 'undefined', 'NaN', 'Infinity']);
