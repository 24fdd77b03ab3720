/**
 * How deep JSON text nests, read before JSON.parse: a 9 kB link of 3.5 million
 * nested arrays made JSON.parse build every one of them (2.9 s) before the
 * depth check could refuse it. One pass over the text, in time proportional
 * to it; strings are passed over (a bracket in a name is no bracket).
 */

/**
 * Where `text` first nests deeper than `max` containers below its top one,
 * as a path like 'objects[0].material.color[0]…' (keys cut to 40
 * characters, as written in the text), or null when it never does.
 * Text that is not JSON is left for JSON.parse to say so.
 * @param {string} text
 * @param {number} max
 * @returns {string|null}
 */
export function tooDeepAt(text, max) {
  const places = []; // per open container, where its current child is: an index (an array) or a key (an object; null before it)
  for (let i = 0; i < text.length; i++) {
    const c = text.charCodeAt(i);
    const top = places.length - 1;
    if (c === QUOTE) {
      const start = i + 1;
      for (i++; i < text.length && text.charCodeAt(i) !== QUOTE; i++) if (text.charCodeAt(i) === BACKSLASH) i++;
      if (places[top] === null) places[top] = text.slice(start, Math.min(i, start + 40)); // a key
    } else if (c === OPEN_ARRAY || c === OPEN_OBJECT) {
      if (places.length >= max) return pathOf(places);
      places.push(c === OPEN_ARRAY ? 0 : null);
    } else if (c === CLOSE_ARRAY || c === CLOSE_OBJECT) {
      places.pop();
    } else if (c === COMMA && top >= 0) {
      places[top] = typeof places[top] === 'number' ? places[top] + 1 : null; // the next element, or a key to come
    }
  }
  return null;
}

const QUOTE = 34, BACKSLASH = 92, COMMA = 44, OPEN_ARRAY = 91, CLOSE_ARRAY = 93, OPEN_OBJECT = 123, CLOSE_OBJECT = 125;

/** 'objects[0].material.color[0]…' from the open containers' places. */
function pathOf(places) {
  const path = places.map((p) => (typeof p === 'number' ? `[${p}]` : `.${p}`)).join('').replace(/^\./, '');
  return path.length > 120 ? `${path.slice(0, 119)}…` : path;
}
