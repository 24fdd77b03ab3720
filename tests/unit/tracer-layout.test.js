// The tracer view's size on screen: screen pixels per traced pixel for a
// numeric scale and for 'auto', from the page's measures.
import { describe, it, expect } from 'vitest';
import { cappedScale, checkScale, fixedScale, fitScale } from '../../lib/p5/tracer/layout.js';

/** The test pages' room: a 1280 × 900 window, 16 px text, a wide parent. */
const ROOM = { rem: 16, parentWidth: 1200, windowWidth: 1280, windowHeight: 900 };

describe('fixedScale', () => {
  it('keeps a numeric scale as given with 16 px text', () => {
    expect(fixedScale(4, 16)).toBe(4);
    expect(fixedScale(2.5, 16)).toBe(2.5);
  });

  it('grows with the text, in whole steps for a whole-number scale, never below 1', () => {
    expect(fixedScale(4, 24)).toBe(6);
    expect(fixedScale(5, 20)).toBe(6);   // 6.25 → 6
    expect(fixedScale(1, 4)).toBe(1);    // 0.25 → at least 1
    expect(fixedScale(2.5, 32)).toBe(5); // a fraction scales as is
    expect(fixedScale(0.5, 20)).toBe(0.625);
  });
});

describe('fitScale', () => {
  it('gives a 64 × 48 picture ten screen pixels per pixel at 1280 × 900: 40rem wide', () => {
    expect(fitScale(64, 48, ROOM)).toBe(10);
  });

  it('leaves room for the panel beside the picture', () => {
    // 1024 wide: 1024 − 34rem = 480 px beside the panel → 7 (a whole number)
    expect(fitScale(64, 48, { ...ROOM, windowWidth: 1024 })).toBe(7);
  });

  it('uses the whole width on a narrow screen, where the panel goes below the picture', () => {
    // 800 − 34rem = 256 < 20rem: no room beside; the parent's 600 px and 70% of the height decide
    expect(fitScale(64, 48, { ...ROOM, parentWidth: 600, windowWidth: 800, windowHeight: 600 })).toBe(8);
  });

  it("fits the parent's width, and 70% of the window's height", () => {
    expect(fitScale(64, 48, { ...ROOM, parentWidth: 320 })).toBe(5);
    expect(fitScale(64, 48, { ...ROOM, windowHeight: 480 })).toBe(7); // 336 / 48
  });

  it('takes 40rem when the parent has no width yet', () => {
    const narrow = { ...ROOM, windowWidth: 800 }; // no room beside a panel: the parent's width decides
    expect(fitScale(64, 48, { ...narrow, parentWidth: 600 })).toBe(9);
    expect(fitScale(64, 48, { ...narrow, parentWidth: 0 })).toBe(10);
    expect(fitScale(64, 48, { ...narrow, parentWidth: undefined })).toBe(10);
  });

  it('grows with the text, as the rem-sized room does', () => {
    expect(fitScale(64, 48, { ...ROOM, rem: 24, parentWidth: 1900, windowWidth: 1920, windowHeight: 1080 })).toBe(15);
  });

  it('shrinks a picture bigger than the room by a fraction, as whole numbers cannot', () => {
    expect(fitScale(1280, 960, ROOM)).toBe(0.5);
    expect(fitScale(640, 480, ROOM)).toBe(1);
  });
});

describe('checkScale', () => {
  it("takes 'auto' and numbers greater than 0", () => {
    expect(checkScale('auto')).toBe('auto');
    expect(checkScale(0.5)).toBe(0.5);
    expect(checkScale(8)).toBe(8);
  });

  it('refuses anything else with a RangeError naming scale', () => {
    for (const bad of [0, -2, NaN, Infinity, '4', null, 'big']) {
      expect(() => checkScale(bad)).toThrow(RangeError);
      expect(() => checkScale(bad)).toThrow(/scale must be 'auto' or a number greater than 0/);
    }
  });
});

describe('cappedScale', () => {
  const usual = { rem: 16, width: 1200, windowWidth: 1280, windowHeight: 900 };
  it('keeps a numeric scale as given with 16 px text and room for it', () => {
    expect(cappedScale(10, 32, 24, usual)).toBe(10);
    expect(cappedScale(3, 160, 120, usual)).toBe(3);
  });

  it('grows on a big screen until the picture takes 35% of the width or half the height', () => {
    const big = { rem: 21.12, width: 1200, windowWidth: 1920, windowHeight: 1080 };
    expect(cappedScale(10, 32, 24, big)).toBe(21);  // 672 px: 35% of 1920
    expect(cappedScale(3, 160, 120, big)).toBe(5);  // 800 × 600
    expect(cappedScale(6, 64, 48, big)).toBe(11);   // 704 px
    expect(cappedScale(2, 32, 24, big)).toBe(21);   // a small scale grows as much
    expect(cappedScale(30, 32, 24, big)).toBe(37);  // already bigger (40 with this text): within the room, 1200 / 32
  });

  it('grows no further than its room and 70% of the window height', () => {
    const big = { rem: 21.12, width: 500, windowWidth: 1920, windowHeight: 1080 };
    expect(cappedScale(10, 32, 24, big)).toBe(15);  // 480 px of 500
    expect(cappedScale(1, 32, 240, { ...big, width: 1200 })).toBe(3); // 720 px tall of 756
  });

  it('shrinks to the room on a phone: whole numbers from 2 up, else the picture fills the room', () => {
    const phone = { rem: 16, width: 288, windowWidth: 320, windowHeight: 640 };
    expect(cappedScale(16, 32, 24, phone)).toBe(9);
    expect(cappedScale(6, 64, 48, phone)).toBe(4);
    expect(cappedScale(3, 160, 120, phone)).toBeCloseTo(1.8);
    expect(cappedScale(1, 640, 480, phone)).toBeCloseTo(0.45);
  });
});
