// One addon, two p5s: registerAddon on p5 2.x, p5.prototype and registerMethod on p5 1.x.
import { describe, it, expect, vi } from 'vitest';

vi.mock('p5', () => ({ default: class {} }));
const { registerAddon, p5Generation, HOOKS_IN_P5_ONE } = await import('../../lib/p5/register.js');

/** p5 1.11 as far as an addon sees it: a prototype and registerMethod's table. */
function p5One() {
  class P5 {}
  P5.VERSION = '1.11.13';
  P5.prototype._registeredMethods = {};
  P5.prototype.registerMethod = function (name, method) { (this._registeredMethods[name] ??= []).push(method); };
  return P5;
}

describe('registerAddon', () => {
  it('on p5 2.x hands the addon to p5.registerAddon', () => {
    const addon = () => {};
    const P5 = class {};
    P5.registerAddon = vi.fn();
    expect(p5Generation(P5)).toBe(2);
    registerAddon(addon, P5);
    expect(P5.registerAddon).toHaveBeenCalledWith(addon);
  });

  it('on p5 1.x puts the methods on p5.prototype and the hooks under their 1.x names', () => {
    const P5 = p5One();
    const remove = () => {}, postsetup = () => {};
    registerAddon((p5Class, fn, lifecycles) => {
      expect(p5Class).toBe(P5);
      fn.createThing = () => 'made';
      lifecycles.remove = remove;
      lifecycles.postsetup = postsetup;
    }, P5);
    expect(p5Generation(P5)).toBe(1);
    expect(new P5().createThing()).toBe('made');
    expect(P5.prototype._registeredMethods).toEqual({ remove: [remove], afterSetup: [postsetup] });
    expect(HOOKS_IN_P5_ONE).toEqual({ presetup: 'beforeSetup', postsetup: 'afterSetup', predraw: 'pre', postdraw: 'post', remove: 'remove' });
  });

  it('the sketchbook addon on p5 1.x: every factory a method, p.remove() destroys what it made', async () => {
    const { sketchbookAddon, FACTORIES } = await import('../../lib/p5/addon.js');
    const saved = FACTORIES.createSwitches;
    const part = { destroyed: false, destroy() { this.destroyed = true; } };
    FACTORIES.createSwitches = () => part;
    try {
      const P5 = p5One();
      registerAddon(sketchbookAddon, P5);
      for (const name of Object.keys(FACTORIES)) expect(typeof P5.prototype[name], name).toBe('function');
      const sketch = new P5();
      sketch.createSwitches({});
      for (const hook of P5.prototype._registeredMethods.remove) hook.call(sketch);
      expect(part.destroyed).toBe(true);
    } finally {
      FACTORIES.createSwitches = saved;
    }
  });

  it('a hook p5 1.x does not have is refused by name', () => {
    expect(() => registerAddon((p5Class, fn, lifecycles) => { lifecycles.presteup = () => {}; }, p5One()))
      .toThrow('p5 1.x has no lifecycle hook like "presteup"');
  });
});
