// The p5 addon: every factory becomes a p5 method taking one options object.
import { describe, it, expect, vi } from 'vitest';

// The 3D view makes a p5 instance of its own: in Node, p5 is a stand-in.
vi.mock('p5', () => ({ default: class {} }));
const { sketchbookAddon, FACTORIES } = await import('../../lib/p5/addon.js');

function register() {
  const p5Class = class {};
  const lifecycles = {};
  sketchbookAddon(p5Class, p5Class.prototype, lifecycles);
  return { p5Class, fn: p5Class.prototype, lifecycles };
}

describe('sketchbookAddon', () => {
  it('adds every factory to p5 as a method', () => {
    const { fn } = register();
    for (const name of Object.keys(FACTORIES)) expect(typeof fn[name], name).toBe('function');
    expect(Object.keys(FACTORIES)).toEqual(expect.arrayContaining(['createTracerView', 'createInspector', 'drawParabola']));
  });

  it('turns off the sketch checker, which would parse a whole bundle before setup()', () => {
    expect(register().p5Class.disableSketchChecker).toBe(true);
  });

  it('refuses anything but one options object, naming the method', () => {
    const { fn } = register();
    const sketch = Object.create(fn);
    expect(() => sketch.createTracerView(64, 48)).toThrow(/createTracerView takes one options object.*got 64/);
    expect(() => sketch.createInspector(null)).toThrow(TypeError);
    expect(() => sketch.drawParabola([1, 2])).toThrow(/drawParabola takes one options object/);
  });

  it('createBvhView names what is wrong: a view that is not a tracer view, a mesh that is not a Mesh, an option it does not know', () => {
    const { fn } = register();
    const sketch = Object.create(fn), view = { onSelect: () => () => {} };
    expect(() => sketch.createBvhView({ mesh: {} })).toThrow(/view must be a tracer view/);
    expect(() => sketch.createBvhView({ view, mesh: { bvh: {} } })).toThrow(/mesh must be a Mesh/);
    expect(() => sketch.createBvhView({ view, mesh: null, dept: 2 })).toThrow(/dept.*depth/);
  });

  it('passes the sketch and the options to the factory, and p.remove() destroys what it made', () => {
    const made = [];
    const saved = FACTORIES.createSwitches;
    FACTORIES.createSwitches = (p, options) => {
      const part = { p, options, destroyed: false, destroy() { this.destroyed = true; } };
      made.push(part);
      return part;
    };
    try {
      const { fn, lifecycles } = register();
      const sketch = Object.create(fn);
      const part = sketch.createSwitches({ legend: 'One switch per idea' });
      expect(part.p).toBe(sketch);
      expect(part.options).toEqual({ legend: 'One switch per idea' });
      lifecycles.remove.call(sketch);
      expect(made[0].destroyed).toBe(true);
    } finally {
      FACTORIES.createSwitches = saved;
    }
  });
});

describe('every factory refuses an options key it does not know, naming it and the closest known one', () => {
  // The check comes first, before any page or sketch is touched: a stand-in sketch is enough.
  const CASES = [
    ['createTracerView', { gird: true }, 'unknown createTracerView option "gird" (did you mean "grid"?)'],
    ['createTracerView', { scale: 4, lable: 'x' }, 'unknown createTracerView option "lable" (did you mean "label"?)'],
    ['createInspector', { veiw: {} }, 'unknown createInspector option "veiw" (did you mean "view"?)'],
    ['createAnswerForm', { onCheck: () => {}, box: [] }, 'unknown createAnswerForm option "box" (did you mean "boxes"?)'],
    ['createPixelMarks', { names: 'x' }, 'unknown createPixelMarks option "names" (did you mean "name"?)'],
    ['createPixelHighlight', { tests: () => true }, 'unknown createPixelHighlight option "tests" (did you mean "test"?)'],
    ['createSliderField', { maximum: 3 }, 'unknown createSliderField option "maximum" (did you mean "max"?'],
    ['createSwitches', { legnd: 'x' }, 'unknown createSwitches option "legnd" (did you mean "legend"?)'],
    ['createExamplePicker', { onChose: () => {} }, 'unknown createExamplePicker option "onChose" (did you mean "onChoose"?)'],
    ['createAnimation', { worker: 2 }, 'unknown createAnimation option "worker" (did you mean "workers"?)'],
    ['createSceneForm', { onchange: () => {} }, 'unknown createSceneForm option "onchange" (did you mean "onChange"?)'],
    ['createHomeworkCheck', { checks: () => [] }, 'unknown createHomeworkCheck option "checks" (did you mean "check"?)'],
  ];
  it.each(CASES)('%s(%o)', (name, options, message) => {
    const sketch = Object.create(register().fn);
    expect(() => sketch[name](options)).toThrow(TypeError);
    expect(() => sketch[name](options)).toThrow(message);
  });
});
