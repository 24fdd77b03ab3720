/**
 * A scene in a page's link, to share it: compact, in the fragment, and read
 * in time that does not grow faster than the link.
 *
 *   #scene=z.<base64url of the deflate-raw compressed compact JSON>
 *
 * The fragment (`#…`) never reaches a server, so no "431 Request Header Fields
 * Too Large" however big the scene; compression makes a link 3–5 times shorter
 * than the base64url JSON of `?scene=…`, which is still read (old links keep
 * working). A link longer than a browser opens is refused with a message, a
 * link a chat might cut gets a warning (`linkNotice`). Decompression stops at
 * MAX_SCENE_BYTES: a small link cannot unpack into gigabytes.
 *
 *   const scene = await readSceneLink(location.href);         // null when the link has none
 *   history.replaceState(null, '', await sceneLinkURL(location.href, json));
 */
import { compactSceneBytes, decodeScene, sceneFromBytes, isBase64url, toBase64url, fromBase64url, pipeBytes } from '../../scene/codec.js';

/** Links longer than this may be cut by chats and e-mail. */
export const LINK_WARN_LENGTH = 8_000;
/** Chromium opens no longer URL (2 MB); other browsers' limits are larger. */
export const LINK_MAX_LENGTH = 2 * 1024 * 1024;
/** A scene's JSON text may unpack to this many bytes, no more. */
export const MAX_SCENE_BYTES = 8 * 1024 * 1024;

const PREFIX = 'z.';

/** The scene's text in `href`: the fragment's `scene=` first, else the query's; null when neither. */
export function sceneTextInLink(href) {
  const url = new URL(href);
  const inFragment = new URLSearchParams(url.hash.slice(1)).get('scene');
  return inFragment ?? url.searchParams.get('scene');
}

/** Scene JSON as link text: `z.` + base64url of its compressed compact JSON. */
export async function encodeSceneLink(json) {
  return PREFIX + toBase64url(await pipeBytes(compactSceneBytes(json), new CompressionStream('deflate-raw')));
}

/**
 * The Scene in link text: `z.…` (compressed), or the older base64url JSON or
 * plain JSON text; a TypeError/RangeError saying what is wrong otherwise.
 */
export async function decodeSceneLink(text) {
  const t = String(text ?? '').trim();
  if (!t.startsWith(PREFIX)) return decodeScene(t);
  const body = t.slice(PREFIX.length);
  if (!isBase64url(body)) throw new TypeError('the scene in the link is not base64url text');
  let bytes;
  try {
    bytes = await pipeBytes(fromBase64url(body), new DecompressionStream('deflate-raw'), MAX_SCENE_BYTES, 'the scene');
  } catch (error) {
    if (error instanceof RangeError) throw error;
    throw new TypeError('the scene in the link is cut short or damaged', { cause: error });
  }
  return sceneFromBytes(bytes);
}

/** The Scene in a page's link, null when it has none; throws (see decodeSceneLink) when it cannot be read. */
export async function readSceneLink(href) {
  const text = sceneTextInLink(href);
  return text === null ? null : decodeSceneLink(text);
}

/** `href` sharing the scene `json`: in the fragment, and the query's old `scene=` gone. */
export async function sceneLinkURL(href, json) {
  const url = new URL(href);
  url.searchParams.delete('scene');
  url.hash = `scene=${await encodeSceneLink(json)}`;
  return url.href;
}

/**
 * What to say about a link of `length` characters: `{ open: false }` when no
 * browser would open it, a `warning` when a chat might cut it.
 */
export function linkNotice(length) {
  const n = length.toLocaleString('en');
  if (length > LINK_MAX_LENGTH) {
    return { open: false, message: `This link is ${n} characters long, more than a browser opens: copy the scene as code instead.` };
  }
  if (length > LINK_WARN_LENGTH) {
    return { open: true, message: `Link copied, but it is ${n} characters long: a chat or an e-mail may cut it. If it does not open, copy the scene as code.` };
  }
  return { open: true, message: 'Link copied: paste it into the chat.' };
}

/* ---------------- bytes ---------------- */
