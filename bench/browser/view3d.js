/**
 * The 3D scene view's costs, for bench/browser.js section 5:
 *   window.bench.trace(n): n progressive traces of the class scene at 640×480
 *     (coarse, 8 ms budget), each from restart() to done, in ms — with
 *     ?view3d=1 a 3D view (with a selected pixel) follows the picture;
 *   window.bench.turn(ms): turns the 3D view a little every animation frame
 *     for `ms`; frames per second and the median time of a draw's own work.
 */
import p5 from 'p5';
import { Camera, classScene } from '../../lib/index.js';
import '../../lib/p5/index.js';

const withView = new URLSearchParams(location.search).get('view3d') === '1';
const bench = (window.bench = {});

new p5((p) => {
  p.setup = () => {
    p.noCanvas();
    const view = p.createTracerView({ scene: classScene(), camera: new Camera({ width: 640, height: 480 }), scale: 1 });
    view.select(320, 240);
    const sceneView = withView ? p.createSceneView({ view }) : null;
    const done = () => new Promise((resolve) => {
      const check = () => (view.done ? resolve() : requestAnimationFrame(check));
      check();
    });

    bench.trace = async (n) => {
      const times = [];
      for (let i = 0; i < n; i++) {
        await done();
        const start = performance.now();
        view.restart();
        await done();
        times.push(performance.now() - start);
      }
      return times;
    };

    bench.turn = async (ms) => {
      await done();
      await sceneView.ready;
      const draws = [];
      let frames = 0;
      const start = performance.now();
      await new Promise((resolve) => {
        const tick = () => {
          if (frames > 0) draws.push(sceneView.lastDrawMs);
          if (performance.now() - start >= ms) return resolve();
          sceneView.setOrbit({ yaw: sceneView.orbit.yaw + 1.5 });
          frames++;
          requestAnimationFrame(tick);
        };
        tick();
      });
      draws.sort((a, b) => a - b);
      return { fps: (frames * 1000) / (performance.now() - start), drawMs: draws[draws.length >> 1] };
    };
    bench.ready = true;
  };
}, document.getElementById('sketch'));
