/**
 * A sketch's code in a page's link, to share it: in the fragment (a server
 * never sees it, so no length limit of the server's), compressed as sketch
 * 05's scene links are (lib/p5/page/scene-link.js):
 *
 *   #code=z.<base64url of the deflate-raw compressed UTF-8 text>
 *
 * Reading stops at MAX_CODE_BYTES: a small link cannot unpack into gigabytes.
 * Code read from a link is only text for the editor: it runs when the
 * student presses Run, and then in the sandboxed frame.
 */
import { isBase64url, toBase64url, fromBase64url, pipeBytes } from '../lib/scene/codec.js';

/** A sketch's code may unpack to this many bytes, no more. */
export const MAX_CODE_BYTES = 512 * 1024;
/** Links longer than this may be cut by chats and e-mail. */
export const CODE_LINK_WARN_LENGTH = 8_000;

const PREFIX = 'z.';

/** The code's text in `href`'s fragment (`#code=…`), or null when it has none. */
export function codeTextInLink(href) {
  return new URLSearchParams(new URL(href).hash.slice(1)).get('code');
}

/** Code as link text: `z.` + base64url of its compressed UTF-8 bytes. */
export async function encodeCodeLink(code) {
  return PREFIX + toBase64url(await pipeBytes(new TextEncoder().encode(code), new CompressionStream('deflate-raw')));
}

/** The code in link text; a TypeError or RangeError saying what is wrong otherwise. */
export async function decodeCodeLink(text) {
  const t = String(text ?? '').trim();
  if (!t.startsWith(PREFIX) || !isBase64url(t.slice(PREFIX.length))) throw new TypeError('the code in the link is not z. and base64url text');
  let bytes;
  try {
    bytes = await pipeBytes(fromBase64url(t.slice(PREFIX.length)), new DecompressionStream('deflate-raw'), MAX_CODE_BYTES, 'the code');
  } catch (error) {
    if (error instanceof RangeError) throw error;
    throw new TypeError('the code in the link is cut short or damaged', { cause: error });
  }
  try {
    return new TextDecoder('utf-8', { fatal: true }).decode(bytes);
  } catch (error) {
    throw new TypeError('the code in the link is not UTF-8 text', { cause: error });
  }
}

/** `href` sharing `code`: in the fragment, the rest of the address kept. */
export async function codeLinkURL(href, code) {
  const url = new URL(href);
  url.hash = `code=${await encodeCodeLink(code)}`;
  return url.href;
}
