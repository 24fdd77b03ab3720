// Numbers as the kit prints them: each formatter prints what the pages, the
// legends and the screenshots have always shown.
import { describe, it, expect } from 'vitest';
import { formatLabel, sign, formatNumber, formatVector, formatAngle, formatRounded, formatPowerOfTen, formatRate } from '../../lib/text/format.js';

describe('formatLabel, the diagrams\' labels', () => {
  it('rounds to one decimal (or `digits`) with a real minus sign, and never prints −0', () => {
    expect([-3.25, 12.345, 0.05, 0].map((n) => formatLabel(n))).toEqual(['−3.3', '12.3', '0.1', '0.0']);
    expect(formatLabel(-0.04)).toBe('0.0');
    expect(formatLabel(-0.04, 2)).toBe('−0.04');
    expect(formatLabel(12.345, 2)).toBe('12.35');
  });

  it('prints thousands whole, millions as a×10ⁿ, and a dash for no number', () => {
    expect([1234.5, -98765.4].map((n) => formatLabel(n))).toEqual(['1235', '−98765']);
    expect([1e6, 2.5e7, -3.4e12].map((n) => formatLabel(n))).toEqual(['1.00×10⁶', '2.50×10⁷', '−3.40×10¹²']);
    expect([null, undefined, NaN, Infinity].map((n) => formatLabel(n))).toEqual(['—', '—', '—', '—']);
  });

  it('puts + or − between a formula\'s terms', () => {
    expect([sign(-2), sign(0), sign(3)]).toEqual(['−', '+', '+']);
  });
});

describe('formatNumber and formatVector, the inspector\'s values', () => {
  it('keeps 4 significant digits, thousands whole, powers of ten for the very large and small', () => {
    expect([0, -0, 1 / 3, -2.5, 1234.56].map(formatNumber)).toEqual(['0', '0', '0.3333', '-2.5', '1235']);
    expect([12345678, 0.00001234, 1e-5, 2e7].map(formatNumber)).toEqual(['1.235e7', '1.234e-5', '1e-5', '2e7']);
  });

  it('says — for no value and ∞ for the infinite', () => {
    expect([null, undefined, NaN, Infinity, -Infinity].map(formatNumber)).toEqual(['—', '—', '—', '∞', '-∞']);
    expect(formatVector({ x: 1 / 3, y: -2, z: 1e8 })).toBe('(0.3333, -2, 1e8)');
    expect(formatVector(null)).toBe('—');
  });
});

describe('formatAngle, the answer line\'s angles', () => {
  it('prints one decimal and no −0.0', () => {
    expect([30, -1.94, 3.21, -0.04].map(formatAngle)).toEqual(['30.0', '-1.9', '3.2', '0.0']);
  });
});

describe('formatRounded and formatPowerOfTen, the legends\' numbers', () => {
  it('rounds to whole numbers from 10 up, else to one decimal', () => {
    expect([0.04, 2.46, 9.96, 12.5, -3.35, 150.4].map(formatRounded)).toEqual(['0', '2.5', '10', '13', '-3.3', '150']);
  });

  it('gives the nearest power of ten, in superscript from 1000 up', () => {
    expect([0.01, 1, 7, 100, 316, 1000, 12345, 1e12].map(formatPowerOfTen)).toEqual(['0.01', '1', '10', '100', '100', '10³', '10⁴', '10¹²']);
  });
});

describe('formatRate, the progress line\'s rays per second', () => {
  it('prints units, thousands (k) and millions (M)', () => {
    expect([0, 850.4, 1000, 35400, 1e6, 1234567].map(formatRate)).toEqual(['0', '850', '1k', '35k', '1.0M', '1.2M']);
  });
});
