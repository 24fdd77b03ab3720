/**
 * One way to register an addon with p5 2.x and with p5 1.x (1.11 is still
 * the default of many classes and of OpenProcessing). On 2.x it is
 * `p5.registerAddon(addon)`; on 1.x, which has none, the addon gets
 * `p5.prototype` as its `fn` and its lifecycle hooks go to 1.x's
 * `registerMethod` under their 1.x names.
 *
 *   registerAddon((p5Class, fn, lifecycles) => { fn.myThing = …; lifecycles.remove = …; });
 */
import p5 from 'p5';

/** p5 2.x lifecycle hooks and their p5 1.x names (registerMethod). */
export const HOOKS_IN_P5_ONE = { presetup: 'beforeSetup', postsetup: 'afterSetup', predraw: 'pre', postdraw: 'post', remove: 'remove' };

/**
 * The p5 this page has: 2 (registerAddon), 1 (registerMethod) or 0 (none, or too old).
 * @param {any} [p5Class] p5 itself (tests pass a stand-in)
 */
export function p5Generation(p5Class = p5) {
  if (typeof p5Class?.registerAddon === 'function') return 2;
  return typeof p5Class?.prototype?.registerMethod === 'function' ? 1 : 0;
}

/**
 * Registers `addon(p5Class, fn, lifecycles)` with the page's p5, 2.x or 1.x.
 * @param {(p5Class: any, fn: object, lifecycles: Record<string, Function>) => void} addon
 * @param {any} [p5Class] p5 itself (tests pass a stand-in)
 */
export function registerAddon(addon, p5Class = p5) {
  if (p5Generation(p5Class) === 2) return p5Class.registerAddon(addon);
  const lifecycles = /** @type {Record<string, Function>} */ ({});
  addon(p5Class, p5Class.prototype, lifecycles);
  for (const [hook, run] of Object.entries(lifecycles)) {
    const name = HOOKS_IN_P5_ONE[hook];
    if (!name) throw new Error(`p5 1.x has no lifecycle hook like "${hook}": use ${Object.keys(HOOKS_IN_P5_ONE).join(', ')}`);
    p5Class.prototype.registerMethod(name, run);
  }
}

