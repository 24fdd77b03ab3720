// What a tracer view tells its listeners (lib/p5/tracer/events.js): each
// listener hears its own event, in the order added, until it is removed.
import { describe, it, expect } from 'vitest';
import { createEvents } from '../../lib/p5/tracer/events.js';

describe('createEvents', () => {
  it('calls each listener of an event with what is emitted, in the order they were added', () => {
    const events = createEvents(['select', 'restart']);
    const heard = [];
    events.on('select', (pixel, view) => heard.push(['first', pixel, view]));
    events.on('select', (pixel) => heard.push(['second', pixel]));
    events.on('restart', () => heard.push(['restart']));
    events.emit('select', { x: 3, y: 4 }, 'the view');
    expect(heard).toEqual([['first', { x: 3, y: 4 }, 'the view'], ['second', { x: 3, y: 4 }]]);
  });

  it('on() returns the function that removes that listener, and only that one', () => {
    const events = createEvents(['progress']);
    const heard = [];
    const stop = events.on('progress', (p) => heard.push(`a${p}`));
    events.on('progress', (p) => heard.push(`b${p}`));
    events.emit('progress', 1);
    stop();
    stop(); // twice is harmless
    events.emit('progress', 2);
    expect(heard).toEqual(['a1', 'b1', 'b2']);
  });

  it('heard() says whether an event has a listener', () => {
    const events = createEvents(['progress']);
    expect(events.heard('progress')).toBe(false);
    const stop = events.on('progress', () => {});
    expect(events.heard('progress')).toBe(true);
    stop();
    expect(events.heard('progress')).toBe(false);
  });

  it('refuses an event it does not know, and a listener that is no function, naming them', () => {
    const events = createEvents(['select', 'restart', 'progress']);
    expect(() => events.on('selected', () => {})).toThrow(new RangeError("on() takes one of 'select', 'restart', 'progress', got \"selected\""));
    expect(() => events.on('select', 'log')).toThrow(TypeError);
    expect(() => events.on('select', 'log')).toThrow(/on\('select', fn\) needs a function/);
  });
});
