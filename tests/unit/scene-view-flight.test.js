// Shoot's flight (lib/p5/scene-view/flight.js): which traced pixels fly, how
// far each segment has grown at a given time, and when a ray has arrived.
import { describe, it, expect } from 'vitest';
import { Vec3 } from '../../lib/math/vec3.js';
import { legSeconds, startOf, tracedSince, flightFrame, launch, Flight, checkSpeed, MAX_FLYING, FLY_LAST } from '../../lib/p5/scene-view/flight.js';

/** A pixel's story: a primary ray to a hit, its normal, a shadow ray blocked half-way, a bounce. */
const story = () => [
  { kind: 'primary', depth: 0, from: new Vec3(0, 0, 0), to: new Vec3(10, 0, 0), hit: true },
  { kind: 'normal', depth: 0, from: new Vec3(10, 0, 0), to: new Vec3(10, 1, 0) },
  { kind: 'shadow', depth: 0, from: new Vec3(10, 0, 0), to: new Vec3(10, 10, 0), facing: true, lit: false, blockedAt: new Vec3(10, 5, 0) },
  { kind: 'reflection', depth: 1, from: new Vec3(10, 0, 0), to: new Vec3(20, 0, 0), hit: false },
];

describe('legSeconds', () => {
  it('takes 1.6 s over the rays of one second, within 0.06 s and 0.8 s a leg', () => {
    expect(legSeconds(4)).toBeCloseTo(0.4, 12);
    expect(legSeconds(8)).toBeCloseTo(0.2, 12);
    expect(legSeconds(1)).toBe(0.8); // 1.6 s would be too slow to follow
    expect(legSeconds(120)).toBe(0.06); // 13 ms would be too fast to see
  });
});

describe('startOf', () => {
  it('starts a ray of depth d after d legs, its normal and shadow rays one leg later', () => {
    expect(story().map(startOf)).toEqual([0, 1, 1, 1]);
    expect(startOf({ kind: 'shadow', depth: 2 })).toBe(3);
  });
});

describe('tracedSince', () => {
  it('from nothing seen, counts every pixel up to the current one and flies them', () => {
    expect(tracedSince(null, { x: 3, y: 0 }, 16)).toEqual({ count: 4, fly: [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 2, y: 0 }, { x: 3, y: 0 }] });
  });

  it('counts the pixels since the last one seen, in scanline order, and flies only the last few', () => {
    const { count, fly } = tracedSince({ x: 3, y: 0 }, { x: 2, y: 1 }, 16); // pixels 4 … 18
    expect(count).toBe(15);
    expect(fly).toHaveLength(FLY_LAST);
    expect(fly[0]).toEqual({ x: 11, y: 0 });
    expect(fly.at(-1)).toEqual({ x: 2, y: 1 });
    expect(fly.slice(4, 6)).toEqual([{ x: 15, y: 0 }, { x: 0, y: 1 }]); // across the end of the row
  });

  it('is null when nothing new was traced', () => {
    expect(tracedSince({ x: 5, y: 2 }, { x: 5, y: 2 }, 16)).toBeNull();
    expect(tracedSince(null, null, 16)).toBeNull();
  });
});

describe('flightFrame', () => {
  const LEG = 100;

  it('grows the primary ray first; the hit dot waits for it to arrive', () => {
    const { segments, moving } = flightFrame([{ segments: story(), t0: 1000 }], 1050, LEG);
    expect(segments).toHaveLength(1);
    expect(segments[0].to).toEqual(new Vec3(5, 0, 0));
    expect(segments[0].hit).toBe(false);
    expect(moving).toBe(true);
  });

  it('then, at the hit, the normal, the shadow ray (blocked only once it got there) and the bounce', () => {
    const { segments } = flightFrame([{ segments: story(), t0: 1000 }], 1150, LEG);
    expect(segments.map((s) => s.kind)).toEqual(['primary', 'normal', 'shadow', 'reflection']);
    expect(segments[0]).toMatchObject({ to: new Vec3(10, 0, 0), hit: true });
    expect(segments[2].to).toEqual(new Vec3(10, 5, 0));
    expect(segments[2].blockedAt).toBeNull();
    expect(segments[3].to).toEqual(new Vec3(15, 0, 0));
    const arrived = flightFrame([{ segments: story(), t0: 1000 }], 1200, LEG).segments;
    expect(arrived[2].blockedAt).toEqual(new Vec3(10, 5, 0));
  });

  it('a lone ray that has arrived stays, still; an older one goes once it arrived two legs ago', () => {
    const alone = flightFrame([{ segments: story(), t0: 0 }], 10_000, LEG);
    expect(alone.flying).toHaveLength(1);
    expect(alone.moving).toBe(false);
    const old = { segments: story(), t0: 0 }, young = { segments: story(), t0: 9_990 };
    const both = flightFrame([old, young], 10_000, LEG);
    expect(both.flying).toEqual([young]);
    expect(flightFrame([old, young], 390, LEG).flying).toEqual([old, young]); // 3.9 legs: arrived at 2, gone only after 4
  });

  it('draws nothing of a ray not yet sent', () => {
    expect(flightFrame([{ segments: story(), t0: 2000 }], 1000, LEG).segments).toEqual([]);
  });
});

describe('launch and Flight', () => {
  it('keeps at most MAX_FLYING rays in flight, dropping the oldest', () => {
    const flying = [];
    for (let i = 0; i < MAX_FLYING + 5; i++) launch(flying, [], i);
    expect(flying).toHaveLength(MAX_FLYING);
    expect(flying[0].t0).toBe(5);
  });

  it('counts every ray sent, flies the last few with their stories, and remembers the last pixel', () => {
    const flight = new Flight(), asked = [];
    let clock = 100;
    const storyOf = (x, y) => { asked.push(`${x},${y}`); return story(); };
    expect(flight.traced({ x: 1, y: 0 }, 4, storyOf, () => clock++)).toBe(true);
    expect(flight.traced({ x: 1, y: 0 }, 4, storyOf)).toBe(false); // nothing new
    expect(flight.traced({ x: 3, y: 2 }, 4, storyOf, () => clock++)).toBe(true);
    expect(flight.shots).toBe(12); // 4 × 3 pixels, up to (3, 2)
    expect(asked).toEqual(['0,0', '1,0', '0,1', '1,1', '2,1', '3,1', '0,2', '1,2', '2,2', '3,2']);
    expect(flight.last).toEqual({ x: 3, y: 2 });
    expect(flight.flying.map((f) => f.t0)).toEqual([100, 101, 102, 103, 104, 105, 106, 107, 108, 109]);
  });

  it('frame() keeps only the rays still shown', () => {
    const flight = new Flight();
    flight.traced({ x: 1, y: 0 }, 4, () => story(), () => 0);
    const { moving } = flight.frame(10_000, 100);
    expect(flight.flying).toHaveLength(1); // the newest stays
    expect(moving).toBe(false);
  });
});

describe('checkSpeed', () => {
  it('takes rays per second greater than 0, and names the field otherwise', () => {
    expect(checkSpeed(15)).toBe(15);
    for (const bad of [0, -4, Infinity, NaN, '4']) expect(() => checkSpeed(bad)).toThrow(/^raysPerSecond must be a number greater than 0, got /);
  });
});
