import { describe, it, expect } from 'vitest';
import { resolve } from 'node:path';
import { syntaxErrorsWhereTheyAre, swapHooks } from '../../scripts/vite-live-coding.js';

const ROOT = resolve('.');
const plugin = syntaxErrorsWhereTheyAre();
plugin.configResolved({ root: ROOT });
const context = { error: (message, pos) => { throw Object.assign(new Error(message), { pos }); } };
const transform = (code, id) => plugin.transform.call(context, code, id);

const BROKEN = "import p5 from 'p5';\n\nfunction f() {\n  const s = 'abc;\n}\n";

describe('syntaxErrorsWhereTheyAre', () => {
  it('leaves valid code and files it does not own alone', () => {
    expect(transform("import p5 from 'p5';\nnew p5(() => {});\n", resolve('sketches/10-playground.js'))).toBeNull();
    expect(transform(BROKEN, resolve('node_modules/x/index.js'))).toBeNull();
    expect(transform('body { color: red }', resolve('sketches/sketch.css'))).toBeNull();
  });

  it("a page's script with a syntax error becomes a module showing it on that page, at its line and column", () => {
    const code = transform(BROKEN, resolve('sketches/10-playground.js'));
    expect(code).toContain('import { showMistake } from "/lib/p5/page/error-panel.js";');
    expect(code).toContain('console.error("SyntaxError: Unterminated string (sketches/10-playground.js:4:13)");');
    expect(code).toContain('"file":"sketches/10-playground.js","line":4,"column":13,"source":"  const s = \'abc;","exact":true');
    expect(BROKEN.split('\n')[3][12]).toBe("'"); // column 13 is the quote that opens the string
  });

  it('any other module reports it to Vite (its overlay) at the offset of the mistake, not at 1:0', () => {
    let thrown;
    try { transform(BROKEN, resolve('lib/some-helper.js')); } catch (error) { thrown = error; }
    expect(thrown.message).toBe('Syntax error: Unterminated string');
    expect(thrown.pos).toBe(BROKEN.indexOf("'abc"));
  });
});

describe('swapHooks: which page scripts a save swaps in place', () => {
  const SKETCH = "import p5 from 'p5';\nimport { Scene } from '../lib/index.js';\nimport '../lib/p5/index.js';\nnew p5((p) => { p.setup = () => new Scene(); }, 'sketch');\n";
  const file = resolve('sketches/11-my-sketch.js');

  it('a sketch importing p5 and the kit alone gets the hooks, on its first line, every line keeping its number', () => {
    const code = swapHooks(ROOT, file, SKETCH);
    const lines = code.split('\n');
    expect(lines[0]).toMatch(/^if \(import\.meta\.hot\) \{ import\.meta\.hot\.accept\(__sketchbookSwap\.swappedIn\); import\.meta\.hot\.dispose\(__sketchbookSwap\.swapOut\); \} import p5 from 'p5';$/);
    expect(lines.slice(1, 4)).toEqual(SKETCH.split('\n').slice(1, 4));
    expect(code).toContain('import * as __sketchbookSwap from "/lib/p5/page/hot-swap.js";');
  });

  it('a sketch importing a module of its own, or a package other than p5, reloads instead', () => {
    expect(swapHooks(ROOT, file, `import { helper } from './helper.js';\n${SKETCH}`)).toBeNull();
    expect(swapHooks(ROOT, file, `import confetti from 'confetti';\n${SKETCH}`)).toBeNull();
    expect(swapHooks(ROOT, file, `export { helper } from './helper.js';\n${SKETCH}`)).toBeNull();
  });

  it('a sketch calling what a swap cannot undo (timers, workers, the camera, a window handler) reloads instead', () => {
    for (const call of ['setTimeout(() => {}, 10);', 'setInterval(f, 10);', 'requestAnimationFrame(f);', 'new Worker(url);', 'p.createCapture(p.VIDEO);', 'window.onresize = f;']) {
      expect(swapHooks(ROOT, file, `${SKETCH}${call}\n`), call).toBeNull();
    }
    expect(swapHooks(ROOT, file, `${SKETCH}// setTimeout in a comment is nothing\nconst view = { timeout: 1 };\n`)).not.toBeNull();
  });
});

describe("syntaxErrorsWhereTheyAre: a page's script importing what the kit does not have", () => {
  const file = resolve('sketches/10-playground.js');
  const SKETCH = "import p5 from 'p5';\nimport { Scene, Spehre } from '../lib/index.js';\nimport '../lib/p5/index.js';\nnew p5(() => {});\n";

  it('a name the kit does not export: shown on the page at the import, with the nearest export', () => {
    const code = transform(SKETCH, file);
    expect(code).toContain('"SyntaxError: The requested module \'../lib/index.js\' does not provide an export named \'Spehre\'"');
    expect(code).toContain('"file":"sketches/10-playground.js","line":2,"column":17');
    expect(code).toContain('"suggestion":"did you mean Sphere?"');
    expect(SKETCH.split('\n')[1].slice(16, 22)).toBe('Spehre'); // column 17 is where the name starts
  });

  it('a p5 method of the addon imported as if exported: the method it is, and how to call it', () => {
    const veiw = transform("import p5 from 'p5';\nimport { createTracerVeiw } from '../lib/p5/index.js';\n", file);
    expect(veiw).toContain('"suggestion":"did you mean createTracerView? It is a method of p, not an export: write p.createTracerView({ … })"');
    const exact = transform("import { createInspector } from '../lib/p5/index.js';\n", file);
    expect(exact).toContain('"suggestion":"createInspector is a method of p, not an export: write p.createInspector({ … })"');
  });

  it('a kit file that is not there names the nearest file; good imports and other modules are left alone', () => {
    const code = transform("import '../lib/p5/indx.js';\n", file);
    expect(code).toContain('there is no lib/p5/indx.js');
    expect(code).toContain(`"suggestion":"did you mean '../lib/p5/index.js'?"`);
    expect(transform("import { Scene, Sphere, Camera, render } from '../lib/index.js';\nimport { TracerView, FACTORIES } from '../lib/p5/index.js';\n", file)).toBeNull();
    expect(transform("import { Spehre } from '../lib/index.js';\n", resolve('lib/some-helper.js'))).toBeNull(); // not a page's script
    expect(transform("import { anything } from './helper.js';\n", file)).toBeNull(); // the sketch's own module: the browser says
  });

  it('every page the dev server serves gets the classic script that reports a module the browser refused', () => {
    const [tag] = plugin.transformIndexHtml();
    expect(tag).toMatchObject({ tag: 'script', injectTo: 'head-prepend' });
    expect(tag.children).toContain('import("/lib/p5/page/error-panel.js")');
    expect(tag.children).toContain('showModuleFailure');
    expect(tag.attrs?.type).toBeUndefined(); // classic: it runs even when every module of the page fails
  });
});
