/**
 * What a tracer view tells its listeners: `on(name, fn)` adds a listener and
 * returns the function that removes it; `emit(name, …args)` calls them all.
 * The names are fixed, so a typo ('selected') throws instead of never firing.
 */
import { show } from '../../text/check.js';

/**
 * @param {readonly string[]} names the events there are
 */
export function createEvents(names) {
  /** @type {Map<string, Function[]>} */
  const listeners = new Map(names.map((name) => [name, []]));
  return {
    /**
     * @param {string} name one of `names`
     * @param {Function} fn
     * @returns {() => void} removes the listener
     */
    on(name, fn) {
      if (!listeners.has(name)) throw new RangeError(`on() takes one of ${names.map((n) => `'${n}'`).join(', ')}, got ${show(name)}`);
      if (typeof fn !== 'function') throw new TypeError(`on('${name}', fn) needs a function, got ${show(fn)}`);
      listeners.get(name).push(fn);
      return () => { listeners.set(name, listeners.get(name).filter((l) => l !== fn)); };
    },
    /** @param {string} name @param {...unknown} args */
    emit(name, ...args) {
      for (const fn of listeners.get(name)) fn(...args);
    },
    /** True when `name` has a listener (to skip building what no one reads). */
    heard(name) {
      return listeners.get(name).length > 0;
    },
  };
}
