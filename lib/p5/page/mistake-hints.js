/**
 * "Did you mean …?" for a name that is not there, as p5's Friendly Error
 * System does: the error panel (error-panel.js) loads this module only when
 * a message names a missing name, and shows the nearest name the kit, p5 or
 * the module imported from has (text/check.js's closestName, the same as for a
 * misspelt option):
 *
 *   p.createTracerVeiw is not a function            → did you mean p.createTracerView?
 *   Spehre is not defined                           → did you mean Sphere?
 *   createCanvas is not defined (instance mode)     → in instance mode write p.createCanvas(…)
 *   … does not provide an export named 'Spehre'     → did you mean Sphere?
 */
import p5 from 'p5';
import * as library from '../../index.js';
import * as addon from '../exports.js'; // the entry's names, not the entry: it installs the panel that loads this module
import { closestName } from '../../text/check.js';

/**
 * The hint for `message`, or null when no name is near enough.
 * @param {string} message the panel's message ("TypeError: p.x is not a function")
 * @param {string} base the URL a module named in the message is relative to (the importing script's)
 * @returns {Promise<string|null>}
 */
export async function hintFor(message, base) {
  const missingExport = /requested module '([^']+)' does not provide an export named '([^']+)'/.exec(message);
  if (missingExport) return exportHint(missingExport[1], missingExport[2], base);
  const notFunction = /^TypeError: (?:(.*)\.)?([\w$]+) is not a function/.exec(message);
  if (notFunction) return methodHint(notFunction[1], notFunction[2]);
  const notDefined = /^ReferenceError: (?:([\w$]+) is not defined|Can't find variable: ([\w$]+))/.exec(message);
  if (notDefined) return nameHint(notDefined[1] ?? notDefined[2], await ownNames(base));
  return null;
}

/** The names the sketch's file (`url`) writes, its own constants and functions among them; none when it cannot be read. */
async function ownNames(url) {
  if (new URL(url).origin !== location.origin || !/\.[cm]?js$/.test(new URL(url).pathname)) return [];
  try {
    const response = await fetch(url);
    return response.ok ? [...new Set((await response.text()).match(/[A-Za-z_$][\w$]*/g))] : [];
  } catch {
    return [];
  }
}

/** An import the module does not export: the nearest name it does. */
async function exportHint(from, name, base) {
  const module = await import(/* @vite-ignore */ new URL(from, base).href);
  const methods = Object.keys(module.FACTORIES ?? {}); // lib/p5/index.js: createTracerView is p's method, not an export
  const meant = closestName(name, [...Object.keys(module), ...methods]);
  if (!meant) return null;
  if (!methods.includes(meant)) return `did you mean ${meant}?`;
  const method = `is a method of p, not an export: write p.${meant}({ … })`;
  return meant === name ? `${meant} ${method}` : `did you mean ${meant}? It ${method}`;
}

/** `receiver.name(…)` where it has no such method: the nearest of p5's functions and the kit's methods. */
function methodHint(receiver, name) {
  const meant = closestName(name, [...p5Functions(), ...kitMethods()]);
  if (!meant) return null;
  const on = receiver && /^[\w$.]+$/.test(receiver) ? `${receiver}.` : '…';
  return `did you mean ${on}${meant}?`;
}

/**
 * A bare name that is not defined: a p5 or kit function without `p.`, a kit
 * class not imported, or a misspelling of one, or of a name the sketch itself
 * writes (`WIDHT` → its own `WIDTH`, before p5's `width`).
 */
function nameHint(name, own) {
  const global = typeof (/** @type {any} */ (window).setup) === 'function' || typeof (/** @type {any} */ (window).draw) === 'function';
  const ofP5 = p5Names();
  if (ofP5.has(name)) {
    const whose = Object.hasOwn(addon.FACTORIES, name) ? 'a p5 method of the kit' : "p5's";
    return global
      ? `${name} is ${whose}: it is there once p5 has started, so use it in setup() or draw()`
      : `${name} is ${whose}: in instance mode write p.${name}${ofP5.get(name) ? '(…)' : ''}`;
  }
  const where = Object.hasOwn(library, name) ? 'lib/index.js' : Object.hasOwn(addon, name) ? 'lib/p5/index.js' : null;
  if (where) return `${name} is the kit's: add it to the sketch's import from ${where}`;
  const mine = closestName(name, own.filter((n) => n !== name));
  if (mine) return `did you mean ${mine}?`;
  const exported = closestName(name, [...Object.keys(library), ...Object.keys(addon)]);
  const p5Name = closestName(name, ofP5.keys());
  const meant = exported ?? p5Name;
  if (!meant) return null;
  return meant === exported || global ? `did you mean ${meant}?` : `did you mean p.${meant}${ofP5.get(meant) ? '(…)' : ''}?`;
}

let names = null;
/** p5's own names (its functions, constants and fields, the addon's factories among them) → is it a function? */
function p5Names() {
  if (names) return names;
  names = new Map();
  for (let o = p5.prototype; o && o !== Object.prototype; o = Object.getPrototypeOf(o)) {
    for (const key of Object.getOwnPropertyNames(o)) {
      if (key.startsWith('_') || key === 'constructor' || names.has(key)) continue;
      const d = Object.getOwnPropertyDescriptor(o, key);
      names.set(key, typeof d.value === 'function');
    }
  }
  for (const key of Object.keys(p5)) if (/^[A-Z][A-Z_0-9]+$/.test(key)) names.set(key, false); // constants: p.PI, p.WEBGL
  return names;
}

function p5Functions() {
  return [...p5Names()].filter(([, isFunction]) => isFunction).map(([key]) => key);
}

/** The methods of the kit's exported classes (view.setMode, scene.add, …). */
function kitMethods() {
  const methods = new Set();
  for (const value of [...Object.values(library), ...Object.values(addon)]) {
    if (typeof value !== 'function' || !value.prototype) continue;
    for (const key of Object.getOwnPropertyNames(value.prototype)) {
      if (key !== 'constructor' && !key.startsWith('_') && typeof Object.getOwnPropertyDescriptor(value.prototype, key).value === 'function') methods.add(key);
    }
  }
  return methods;
}
