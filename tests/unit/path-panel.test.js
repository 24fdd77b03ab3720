// The path panel's 3D segments: a path from the eye, hit to hit, on toward the sky, coloured by the throughput it carries.
import { describe, it, expect } from 'vitest';
import { Scene, Sphere, Plane, Camera, inspectPath } from '../../lib/index.js';
import { pathRays } from '../../lib/p5/pixel/path-panel.js';

describe('pathRays', () => {
  it('one segment per bounce, from the eye, joined end to end, the last toward the sky when the path left', () => {
    const scene = new Scene({ background: [0.6, 0.6, 0.6] })
      .add(new Plane([0, -1, 0], [0, 1, 0], { color: [0.8, 0.3, 0.3] }))
      .add(new Sphere([0, 0, -8], 1, { color: [0.3, 0.3, 0.9] }));
    const camera = new Camera({ width: 16, height: 12, pitch: -20 });
    const path = inspectPath(scene, camera, 8, 9, { sample: 2 });
    const rays = pathRays(path);
    expect(path.end).toBe('sky');
    expect(rays).toHaveLength(path.bounces.length + 1);
    expect(rays[0].from).toEqual(path.ray.origin);
    path.bounces.forEach((b, i) => {
      expect(rays[i].to).toEqual(b.point);
      expect(rays[i + 1].from).toEqual(b.point);
    });
    expect(rays[0].color).toBe('rgb(255, 255, 255)'); // the eye's ray carries everything
    expect(rays[1].color).toMatch(/^rgb\(255, \d+, \d+\)$/); // after the red floor: red the strongest
    expect(rays[1].weight).toBeLessThan(rays[0].weight);
  });
});

describe('a path-traced view and the GPU engine', () => {
  // The GPU path traces too (lib/p5/tracer/gpu-path-renderer.js, tested in Chromium by tests/e2e/gpu-paths.spec.js);
  // here in Node there is no WebGL2, so the view stays on the CPU and says why.
  it('without WebGL2 stays on the CPU, path tracing, and says why', async () => {
    const { engineRenderer } = await import('../../lib/p5/tracer/engines.js');
    const { PathProgressiveRenderer } = await import('../../lib/tracing/pathtrace/progressive.js');
    const scene = new Scene({ background: [0.5, 0.5, 0.5] }).add(new Sphere([0, 0, -8], 1));
    const paths = new PathProgressiveRenderer({ scene, camera: new Camera({ width: 8, height: 6 }), path: { samples: 2 } });
    const asked = engineRenderer('gpu', paths, { budgetMs: 8, shader: undefined, shaded: true });
    expect(asked).toEqual({ renderer: paths, engine: 'cpu', why: 'the GPU engine needs WebGL2: there is no canvas here (a browser is needed)' });
    expect(engineRenderer('cpu', paths, { budgetMs: 8, shader: undefined, shaded: true })).toEqual({ renderer: paths, engine: 'cpu', why: null });
  });
});
