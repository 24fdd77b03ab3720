// The npm package, as a teacher gets it: npm pack holds the library, its
// types, the README and the licence, and no tests; the tarball installs into
// a fresh project (offline: the library needs no package of its own; p5 is an
// optional peer) and renders a scene through the package's own name; its
// types check a TypeScript file that uses them.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, mkdirSync, writeFileSync, readFileSync, rmSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

const root = resolve('.');
const npm = (args, cwd) => execFileSync('npm', args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
const pkg = JSON.parse(readFileSync('package.json', 'utf8'));

let tmp, packed, files;

beforeAll(() => {
  tmp = mkdtempSync(join(tmpdir(), 'rt-package-'));
  execFileSync(process.execPath, ['scripts/types.js'], { stdio: 'pipe' }); // what prepack does
  [packed] = JSON.parse(npm(['pack', '--json', '--ignore-scripts', '--pack-destination', tmp], root));
  files = packed.files.map((f) => f.path);
}, 120_000);

afterAll(() => rmSync(tmp, { recursive: true, force: true }));

describe('npm pack', () => {
  it('is publishable, with the two entry points and their types', () => {
    expect(pkg.private).toBeUndefined();
    expect(pkg.exports['.']).toEqual({ types: './types/index.d.ts', default: './lib/index.js' });
    expect(pkg.exports['./p5']).toEqual({ types: './types/p5/index.d.ts', default: './lib/p5/index.js' });
    expect(pkg.types).toBe('types/index.d.ts');
  });

  it('holds the library, its types, the README and the licence, and no tests', () => {
    for (const file of ['package.json', 'README.md', 'LICENSE', 'lib/index.js', 'lib/p5/index.js', 'lib/p5/style.css',
      'lib/tracing/workers/render-worker.js', 'types/index.d.ts', 'types/p5/index.d.ts', 'types/shapes/sphere.d.ts']) {
      expect(files, file).toContain(file);
    }
    const strays = files.filter((f) => !/^(lib|types)\//.test(f) && !['package.json', 'README.md', 'LICENSE'].includes(f));
    expect(strays).toEqual([]);
    expect(files.filter((f) => /(^|\/)tests?\/|\.(test|spec)\.js$/.test(f))).toEqual([]);
    // every module of the library has its declarations
    for (const js of files.filter((f) => f.startsWith('lib/') && f.endsWith('.js'))) {
      expect(files, `types of ${js}`).toContain(js.replace(/^lib\//, 'types/').replace(/\.js$/, '.d.ts'));
    }
  });

  it('installs into a fresh project offline, renders a scene and gives its types to TypeScript', () => {
    const project = join(tmp, 'project');
    mkdirSync(project);
    writeFileSync(join(project, 'package.json'), JSON.stringify({ name: 'my-sketch', private: true, type: 'module' }));
    npm(['install', join(tmp, packed.filename), '--offline', '--no-audit', '--no-fund', '--ignore-scripts'], project);

    writeFileSync(join(project, 'render.js'), `
      import { Scene, Sphere, Camera, render } from 'raytracing-sketchbook';
      const scene = new Scene({ background: [0, 0, 1] })
        .add(new Sphere([0, 0, -20], 4, { color: [1, 0.32, 0.36] }))
        .add(new Sphere([0, 10, 0], 1, { color: [0, 0, 0], emission: 1.2 })); // a light above the eye
      const camera = new Camera({ width: 32, height: 24 });
      const rgba = render(scene, camera);
      const at = (x, y) => [...rgba.slice((y * 32 + x) * 4, (y * 32 + x) * 4 + 4)];
      console.log(JSON.stringify({ length: rgba.length, centre: at(16, 12), corner: at(0, 23),
        p5: import.meta.resolve('raytracing-sketchbook/p5') }));
    `);
    const out = JSON.parse(execFileSync(process.execPath, ['render.js'], { cwd: project, encoding: 'utf8' }));
    expect(out.length).toBe(32 * 24 * 4);
    expect(out.corner).toEqual([0, 0, 255, 255]); // the background
    expect(out.centre).toEqual([250, 80, 90, 255]); // the pink sphere, lit from above the eye (render() in this repo gives the same)
    expect(out.p5).toMatch(/node_modules\/raytracing-sketchbook\/lib\/p5\/index\.js$/);
    expect(existsSync(join(project, 'node_modules', 'p5'))).toBe(false); // the library alone needs no p5

    // The generated types, through "exports": right code checks, a wrong option does not.
    writeFileSync(join(project, 'good.ts'), `
      import { Scene, Sphere, Camera, render } from 'raytracing-sketchbook';
      const scene: Scene = new Scene({ background: [0, 0, 0] }).add(new Sphere([0, 0, -5], 1, { color: 'pink' }));
      const pixels: Uint8ClampedArray = render(scene, new Camera({ width: 4, height: 3, fov: 40 }));
    `);
    writeFileSync(join(project, 'bad.ts'), `
      import { Camera } from 'raytracing-sketchbook';
      new Camera({ width: 4, height: '3' });
    `);
    writeFileSync(join(project, 'tsconfig.json'), JSON.stringify({
      compilerOptions: { strict: true, noEmit: true, module: 'nodenext', moduleResolution: 'nodenext', target: 'es2022', lib: ['es2022', 'dom'], types: [] },
      files: ['good.ts', 'bad.ts'],
    }));
    let report = '';
    try {
      execFileSync(process.execPath, [join(root, 'node_modules/typescript/bin/tsc'), '-p', '.'], { cwd: project, encoding: 'utf8', stdio: 'pipe' });
    } catch (error) {
      report = error.stdout || String(error);
    }
    const errors = report.split('\n').filter((line) => / error TS/.test(line));
    expect(errors).toEqual([expect.stringMatching(/^bad\.ts\(3,\d+\): error TS2322: Type 'string' is not assignable to type 'number'/)]);
  }, 120_000);
});
