/**
 * Argument checks shared by every constructor: each throws a TypeError or
 * RangeError whose message names the field, so a student sees what to fix.
 */

/** A finite number, else a TypeError naming `field`. */
export function finiteNumber(value, field) {
  if (typeof value !== 'number' || !Number.isFinite(value)) {
    throw new TypeError(`${field} must be a finite number, got ${show(value)}`);
  }
  return value;
}

/** A finite number in [min, max], else a Type/RangeError naming `field`. */
export function numberInRange(value, field, min, max) {
  finiteNumber(value, field);
  if (value < min || value > max) {
    throw new RangeError(`${field} must be between ${min} and ${max}, got ${value}`);
  }
  return value;
}

/** A positive integer (width, height, …). */
export function positiveInteger(value, field) {
  finiteNumber(value, field);
  if (!Number.isInteger(value) || value <= 0) {
    throw new RangeError(`${field} must be a positive whole number, got ${value}`);
  }
  return value;
}

/** A boolean. */
export function bool(value, field) {
  if (typeof value !== 'boolean') throw new TypeError(`${field} must be true or false, got ${show(value)}`);
  return value;
}

/** The longest `show` text: a message echoes a bad value, never a whole megabyte of it. */
export const SHOW_MAX = 80;

/**
 * Short printable form of a bad value for error messages: at most SHOW_MAX
 * characters (cut with "…"), however long or deeply nested the value; never throws.
 */
export function show(value) {
  let text;
  try {
    text = showWithin(value, 4);
  } catch {
    text = Object.prototype.toString.call(value); // a proxy, an object without a prototype, …
  }
  return text.length > SHOW_MAX ? `${text.slice(0, SHOW_MAX - 1)}…` : text;
}

/** `show` down to `depth` levels, each list cut once it has said enough. */
function showWithin(value, depth) {
  if (typeof value === 'string') return JSON.stringify(value.length > SHOW_MAX ? value.slice(0, SHOW_MAX) : value);
  if (typeof value === 'function') return `function ${value.name || '(anonymous)'}`;
  if (value === null || typeof value !== 'object') return String(value);
  if (depth === 0) return Array.isArray(value) ? '[…]' : '{…}';
  const parts = [];
  let length = 0;
  const entries = Array.isArray(value) ? value : Object.keys(value);
  for (let i = 0; i < entries.length; i++) {
    if (length > SHOW_MAX) { parts.push('…'); break; }
    const part = Array.isArray(value) ? showWithin(value[i], depth - 1)
      : `${JSON.stringify(entries[i].slice(0, SHOW_MAX))}:${showWithin(value[entries[i]], depth - 1)}`;
    parts.push(part);
    length += part.length + 2;
  }
  return Array.isArray(value) ? `[${parts.join(', ')}]` : `{${parts.join(',')}}`;
}

/** Runs `make`; a TypeError or RangeError it throws gets the field's path in front ("objects[2]." + "radius must…"). */
export function withPath(make, prefix) {
  try {
    return make();
  } catch (error) {
    if (error instanceof TypeError) throw new TypeError(prefix + error.message, { cause: error });
    if (error instanceof RangeError) throw new RangeError(prefix + error.message, { cause: error });
    throw error;
  }
}

/** A whole number in [0, limit) — a pixel coordinate. */
export function pixelCoordinate(value, field, limit) {
  finiteNumber(value, field);
  if (!Number.isInteger(value) || value < 0 || value >= limit) {
    throw new RangeError(`${field} must be a whole number from 0 to ${limit - 1}, got ${value}`);
  }
  return value;
}

/**
 * An options object whose every key is one of `known`; a misspelt key would
 * silently fall back to its default, so it throws a TypeError naming the key,
 * `where` it was given and the closest known key:
 * `unknown material option "colour" (did you mean "color"?)`.
 * Undefined is fine (every option takes its default).
 * @param {object|undefined} options
 * @param {readonly string[]} known the keys this options object takes
 * @param {string} where what the options are for, as a student would say it ("material", "camera")
 * @returns {any} the options' own keys in an object with no prototype (empty when
 *   undefined): read options from it, so a key set on Object.prototype anywhere is no option here
 */
export function checkOptions(options, known, where) {
  const own = Object.create(null);
  if (options === undefined) return own;
  if (options === null || typeof options !== 'object' || Array.isArray(options)) {
    throw new TypeError(`${where} options must be an object like { ${known[0]}: … }, got ${show(options)}`);
  }
  for (const key of Object.keys(options)) {
    if (!known.includes(key)) throw new TypeError(unknownOption(key, known, where));
    own[key] = options[key];
  }
  return own;
}

/** The longest option key (or name) worth comparing with the known ones: known keys are short, and the distance takes length² time. */
export const OPTION_KEY_MAX = 40;

/** The message for an unknown key: the closest known key, and the whole list when none is close. */
function unknownOption(key, known, where) {
  const message = `unknown ${where} option ${show(key)}`;
  if (key.length > OPTION_KEY_MAX) return known.length ? `${message} (known options: ${known.join(', ')})` : `${message} (it takes no options)`;
  const best = closestName(key, known, Infinity);
  if (best === null) return `${message} (it takes no options)`;
  return closestName(key, known, Math.max(2, Math.floor(key.length / 2))) === best
    ? `${message} (did you mean ${JSON.stringify(best)}?)`
    : `${message} (did you mean ${JSON.stringify(best)}? known options: ${known.join(', ')})`;
}

/**
 * The name of `names` closest to `name` by editDistance, case aside, or null
 * when even that one is more than `most` edits away: "did you mean …?" for a
 * misspelt option, colour, import or p5 function alike. A tie goes to the
 * name that keeps more of the letters written ('gren' → 'green', not 'grey'),
 * then to the one closer with case, then to the first. By default a short
 * name may be one edit off, a longer one two or three ("createTracerVeiw" → "createTracerView").
 * @param {string} name what was written
 * @param {Iterable<string>} names what could have been meant
 * @param {number} [most] the most edits allowed
 * @returns {string|null}
 */
export function closestName(name, names, most = name.length <= 4 ? 1 : name.length <= 8 ? 2 : 3) {
  if (name.length > OPTION_KEY_MAX) return null; // names worth suggesting are short; the distance takes length² time
  let best = null, bestScore = null;
  const lower = name.toLowerCase();
  for (const candidate of names) {
    const d = editDistance(lower, candidate.toLowerCase());
    if (d > most || (bestScore && d > bestScore[0])) continue;
    const score = [d, editDistance(lower, candidate.toLowerCase(), 2), editDistance(name, candidate)];
    if (!bestScore || lessThan(score, bestScore)) { best = candidate; bestScore = score; }
  }
  return best;
}

/** Is score a before score b, comparing their numbers in turn? */
function lessThan(a, b) {
  const i = a.findIndex((x, k) => x !== b[k]);
  return i >= 0 && a[i] < b[i];
}

/**
 * Edits (insert, delete, replace, swap two neighbours) turning a into b:
 * the optimal string alignment distance, so "widht" is one edit from "width".
 * `replaceCost` 2 counts a replaced letter as a delete and an insert (closestName's tie-break).
 */
export function editDistance(a, b, replaceCost = 1) {
  const rows = [];
  for (let i = 0; i <= a.length; i++) {
    rows.push([i]);
    for (let j = 1; j <= b.length; j++) {
      if (i === 0) { rows[0].push(j); continue; }
      const cost = a[i - 1] === b[j - 1] ? 0 : replaceCost;
      let d = Math.min(rows[i - 1][j] + 1, rows[i][j - 1] + 1, rows[i - 1][j - 1] + cost);
      if (i > 1 && j > 1 && a[i - 1] === b[j - 2] && a[i - 2] === b[j - 1]) d = Math.min(d, rows[i - 2][j - 2] + 1);
      rows[i].push(d);
    }
  }
  return rows[a.length][b.length];
}
