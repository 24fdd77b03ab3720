/**
 * A scene and its JSON kept in step one change at a time, for the scene form
 * (lib/p5/controls/scene-form.js). A new value is checked on its own object, with
 * sceneFromJSON's checks and messages (objectFromJSON), and the new Scene
 * reuses every other shape and light as built before: checking and building
 * 1,000 spheres again for each typed value or "Add sphere" held the page's
 * main thread 120–400 ms on a busy machine.
 *
 * After any edits `edits.scene` is the scene `sceneFromJSON(edits.json)`
 * builds, to the last bit (tests/unit/scene-edits.test.js checks it over
 * random edits), and `json` is what the whole scene's check and sceneToJSON
 * would make of the change, in the rows' order. The
 * objects of `json` stay in the order of the form's rows (new ones at the
 * end), so a row's index keeps naming its object. Each edit makes a new
 * `json` (the old one is left as it was) and a new Scene.
 *
 *   const edits = new SceneEdits(sceneToJSON(classScene()));
 *   edits.set(['objects', 1, 'radius'], 6);   // a bad value throws sceneFromJSON's error; nothing changes
 *   edits.add({ type: 'sphere', center: [0, 3, -12], radius: 1 });
 *   view.setScene(edits.scene);
 */
import { Scene } from './scene.js';
import { sceneToJSON, sceneFromJSON, objectToJSON, objectFromJSON, addOrder } from './json.js';
import { withValue } from './fields.js';
import { show } from '../text/check.js';

export class SceneEdits {
  /** The shapes and point lights, in the order of `json.objects`. */
  #items;

  /** @param {object|string} json scene JSON, checked by sceneFromJSON */
  constructor(json) {
    /** The scene's JSON, every field present (as sceneToJSON writes it). */
    const first = sceneFromJSON(json);
    this.json = sceneToJSON(first);
    // A shape or light whose class `roundTrips` (a sphere, a box, a point light) built from this.json would be the same
    // to the bit: checked once, not twice. Any other is built again from its JSON (a plane's normal, for one, is normalised again).
    const same = (item) => item.constructor.roundTrips === true;
    this.#items = addOrder(first).map((item, i) => (same(item) ? item : objectFromJSON(this.json.objects[i], `objects[${i}]`)));
    /** The scene: what sceneFromJSON(this.json) builds. */
    this.scene = sceneOf(this.json, this.#items);
  }

  /**
   * Puts `value` at `path` of the JSON: `['objects', index, ...field]` (e.g.
   * `['objects', 2, 'material', 'color']`) or a scene field (`['background']`).
   * A bad value throws the TypeError/RangeError sceneFromJSON would, and
   * changes nothing.
   */
  set(path, value) {
    if (!Array.isArray(path) || path.length === 0) throw new TypeError(`path must be a non-empty array like ['objects', 0, 'radius'], got ${show(path)}`);
    if (path[0] !== 'objects') {
      const { objects, ...fields } = this.json;
      const scene = sceneFromJSON({ ...withValue(fields, path, value), objects: [] }); // checked as a whole scene's fields are
      this.#take({ ...sceneToJSON(scene), objects }, this.#items);
      return;
    }
    const index = this.#index(path[1]);
    const field = path.slice(2);
    const { o, item } = checked(field.length ? withValue(this.json.objects[index], field, value) : value, `objects[${index}]`);
    this.#take({ ...this.json, objects: replaced(this.json.objects, index, o) }, replaced(this.#items, index, item));
  }

  /** Adds an object's JSON at the end (checked as sceneFromJSON checks it); returns its index in `json.objects`. */
  add(o) {
    const index = this.#items.length;
    const checkedObject = checked(o, `objects[${index}]`);
    this.#take({ ...this.json, objects: [...this.json.objects, checkedObject.o] }, [...this.#items, checkedObject.item]);
    return index;
  }

  /** Removes the object at `index` of `json.objects`. */
  remove(index) {
    const i = this.#index(index);
    this.#take({ ...this.json, objects: without(this.json.objects, i) }, without(this.#items, i));
  }

  #index(index) {
    if (!Number.isInteger(index) || index < 0 || index >= this.#items.length) {
      throw new RangeError(`index must be a whole number from 0 to ${this.#items.length - 1}, got ${show(index)}`);
    }
    return index;
  }

  #take(json, items) {
    const scene = sceneOf(json, items); // before anything changes
    this.json = json;
    this.#items = items;
    this.scene = scene;
  }
}

/**
 * An object's JSON as sceneToJSON writes it (every field, colours as numbers),
 * and the shape or light built from that JSON: sceneFromJSON(json) then builds
 * the same, to the last bit (a plane's normal is normalised again on reading).
 */
function checked(json, path) {
  const o = objectToJSON(objectFromJSON(json, path));
  return { o, item: objectFromJSON(o, path) };
}

/** A Scene with the scene fields of `json` and `items` added in order, as sceneFromJSON adds them. */
function sceneOf(json, items) {
  const fields = { ...json };
  delete fields.objects;
  const scene = new Scene(fields);
  for (const item of items) scene.add(item);
  return scene;
}

const replaced = (array, index, value) => array.map((x, i) => (i === index ? value : x));
const without = (array, index) => array.filter((_, i) => i !== index);
