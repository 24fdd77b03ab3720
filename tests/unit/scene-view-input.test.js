// The 3D view by pointer (lib/p5/scene-view/input.js): the orbit's maths, and
// what a press, a drag, a click, the wheel and h / v do to the view.
import { describe, it, expect } from 'vitest';
import { Vec3 } from '../../lib/math/vec3.js';
import { Camera } from '../../lib/math/camera.js';
import { orbitCamera, pixelCenter, projectToScreen } from '../../lib/lesson/rays3d.js';
import { dragOrbit, isDrag, zoomDistance, wheelFactor, clampPitch, fanKey, checkOrbit, listenForInput, pixelUnder, CLICK_SLOP } from '../../lib/p5/scene-view/input.js';

describe('the orbit maths', () => {
  it('a drag turns 0.4° per px: to the right turns the view left, down looks from higher', () => {
    expect(dragOrbit({ yaw: 10, pitch: 5 }, 60, 20)).toEqual({ yaw: 10 - 24, pitch: 5 + 8 });
    expect(dragOrbit({ yaw: 10, pitch: 5 }, -10, -10)).toEqual({ yaw: 14, pitch: 1 });
  });

  it('a press becomes a drag once it has moved CLICK_SLOP px', () => {
    expect(CLICK_SLOP).toBe(4);
    expect(isDrag(3, 0)).toBe(false);
    expect(isDrag(2, 3)).toBe(false);
    expect(isDrag(4, 0)).toBe(true);
    expect(isDrag(3, -3)).toBe(true);
  });

  it('zooms from 0.3 to 8 times the scene\'s radius, no nearer and no further', () => {
    expect(zoomDistance(20, 0.5, 10)).toBe(10);
    expect(zoomDistance(20, 0.1, 10)).toBe(3);
    expect(zoomDistance(20, 10, 10)).toBe(80);
  });

  it('the wheel zooms out scrolling down, in scrolling up, as far back each way', () => {
    expect(wheelFactor(0)).toBe(1);
    expect(wheelFactor(200)).toBeGreaterThan(1);
    expect(wheelFactor(-200)).toBeLessThan(1);
    expect(wheelFactor(200) * wheelFactor(-200)).toBeCloseTo(1, 12);
  });

  it('never looks from straight above or below (the orbit would turn over)', () => {
    expect(clampPitch(120)).toBe(89);
    expect(clampPitch(-95)).toBe(-89);
    expect(clampPitch(30)).toBe(30);
  });

  it('h shows the row, v the column (either case); other keys and Ctrl / Alt / Meta nothing', () => {
    expect(fanKey({ key: 'h' })).toBe('row');
    expect(fanKey({ key: 'V' })).toBe('column');
    expect(fanKey({ key: 'x' })).toBeNull();
    expect(fanKey({ key: 'h', ctrlKey: true })).toBeNull();
    expect(fanKey({ key: 'v', metaKey: true })).toBeNull();
  });

  it('checks an orbit\'s parts, naming the bad one', () => {
    expect(checkOrbit({ yaw: 30 })).toEqual({ yaw: 30 });
    expect(checkOrbit({})).toEqual({});
    expect(() => checkOrbit({ distance: 0 })).toThrow(new RangeError('orbit.distance must be a distance greater than 0, got 0'));
    expect(() => checkOrbit({ pitch: NaN })).toThrow(/^orbit\.pitch must be a number of degrees/);
    expect(() => checkOrbit({ yew: 30 })).toThrow(/unknown orbit option "yew" \(did you mean "yaw"\?\)/);
  });
});

describe('pixelUnder', () => {
  const camera = new Camera({ width: 32, height: 24 }), W = 480, H = 360, FOVY = Math.PI / 3, D = 6;
  const eye = orbitCamera({ target: new Vec3(0, 0, -8), yaw: -35, pitch: 20, distance: 14 });
  const view = { eye, camera, planeDistance: D, width: W, height: H, fovy: FOVY };

  it('finds the pixel whose centre is drawn at that point, on a canvas shown at any size and place', () => {
    for (const [x, y] of [[3, 4], [20, 15], [31, 0], [0, 23]]) {
      const at = projectToScreen(eye, pixelCenter(camera, x, y, D), W, H, FOVY);
      expect(pixelUnder({ left: 0, top: 0, width: W, height: H }, at.x, at.y, view)).toMatchObject({ x, y });
      // the same canvas shown at half size, 100 px down the page
      expect(pixelUnder({ left: 10, top: 100, width: W / 2, height: H / 2 }, 10 + at.x / 2, 100 + at.y / 2, view)).toMatchObject({ x, y });
    }
  });

  it('is null off the image plane', () => {
    expect(pixelUnder({ left: 0, top: 0, width: W, height: H }, 2, 2, view)).toBeNull();
  });
});

/** An event of `type` with the given fields (Node has Event, not PointerEvent). */
const event = (type, fields = {}) => Object.assign(new Event(type, { cancelable: true }), fields);

/** A canvas, a figure and a tracer canvas as event targets, and a view that records what it is asked. */
function setup() {
  const canvas = Object.assign(new EventTarget(), { style: {}, setPointerCapture() {} });
  const figure = new EventTarget(), tracerCanvas = new EventTarget();
  const calls = [], picks = [];
  const view = {
    orbit: { yaw: -35, pitch: 20, distance: 12 }, fan: null, shooting: false,
    setOrbit(o) { calls.push(['setOrbit', o]); Object.assign(this.orbit, o); },
    showFan(kind) { calls.push(['showFan', kind]); this.fan = kind; },
    turn(yaw, pitch) { calls.push(['turn', yaw, pitch]); },
    zoom(f) { calls.push(['zoom', f]); },
    stop() { calls.push(['stop']); },
  };
  listenForInput(/** @type {any} */ (canvas), { figure: /** @type {any} */ (figure), tracerCanvas: /** @type {any} */ (tracerCanvas), view, radius: () => 10, pick: (x, y) => picks.push([x, y]) });
  return { canvas, tracerCanvas, view, calls, picks };
}

describe('listenForInput', () => {
  it('a press and release that hardly moved is a click: it picks where it was, and turns nothing', () => {
    const { canvas, calls, picks } = setup();
    canvas.dispatchEvent(event('pointerdown', { button: 0, clientX: 100, clientY: 50 }));
    canvas.dispatchEvent(event('pointermove', { buttons: 1, clientX: 102, clientY: 51 }));
    canvas.dispatchEvent(event('pointerup', { clientX: 102, clientY: 51 }));
    expect(picks).toEqual([[102, 51]]);
    expect(calls).toEqual([]);
  });

  it('a drag turns the view from where the press began, and its release picks nothing', () => {
    const { canvas, calls, picks } = setup();
    canvas.dispatchEvent(event('pointerdown', { button: 0, clientX: 100, clientY: 50 }));
    expect(canvas.style.cursor).toBe('grabbing');
    canvas.dispatchEvent(event('pointermove', { buttons: 1, clientX: 130, clientY: 60 }));
    canvas.dispatchEvent(event('pointermove', { buttons: 1, clientX: 160, clientY: 70 }));
    canvas.dispatchEvent(event('pointerup', { clientX: 160, clientY: 70 }));
    expect(calls).toEqual([['setOrbit', { yaw: -35 - 12, pitch: 20 + 4 }], ['setOrbit', { yaw: -35 - 24, pitch: 20 + 8 }]]);
    expect(picks).toEqual([]);
    expect(canvas.style.cursor).toBe('grab');
  });

  it('another button does not turn or pick; a cancelled press picks nothing', () => {
    const { canvas, calls, picks } = setup();
    canvas.dispatchEvent(event('pointerdown', { button: 2, clientX: 100, clientY: 50 }));
    canvas.dispatchEvent(event('pointermove', { buttons: 2, clientX: 160, clientY: 50 }));
    canvas.dispatchEvent(event('pointerdown', { button: 0, clientX: 100, clientY: 50 }));
    canvas.dispatchEvent(event('pointercancel', {}));
    expect(calls).toEqual([]);
    expect(picks).toEqual([]);
  });

  it('the wheel zooms within the scene\'s limits, and keeps the page from scrolling', () => {
    const { canvas, calls } = setup();
    const wheel = event('wheel', { deltaY: 200 });
    canvas.dispatchEvent(wheel);
    expect(wheel.defaultPrevented).toBe(true);
    expect(calls[0][1].distance).toBeCloseTo(12 * Math.exp(0.3), 12);
    canvas.dispatchEvent(event('wheel', { deltaY: -100_000 }));
    expect(calls[1][1].distance).toBe(3); // 0.3 × the radius
  });

  it('h on either canvas shows the row; h again hides it; v shows the column', () => {
    const { canvas, tracerCanvas, calls } = setup();
    tracerCanvas.dispatchEvent(event('keydown', { key: 'h' }));
    canvas.dispatchEvent(event('keydown', { key: 'h' }));
    canvas.dispatchEvent(event('keydown', { key: 'v' }));
    expect(calls).toEqual([['showFan', 'row'], ['showFan', null], ['showFan', 'column']]);
  });

  it('the arrow keys on the 3D canvas turn it (scene-view-keys.js)', () => {
    const { canvas, calls } = setup();
    const key = event('keydown', { key: 'ArrowLeft' });
    canvas.dispatchEvent(key);
    expect(calls).toEqual([['turn', 10, 0]]);
    expect(key.defaultPrevented).toBe(true);
  });
});
