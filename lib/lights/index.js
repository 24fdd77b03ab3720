/**
 * The list of lights: every light class of the kit, and what the rest of the
 * library asks of a light without knowing its class (the light protocol,
 * docs/ARCHITECTURE.md "A new light").
 *
 * A light has `sources()` (the tracer's point sources: `{ position,
 * emission, object: null, source, attenuation }`, plus `spot` for a cone;
 * lib/lights/packed.js packs any of them), `toJSON()` and `viewKey()`, and may have
 * `outlines()` (loops of points the 3D view draws: a disc's rim). Its class
 * gives `type`, `codeName`, `label`, `fields`, `build(fields)` and
 * `codeArguments(json, code)`, and may say `grouped` (the inspector shows its
 * shadow rays as one group), `roundTrips` (built again from its JSON, the
 * same to the bit) and `workOf(json)` (its shadow rays from a hit point, read
 * from its JSON before any check, and the field that says so; one without it casts one).
 */
import { PointLight } from './point-light.js';
import { SpotLight } from './spot-light.js';
import { AreaLight } from './area-light.js';
import { show } from '../text/check.js';

/**
 * Every light class, in the order the lesson meets them. A new light is one more entry here.
 * @type {(Function & { type: string, codeName: string, label: string, fields: string[], workOf?: (json: any) => { shadowRays: number, field: string } } & Record<string, any>)[]}
 */
const LIGHTS = [PointLight, AreaLight, SpotLight];

/** What a light class must have. */
const STATICS = ['type', 'codeName', 'label'];

/**
 * Adds a light class to the list (a sketch's or a test's own light): Scene.add
 * takes it, and scene JSON reads it by its `type`. Returns the class.
 * @param {any} Light a class with static type, codeName, label, fields, build and codeArguments, and sources() and toJSON()
 */
export function registerLight(Light) {
  const ok = typeof Light === 'function' && STATICS.every((k) => typeof Light[k] === 'string') && Array.isArray(Light.fields)
    && typeof Light.build === 'function' && typeof Light.codeArguments === 'function'
    && typeof Light.prototype.sources === 'function' && typeof Light.prototype.toJSON === 'function';
  if (!ok) throw new TypeError(`registerLight takes a light class with static type, codeName, label, fields, build and codeArguments, and sources() and toJSON(), got ${show(Light)}`);
  const taken = lightClass(Light.type);
  if (taken === Light) return Light;
  if (taken) throw new TypeError(`the light type ${show(Light.type)} is taken`);
  LIGHTS.push(Light);
  return Light;
}

/** The light classes, in order (read only). */
export function lightClasses() {
  return LIGHTS;
}

/** The light class of a scene JSON `type` ('pointLight'), or undefined. */
export function lightClass(type) {
  return LIGHTS.find((Light) => Light.type === type);
}

/** The listed class a light is made by, or undefined when `item` is no listed light. */
export function lightClassOf(item) {
  return item !== null && typeof item === 'object' ? LIGHTS.find((Light) => item instanceof Light) : undefined;
}

/** True when `item` is a light of a listed class. */
export function isLight(item) {
  return lightClassOf(item) !== undefined;
}

/** The distinct lights behind a scene's light sources (`scene.lights`), in order of their first source; emissive shapes are not among them. */
export function lightsOf(scene) {
  return [...new Set(scene.lights.map((l) => l.source))].filter(isLight);
}

/**
 * The shadow rays a light's JSON makes from each hit point, and the field that says so
 * ('' for the light itself); null when `type` is no listed light.
 * @param {any} o the light's JSON (not checked yet)
 * @returns {?{ shadowRays: number, field: string }}
 */
export function lightWork(o) {
  const Light = lightClass(o.type);
  if (!Light) return null;
  return typeof Light.workOf === 'function' ? Light.workOf(o) : { shadowRays: 1, field: '' };
}

export { PointLight, SpotLight, AreaLight };
