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
import { createTracerView, createInspector, Animation, workerCountBox } from '../lib/p5/index.js';

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
  let view, ui, movie, example = 'still';

  p.setup = () => {
    p.noCanvas();
    const column = p.createDiv().addClass('column');
    ui = controls(column);
    view = createTracerView(p, { scene: classScene(), camera: stillCamera, parent: column });
    // The animation: sceneAt(t) traced whole each frame, on this thread or over the workers, counted for the FPS.
    movie = new Animation(view, {
      sceneAt, camera: movieCamera, workers: WORKERS, stats: ui.stats,
      onPlay: (on) => {
        ui.pause.html(on ? 'Pause' : 'Play');
        if (on) ui.note.html(notes[example]);
      },
      onPause: ({ same }) => ui.note.html(same === undefined ? 'Paused: click a pixel of this frame to see its story.'
        : `Paused. Traced again on one thread, this frame is ${same ? 'the same, byte for byte ✓' : 'DIFFERENT ✗'}`),
      onError: (error) => say(ui.error, String(error.message ?? error)),
    });
    const { label, message } = workerCountBox(movie); // "workers (1–8)", a message when the count is bad
    ui.row.elt.append(label, message);
    ui.workers = label;
    ui.stats.parent(column);
    ui.note.parent(column);
    createInspector({ view, parent: p._userNode });
    window.sketch = { sceneAt, camera: movieCamera }; // try sketch.sceneAt(3) in the browser console

    const asked = new URLSearchParams(location.search).get('example') ?? 'still';
    choose(EXAMPLES.includes(asked) ? asked : 'still');
    if (!EXAMPLES.includes(asked)) say(ui.error, `example must be ${EXAMPLES.join(', ')}; got "${asked}", so here is the still scene.`);
  };

  p.draw = () => movie.tick(p.deltaTime);

  /** Shows one example: the still scene, or the animation (main thread or workers), playing. */
  function choose(name) {
    example = name;
    for (const [key, button] of Object.entries(ui.tabs)) button.attribute('aria-pressed', String(key === name));
    ui.row.style('display', name === 'still' ? 'none' : '');
    ui.workers.style.display = name === 'workers' ? '' : 'none';
    ui.stats.style('display', name === 'still' ? 'none' : '');
    say(ui.error, '');
    if (name === 'still') {
      movie.stop();
      view.budgetMs = 8; // traced a little per frame: watch it sharpen
      view.setCamera(stillCamera).setScene(classScene());
    } else movie.start(name === 'animated' ? 'main' : 'workers');
    ui.note.html(notes[name]);
  }

  const notes = {
    still: 'The class scene, traced once, coarse to fine. Click a pixel to see its story.',
    animated: 'Every frame is traced whole on the page’s own thread. Pause to click a pixel of the frame.',
    workers: 'The rows of each frame are dealt out to the workers; the page only copies them onto the screen. Pause to click a pixel.',
  };

  /** Writes a message as plain text (it may quote what someone typed). */
  function say(element, message) {
    element.elt.textContent = message;
  }

  /** Buttons for the three examples and Pause, and the lines under the picture. */
  function controls(column) {
    const tabs = {};
    const bar = p.createDiv().addClass('tabs').parent(column);
    for (const name of EXAMPLES) {
      tabs[name] = p.createButton(name).addClass('rt-button').parent(bar).attribute('data-example', name);
      tabs[name].mouseClicked(() => choose(name));
    }
    const row = p.createDiv().addClass('controls').parent(column);
    const pause = p.createButton('Pause').addClass('rt-button').parent(row).attribute('data-pause', '');
    pause.mouseClicked(() => movie.play(!movie.playing));
    const error = p.createP('').addClass('error').attribute('role', 'alert').attribute('data-error', 'example').parent(column);
    const stats = p.createP('').addClass('stats').attribute('data-stats', '');
    const note = p.createP('').addClass('about');
    return { tabs, row, pause, stats, note, error };
  }
}, document.getElementById('sketch'));
