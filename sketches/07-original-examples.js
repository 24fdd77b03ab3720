/**
 * 07 · The original examples (slide "Javascript Ray Tracer — out of the box"):
 * the class library's three examples on one page.
 *   still     the class scene, traced once, 160 × 120 big pixels;
 *   original  the same at the class library's own size, 640 × 480 (its example
 *             1), traced progressively so the page answers clicks as it sharpens;
 *   animated  the spheres circle the pink one; each frame is traced whole on
 *             the main thread, and an FPS counter says how many per second;
 *   workers   the same frames shared out over Web Workers (ParallelRenderer):
 *             the main thread only copies finished rows onto the screen.
 * Choose one with the buttons, or open the page with ?example=animated.
 */
import p5 from 'p5';
import { Camera, classScene, classSceneAt } from '../lib/index.js';
import { exampleInLink } from '../lib/p5/index.js'; // and the sketchbook's p5 addon: p.createTracerView, …

const STILL = { width: 160, height: 120 };   // traced pixels of the still scene
const ORIGINAL = { width: 640, height: 480 }; // of example 1 as the class library drew it
const MOVIE = { width: 320, height: 240 };   // of each animation frame: bigger frames, more work to share
const SECONDS_PER_TURN = 12;                 // the spheres circle the pink one this fast
const WORKERS = 4;                           // worker count at first (the box takes 1–8)
const EXAMPLES = { // the note under the picture; an animation's frames are traced on `thread`
  still: { note: 'The class scene, traced once, coarse to fine. Click a pixel to see its story.' },
  original: { label: '640×480', note: 'Example 1 at the class library’s own size, 640 × 480: traced a little each frame, coarse to fine. Click a pixel to see its story.' },
  animated: { thread: 'main', note: 'Every frame is traced whole on the page’s own thread. Pause to click a pixel of the frame.' },
  workers: { thread: 'workers', note: 'The rows of each frame are dealt out to the workers; the page only copies them onto the screen. Pause to click a pixel.' },
};

/** The class scene t seconds in: yellow, blue and white have turned about the pink sphere. */
const sceneAt = (t) => classSceneAt(t, SECONDS_PER_TURN);

new p5((p) => {
  const stillCamera = new Camera(STILL), originalCamera = new Camera(ORIGINAL), movieCamera = new Camera(MOVIE);
  let view, movie;

  p.setup = () => {
    p.noCanvas();
    const column = p.createDiv().addClass('column');
    const picker = p.createExamplePicker({ parent: column, examples: EXAMPLES, onChoose: choose }); // a button per example
    view = p.createTracerView({ scene: classScene(), camera: stillCamera, parent: column });
    // The animation: sceneAt(t) traced whole each frame, on this thread or over the workers, counted for the FPS.
    movie = p.createAnimation({ view, sceneAt, camera: movieCamera, workers: WORKERS });
    picker.attach(movie); // Pause, the worker count, the frame counter
    p.createInspector({ view, parent: 'sketch' });
    window.sketch = { sceneAt, camera: movieCamera }; // try sketch.sceneAt(3) in the browser console

    const { name, problem } = exampleInLink(location.search, EXAMPLES); // ?example=animated
    picker.choose(name);
    picker.say(problem);
    p.createTaskList({ page: '07', view, parts: { animation: movie } }); // the page's tasks, ticked off as they are done
  };

  p.draw = () => movie.tick(p.deltaTime);

  /** Shows one example: the animation, playing on its thread, or the still scene, traced once. */
  function choose(name, { thread }) {
    if (thread) return movie.start(thread);
    movie.stop();
    view.budgetMs = 8; // traced a little per frame: watch it sharpen
    view.setCamera(name === 'original' ? originalCamera : stillCamera).setScene(classScene());
  }
}, document.getElementById('sketch'));
