// "Copy scene as code" for hostile names and numbers: the code, run as the
// ES module a sketch is (strict mode), rebuilds the same scene, −0 included.
import { describe, it, expect, afterAll } from 'vitest';
import { mkdtempSync, writeFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { Scene, Sphere, Plane, PointLight } from '../../lib/index.js';
import { sceneToJSON, sceneToCode } from '../../lib/scene/json.js';

const dir = mkdtempSync(join(tmpdir(), 'scene-code-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));
let files = 0;

/** Writes the code as a module (importing the library by file URL), imports it, returns its scene. */
async function runAsModule(scene) {
  const code = sceneToCode(scene, { importFrom: pathToFileURL(resolve('lib/index.js')).href });
  const file = join(dir, `scene${files++}.mjs`);
  writeFileSync(file, `${code}\nexport default scene;\n`);
  return (await import(pathToFileURL(file).href)).default;
}

// Strict-mode reserved words, names the generated code uses, prototype names, and odd text.
const HOSTILE = ['package', 'eval', 'arguments', 'public', 'private', 'protected', 'interface', 'implements', 'static',
  'let', 'yield', 'await', 'enum', 'new', 'class', 'this', 'super', 'import', 'export', 'default', 'null', 'true',
  'undefined', 'NaN', 'Infinity', 'scene', 'Scene', 'Sphere', 'Plane', 'PointLight', '__proto__', 'constructor',
  'prototype', 'hasOwnProperty', 'globalThis', 'Object', '1st', '', '   ', '$', '_', 'ünïcode ☀', 'a\u2028b',
  "it's", 'back\\slash', '"quoted"', '${x}', '`tick`', '</script><img src=x onerror=alert(1)>', '*/ alert(1) /*', '// x'];

describe('sceneToCode with hostile names', () => {
  it('runs as a module and rebuilds every name', async () => {
    const scene = new Scene();
    for (const name of HOSTILE) scene.add(Object.assign(new Sphere([0, 0, -5], 1), { name }));
    const back = await runAsModule(scene);
    expect(back.objects.map((o) => o.name)).toEqual(HOSTILE.map((n) => n));
  });

  it('each reserved word alone makes code that runs', async () => {
    for (const name of ['package', 'eval', 'arguments', 'public', 'private', 'protected', 'interface', 'implements']) {
      const scene = new Scene().add(Object.assign(new Sphere([1, 2, -5], 1), { name }));
      expect(sceneToJSON(await runAsModule(scene)), name).toEqual(sceneToJSON(scene));
    }
  });
});

describe('sceneToCode keeps every number', () => {
  it('−0 stays −0 in centres, normals, positions and colours', async () => {
    const scene = new Scene({ background: [-0, 0.5, 1] })
      .add(Object.assign(new Sphere([-0, 0, -20], 4, { color: [-0, 1, 0.5], emission: [-0, -0, -0] }), { name: 'minus zero' }))
      .add(new Plane([0, -0, 0], [0, 1, -0]))
      .add(new PointLight([-0, 10, 0], [1, -0, 1], 2));
    const code = sceneToCode(scene);
    expect(code).toContain('new Sphere([-0, 0, -20], 4,');
    const back = await runAsModule(scene);
    expect(sceneToJSON(back)).toEqual(sceneToJSON(scene));
    expect(Object.is(back.objects[0].center.x, -0)).toBe(true);
  });

  it('long and tiny numbers come back bit for bit', async () => {
    const scene = new Scene().add(new Sphere([0.1 + 0.2, 1e-300, -1e21], 5e-324, { color: [1 / 3, 0, 1] }));
    expect(sceneToJSON(await runAsModule(scene))).toEqual(sceneToJSON(scene));
  });
});
