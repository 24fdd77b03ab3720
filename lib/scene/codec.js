/**
 * A scene as short URL-safe text, to share it in a link: its JSON (see
 * json.js) without the fields that hold their default value, as UTF-8,
 * in base64url. Reading it back checks every field as sceneFromJSON does.
 *
 *   const text = encodeScene(sceneToJSON(scene));   // 'eyJvYmplY3RzIjpb…'
 *   const copy = decodeScene(text);                  // a Scene, or a TypeError/RangeError saying what is wrong
 *
 * lib/p5/page/scene-link.js puts the compressed form of the same bytes in a page's link.
 */
import { Scene } from './scene.js';
import { Sphere } from '../shapes/sphere.js';
import { sceneToJSON, sceneFromJSON } from './json.js';

/**
 * The most objects a scene from a link or a paste may have: at 10,000 every
 * action of sketch 05 stays quick; a 32 kB link could unpack into 174,762
 * spheres, which froze the page for seconds at each click.
 */
export const MAX_SCENE_OBJECTS = 10_000;

let defaults = null;

/** The library's own defaults, read from an empty scene and a plain sphere: nothing to keep in step. */
function defaultValues() {
  if (!defaults) {
    const probe = sceneToJSON(new Scene().add(new Sphere([0, 0, 0], 1)));
    const { objects, ...scene } = probe;
    defaults = { scene, material: objects[0].material };
  }
  return defaults;
}

/** Equal as JSON text would say (−0 is 0), without writing the text: 70,000 stringify calls at 10,000 spheres. */
const same = (a, b) => (Array.isArray(a) ? Array.isArray(b) && a.length === b.length && a.every((x, i) => same(x, b[i])) : a === b);

/** Scene JSON without the fields that hold their default value (shorter links); `sceneFromJSON` reads it back the same. */
export function compactSceneJSON(json) {
  const { scene, material } = defaultValues();
  const out = {};
  for (const [key, value] of Object.entries(json)) if (key === 'objects' || !same(value, scene[key])) out[key] = value;
  out.objects = (json.objects ?? []).map((o) => {
    const copy = { ...o };
    if (!copy.name) delete copy.name;
    if (copy.material) {
      copy.material = Object.fromEntries(Object.entries(copy.material).filter(([k, v]) => !same(v, material[k])));
    }
    return copy;
  });
  return out;
}

/** The UTF-8 bytes of the scene's compact JSON text. */
export function compactSceneBytes(json) {
  return new TextEncoder().encode(JSON.stringify(compactSceneJSON(json)));
}

/** Scene JSON as URL-safe text: base64url of its compact JSON. */
export function encodeScene(json) {
  return toBase64url(compactSceneBytes(json));
}

/**
 * The Scene in text made by encodeScene (or plain JSON text), checked by
 * sceneFromJSON, at most MAX_SCENE_OBJECTS objects; a TypeError/RangeError saying what is wrong otherwise.
 */
export function decodeScene(text) {
  const t = String(text ?? '').trim();
  if (t.startsWith('{')) return sceneFromJSON(t, { maxObjects: MAX_SCENE_OBJECTS, limitWork: true });
  if (!isBase64url(t)) throw new TypeError('the scene in the link is not base64url text');
  let bytes;
  try {
    bytes = fromBase64url(t);
  } catch {
    throw new TypeError('the scene in the link is cut short or not base64url text');
  }
  return sceneFromBytes(bytes);
}

/** The Scene in UTF-8 bytes of JSON text, checked by sceneFromJSON; a TypeError when the bytes are not text. */
export function sceneFromBytes(bytes) {
  let json;
  try {
    json = new TextDecoder('utf-8', { fatal: true }).decode(bytes);
  } catch {
    throw new TypeError('the scene in the link is not text');
  }
  return sceneFromJSON(json, { maxObjects: MAX_SCENE_OBJECTS, limitWork: true });
}

/* ---------------- base64url ---------------- */

/** True when `text` is made of base64url's letters only (no padding). */
export function isBase64url(text) {
  return /^[A-Za-z0-9_-]+$/.test(text);
}

/** Bytes as base64url text, without padding. */
export function toBase64url(bytes) {
  let binary = '';
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

/** The bytes in base64url text; throws (atob's DOMException) when it is not whole base64. */
export function fromBase64url(text) {
  const binary = atob(text.replace(/-/g, '+').replace(/_/g, '/'));
  return Uint8Array.from(binary, (c) => c.charCodeAt(0));
}

/**
 * `bytes` through a (de)compression stream (the links' deflate-raw); a RangeError
 * past `max` bytes out, saying `what` unpacks to more (a small link cannot unpack into gigabytes).
 * @param {BlobPart} bytes
 * @param {TransformStream} transform
 * @param {number} [max=Infinity]
 * @param {string} [what='the text'] what the link holds, for the message ('the scene')
 * @returns {Promise<Uint8Array>}
 */
export async function pipeBytes(bytes, transform, max = Infinity, what = 'the text') {
  const reader = new Blob([bytes]).stream().pipeThrough(transform).getReader();
  const chunks = [];
  let total = 0;
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    total += value.length;
    if (total > max) {
      await reader.cancel();
      throw new RangeError(`${what} in the link unpacks to more than ${max.toLocaleString('en')} bytes`);
    }
    chunks.push(value);
  }
  const out = new Uint8Array(total);
  let at = 0;
  for (const c of chunks) { out.set(c, at); at += c.length; }
  return out;
}
