/**
 * 07 · The original examples (slide "Javascript Ray Tracer — out of the box"):
 * the class library's three examples on one page.
 *   still     the class scene, traced once;
 *   animated  the spheres circle the pink one; each frame is traced whole on
 *             the main thread, and an FPS counter says how many per second;
 *   workers   the same frames shared out over Web Workers (ParallelRenderer):
 *             the main thread only copies finished rows onto the screen.
 * Choose one with the buttons, or open the page with ?example=animated.
 */
import p5 from 'p5';
import { Camera, classScene } from '../lib/index.js';
import { createTracerView, createInspector, registerView } from '../lib/p5/index.js';
import { ParallelRenderer } from '../lib/workers/parallel.js';

const STILL = { width: 160, height: 120 };   // traced pixels of the still scene
const MOVIE = { width: 320, height: 240 };   // of each animation frame: bigger frames, more work to share
const SECONDS_PER_TURN = 12;                 // the spheres circle the pink one this fast
const WORKERS = 4;                           // worker count at first (the box takes 1–8)
const EXAMPLES = ['still', 'animated', 'workers'];

/** The class scene t seconds in: yellow, blue and white turned about the pink sphere's centre. */
function sceneAt(t) {
  const scene = classScene();
  const pink = scene.objects.find((o) => o.name === 'pink').center;
  const angle = (2 * Math.PI * t) / SECONDS_PER_TURN, turnX = Math.cos(angle), turnZ = Math.sin(angle);
  for (const name of ['yellow', 'blue', 'white']) {
    const c = scene.objects.find((o) => o.name === name).center;
    const x = c.x - pink.x, z = c.z - pink.z;
    c.x = pink.x + x * turnX - z * turnZ;
    c.z = pink.z + x * turnZ + z * turnX;
  }
  return scene;
}

new p5((p) => {
  const stillCamera = new Camera(STILL), movieCamera = new Camera(MOVIE);
  let view, ui, example = 'still', playing = false;
  let time = 0, shown = 0, frames = 0, stamps = [];   // animation clock, time of the frame on screen, FPS
  let workerCount = WORKERS, parallel = null, inFlight = false, workerFrame = null;
  const animation = registerView({}); // holds data-render at "rendering" while the animation plays

  p.setup = () => {
    p.noCanvas();
    const column = p.createDiv().addClass('column');
    ui = controls(column);
    view = createTracerView(p, { scene: classScene(), camera: stillCamera, parent: column });
    animation.done(); // not playing yet
    ui.stats.parent(column);
    ui.note.parent(column);
    createInspector({ view, parent: p._userNode });
    window.sketch = { sceneAt, camera: movieCamera }; // try sketch.sceneAt(3) in the browser console

    const asked = new URLSearchParams(location.search).get('example') ?? 'still';
    choose(EXAMPLES.includes(asked) ? asked : 'still');
    if (!EXAMPLES.includes(asked)) say(ui.error, `example must be ${EXAMPLES.join(', ')}; got "${asked}", so here is the still scene.`);
  };

  p.draw = () => {
    if (!playing) return;
    time += p.deltaTime / 1000;
    if (example === 'animated') {
      showTraced(time);
      counted(time);
    } else if (!inFlight) renderOnWorkers(time);
  };

  /** Shows one example: the still scene, or the animation (main thread or workers), playing. */
  function choose(name) {
    example = name;
    for (const [key, button] of Object.entries(ui.tabs)) button.attribute('aria-pressed', String(key === name));
    ui.row.style('display', name === 'still' ? 'none' : '');
    ui.workers.style('display', name === 'workers' ? '' : 'none');
    ui.stats.style('display', name === 'still' ? 'none' : '');
    say(ui.error, '');
    frames = 0;
    stamps = [];
    workerFrame = null;
    if (name === 'still') {
      play(false);
      view.budgetMs = 8; // traced a little per frame: watch it sharpen
      view.setCamera(stillCamera).setScene(classScene());
    } else {
      view.setCamera(movieCamera);
      showTraced(time);
      play(true);
    }
    ui.note.html(notes[name]);
  }

  function play(on) {
    playing = on;
    ui.pause.html(on ? 'Pause' : 'Play');
    if (on) {
      animation.rendering();
      ui.note.html(notes[example]);
    } else if (!inFlight) paused();
  }

  /** The frame on screen is final: let the inspector explain it, and the page say "done". */
  function paused() {
    if (example === 'workers' && workerFrame) {
      showTraced(shown); // the same frame on one thread, so the inspector knows its scene…
      const same = workerFrame.every((byte, i) => byte === view.renderer.buffer[i]);
      blit(workerFrame); // …but what stays on screen is the workers' picture
      ui.note.html(`Paused. Traced again on one thread, this frame is ${same ? 'the same, byte for byte ✓' : 'DIFFERENT ✗'}`);
    } else if (example === 'animated') {
      ui.note.html('Paused: click a pixel of this frame to see its story.');
    }
    showStats();
    animation.done();
  }

  /** Traces the frame of time t whole, now, on this thread (the view's own renderer). */
  function showTraced(t) {
    view.budgetMs = 60_000; // no slicing: the whole frame in one go
    view.setScene(sceneAt(t));
    view.draw();
    shown = t;
  }

  async function renderOnWorkers(t) {
    if (parallel?.workers !== workerCount) {
      parallel?.terminate();
      parallel = new ParallelRenderer({ workers: workerCount });
    }
    inFlight = true;
    try {
      const buffer = await parallel.render(sceneAt(t), movieCamera);
      if (example === 'workers') {
        workerFrame = buffer;
        blit(buffer);
        counted(t);
      }
    } catch (error) {
      say(ui.error, String(error.message ?? error));
      play(false);
    } finally {
      inFlight = false;
      if (!playing) paused();
    }
  }

  function blit(buffer) {
    view.canvas.getContext('2d').putImageData(new ImageData(buffer, MOVIE.width, MOVIE.height), 0, 0);
  }

  /** One more frame on screen, made for time t: count it for the FPS. */
  function counted(t) {
    shown = t;
    frames++;
    const now = performance.now();
    stamps = [...stamps.filter((s) => now - s < 1000), now];
    showStats();
  }

  function showStats() {
    const span = stamps.length > 1 ? stamps.at(-1) - stamps[0] : 0;
    const fps = span > 0 ? ((stamps.length - 1) * 1000) / span : 0;
    const by = example === 'workers' ? `${workerCount} worker${workerCount > 1 ? 's' : ''}` : 'main thread';
    ui.stats.html(`frame ${frames} · ${fps.toFixed(1)} FPS · t = ${shown.toFixed(2)} s · ${by}`);
    Object.assign(ui.stats.elt.dataset, { frame: frames, fps: fps.toFixed(1), time: shown });
  }

  const notes = {
    still: 'The class scene, traced once, coarse to fine. Click a pixel to see its story.',
    animated: 'Every frame is traced whole on the page’s own thread. Pause to click a pixel of the frame.',
    workers: 'The rows of each frame are dealt out to the workers; the page only copies them onto the screen. Pause to click a pixel.',
  };

  /** Writes a message as plain text (it may quote what someone typed). */
  function say(element, text) {
    element.elt.textContent = text;
  }

  /** Buttons for the three examples, Pause, the worker-count box and the lines under the picture. */
  function controls(column) {
    const tabs = {};
    const bar = p.createDiv().addClass('tabs').parent(column);
    for (const name of EXAMPLES) {
      tabs[name] = p.createButton(name).addClass('rt-button').parent(bar).attribute('data-example', name);
      tabs[name].mouseClicked(() => choose(name));
    }
    const row = p.createDiv().addClass('controls').parent(column);
    const pause = p.createButton('Pause').addClass('rt-button').parent(row).attribute('data-pause', '');
    pause.mouseClicked(() => play(!playing));
    const workers = p.createElement('label', 'workers (1–8) ').parent(row);
    const countBox = p.createInput(String(WORKERS), 'number').attribute('min', '1').attribute('max', '8').parent(workers);
    const countError = p.createSpan('').addClass('error').attribute('role', 'alert').attribute('data-error', 'workers').parent(row);
    countBox.changed(() => {
      const typed = countBox.value().trim(), n = Number(typed);
      if (typed === '' || !Number.isInteger(n) || n < 1 || n > 8) {
        say(countError, `workers must be a whole number from 1 to 8, got ${typed ? `"${typed}"` : 'nothing'}; still using ${workerCount}.`);
      } else {
        say(countError, '');
        workerCount = n;
      }
    });
    const error = p.createP('').addClass('error').attribute('role', 'alert').attribute('data-error', 'example').parent(column);
    const stats = p.createP('').addClass('stats').attribute('data-stats', '');
    const note = p.createP('').addClass('about');
    return { tabs, row, pause, workers, stats, note, error };
  }
}, document.getElementById('sketch'));
