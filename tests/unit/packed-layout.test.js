// The hot loops' literal copies of the packed layout (lib/tracing/kernel.js,
// lib/shapes/sphere.js) are checked against the modules that own them:
// a copy that parts from its owner stops the library at load, naming it.
import { it, expect } from 'vitest';
import * as shapeLayout from '../../lib/shapes/packed.js';
import * as lightLayout from '../../lib/lights/packed.js';
import { MATERIAL_NUMBERS, MATERIAL_AT } from '../../lib/shapes/material.js';
import { packScene } from '../../lib/tracing/kernel.js';
import { classScene } from '../../lib/index.js';

const { checkCopies } = shapeLayout;

it('a copy equal to its owner passes; one that differs throws, naming the offset and the owner', () => {
  expect(() => checkCopies({ SHAPE: 7, KIND: 6, P: 0, N: 3 }, shapeLayout, 'lib/shapes/packed.js')).not.toThrow();
  expect(() => checkCopies({ LIGHT: 15 }, lightLayout, 'lib/lights/packed.js'))
    .toThrow("LIGHT is 15 in a copy of lib/lights/packed.js's layout, which says 14: change the copy");
  expect(() => checkCopies({ MATERIAL: 12 }, { MATERIAL: MATERIAL_NUMBERS + 1 }, 'lib/shapes/material.js')).toThrow(/MATERIAL is 12 .* which says 13/);
});

it('the kernel packs by its owners\' numbers: a material at MATERIAL_NUMBERS apart, a light at LIGHT apart', () => {
  const packed = packScene(classScene({ full: true }));
  expect(packed.materials.length).toBe(packed.count * MATERIAL_NUMBERS);
  expect(packed.materials[MATERIAL_NUMBERS + MATERIAL_AT.reflection]).toBe(0.5); // the pink ball's mirror
  expect(packed.lights.length).toBe(packed.lightCount * lightLayout.LIGHT);
  expect(packed.lights[lightLayout.LIGHT + lightLayout.LIGHT_EMISSION]).toBe(1); // the second glow's emission
});
