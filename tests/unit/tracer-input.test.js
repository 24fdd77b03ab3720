// The tracer view's input: the pixel under a point of the screen, where an
// arrow key moves the selection, and the events that select (on a stand-in canvas).
import { describe, it, expect } from 'vitest';
import { pixelAt, arrowMove, listenForPixels } from '../../lib/p5/tracer/input.js';

/** A canvas standing in for the picture: shown at (left, top), w × h on screen; it keeps its listeners. */
function fakeCanvas(left, top, w, h) {
  const listeners = {};
  let captured = null;
  return {
    getBoundingClientRect: () => ({ left, top, width: w, height: h }),
    addEventListener: (type, fn) => { listeners[type] = fn; },
    setPointerCapture: (id) => { captured = id; },
    hasPointerCapture: (id) => captured === id,
    /** Sends an event to the listener; returns the event, `prevented` when its default was prevented. */
    fire: (type, fields) => {
      const event = { ...fields, prevented: false, preventDefault() { event.prevented = true; } };
      listeners[type](event);
      return event;
    },
  };
}

/** A view standing in for a TracerView: its size, its selection, and the calls to select. */
function fakeView(width, height) {
  const view = { width, height, selected: null, calls: [] };
  view.select = (x, y) => { view.calls.push([x, y]); view.selected = { x, y }; };
  return view;
}

describe('pixelAt', () => {
  it("gives the traced pixel under a point, whatever the canvas's on-screen scale", () => {
    const canvas = fakeCanvas(100, 50, 640, 480); // 64 × 48 shown ten times bigger
    expect(pixelAt(canvas, 100, 50, 64, 48)).toEqual({ x: 0, y: 0 });
    expect(pixelAt(canvas, 100 + 105, 50 + 129.9, 64, 48)).toEqual({ x: 10, y: 12 });
    expect(pixelAt(canvas, 100 + 639.9, 50 + 479.9, 64, 48)).toEqual({ x: 63, y: 47 });
  });

  it('gives the nearest edge pixel for a point outside the canvas (a drag past its edge)', () => {
    const canvas = fakeCanvas(0, 0, 320, 240);
    expect(pixelAt(canvas, -5, 1000, 32, 24)).toEqual({ x: 0, y: 23 });
    expect(pixelAt(canvas, 320, -1, 32, 24)).toEqual({ x: 31, y: 0 });
  });
});

describe('arrowMove', () => {
  it('moves the selection one pixel per arrow, ten with Shift', () => {
    expect(arrowMove('ArrowRight', false, { x: 10, y: 12 }, 64, 48)).toEqual({ x: 11, y: 12 });
    expect(arrowMove('ArrowUp', false, { x: 10, y: 12 }, 64, 48)).toEqual({ x: 10, y: 11 });
    expect(arrowMove('ArrowLeft', true, { x: 10, y: 12 }, 64, 48)).toEqual({ x: 0, y: 12 });
    expect(arrowMove('ArrowDown', true, { x: 10, y: 12 }, 64, 48)).toEqual({ x: 10, y: 22 });
  });

  it('stops at the edges of the picture', () => {
    expect(arrowMove('ArrowLeft', false, { x: 0, y: 5 }, 64, 48)).toEqual({ x: 0, y: 5 });
    expect(arrowMove('ArrowDown', true, { x: 3, y: 45 }, 64, 48)).toEqual({ x: 3, y: 47 });
  });

  it('selects the middle pixel at the first press when nothing is selected', () => {
    for (const key of ['ArrowLeft', 'ArrowRight', 'ArrowUp', 'ArrowDown']) {
      expect(arrowMove(key, false, null, 64, 48)).toEqual({ x: 32, y: 24 });
      expect(arrowMove(key, true, null, 64, 48)).toEqual({ x: 32, y: 24 });
    }
  });

  it('ignores keys that are no arrows', () => {
    expect(arrowMove('a', false, { x: 1, y: 1 }, 64, 48)).toBeNull();
    expect(arrowMove('Enter', true, null, 64, 48)).toBeNull();
  });
});

describe('listenForPixels', () => {
  it('selects the pixel pressed, and the pixels dragged over while pressed', () => {
    const canvas = fakeCanvas(0, 0, 320, 240), view = fakeView(32, 24);
    listenForPixels(canvas, view);
    canvas.fire('pointerdown', { button: 0, pointerId: 1, clientX: 105, clientY: 125 });
    canvas.fire('pointermove', { buttons: 1, pointerId: 1, clientX: 115, clientY: 125 });
    canvas.fire('pointermove', { buttons: 0, pointerId: 1, clientX: 200, clientY: 125 }); // released: no drag
    expect(view.calls).toEqual([[10, 12], [11, 12]]);
  });

  it('does not select again for a move that did not move, or within the same pixel', () => {
    const canvas = fakeCanvas(0, 0, 320, 240), view = fakeView(32, 24);
    listenForPixels(canvas, view);
    canvas.fire('pointerdown', { button: 0, pointerId: 1, clientX: 105, clientY: 125 });
    canvas.fire('pointermove', { buttons: 1, pointerId: 1, clientX: 105, clientY: 125 }); // the page reflowed
    canvas.fire('pointermove', { buttons: 1, pointerId: 1, clientX: 108, clientY: 127 }); // the same pixel
    expect(view.calls).toEqual([[10, 12]]);
  });

  it('ignores presses of other buttons than the main one', () => {
    const canvas = fakeCanvas(0, 0, 320, 240), view = fakeView(32, 24);
    listenForPixels(canvas, view);
    canvas.fire('pointerdown', { button: 2, pointerId: 1, clientX: 105, clientY: 125 });
    expect(view.calls).toEqual([]);
  });

  it('moves the selection with the arrow keys and keeps them from scrolling the page; other keys pass', () => {
    const canvas = fakeCanvas(0, 0, 320, 240), view = fakeView(32, 24);
    listenForPixels(canvas, view);
    const first = canvas.fire('keydown', { key: 'ArrowRight', shiftKey: false });
    const shifted = canvas.fire('keydown', { key: 'ArrowRight', shiftKey: true });
    const other = canvas.fire('keydown', { key: 'x', shiftKey: false });
    expect(view.calls).toEqual([[16, 12], [26, 12]]);
    expect([first.prevented, shifted.prevented, other.prevented]).toEqual([true, true, false]);
  });
});
