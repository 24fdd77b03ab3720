import { describe, it, expect } from 'vitest';
import { FrameView } from '../../editor/page-judge.js';
import { sceneToJSON, cameraToJSON } from '../../lib/scene/json.js';
import { trafficSignalScene, trafficSignalCamera, checkTrafficSignal, checkRearLights, inspectPixel, Sphere } from '../../lib/index.js';
import { HOMEWORK_CHECKS } from '../../lib/lesson/homework.js';
import { MAX_SCENE_OBJECTS } from '../../lib/scene/codec.js';

const signal = (...lights) => {
  const scene = trafficSignalScene();
  for (const [y, emission] of lights) scene.add(new Sphere([0, y, -15.9], 0.45, { color: [0, 0, 0], emission }));
  return scene;
};
const message = (scene, camera = trafficSignalCamera()) => ({ type: 'scene', scene: JSON.stringify(sceneToJSON(scene)), camera: JSON.stringify(cameraToJSON(camera)), mode: 'shaded', order: 'coarse', problem: null });
const RIGHT = signal([6.5, [1, 0, 0]], [5.4, [1, 0.85, 0]], [4.3, [0, 1, 0.2]]);

describe('FrameView: the page reads what the frame\'s code built, and judges it itself', () => {
  it('reads the scene and camera with the library\'s checked reader: the self-check passes on the scene the page read', () => {
    const view = new FrameView();
    view.read(message(RIGHT));
    expect(view.problem).toBeNull();
    expect(view.scene.objects).toHaveLength(RIGHT.objects.length);
    expect(view.camera.width).toBe(trafficSignalCamera().width);
    expect(HOMEWORK_CHECKS).toEqual({ '08': checkTrafficSignal, '09': checkRearLights }); // the page's own check, whatever the code names
    expect(HOMEWORK_CHECKS['08'](view.scene, view.camera).passed).toBe(true);
    view.read(message(signal([6.5, [1, 0, 0]])));
    expect(checkTrafficSignal(view.scene, view.camera).passed).toBe(false);
  });

  it('names what is wrong in a scene it cannot read, and keeps no scene then', () => {
    const view = new FrameView();
    view.read(message(RIGHT));
    view.read({ ...message(RIGHT), scene: '{"objects": [' });
    expect(view.problem).toMatch(/^The scene your code built could not be read: scene is not valid JSON/);
    expect(view.scene).toBeNull();
    view.read({ ...message(RIGHT), scene: '{"objects":[{"type":"sphere","center":[0,0,-5],"radius":-1}]}' });
    expect(view.problem).toContain('objects[0].radius');
    const many = JSON.stringify({ objects: Array.from({ length: MAX_SCENE_OBJECTS + 1 }, () => ({ type: 'sphere', center: [0, 0, -5], radius: 1 })) });
    view.read({ ...message(RIGHT), scene: many });
    expect(view.problem).toContain(`more than the ${MAX_SCENE_OBJECTS.toLocaleString('en')}`);
    view.read({ ...message(RIGHT), camera: '{"width":0,"height":3}' });
    expect(view.problem).toContain('width');
    view.read({ ...message(RIGHT), scene: `${'['.repeat(100)}${']'.repeat(100)}` });
    expect(view.problem).toContain('nested more than');
    view.read({ type: 'scene', scene: null, camera: null, problem: 'scene objects must be spheres' });
    expect(view.problem).toBe('The scene your code built could not be sent to the page: scene objects must be spheres');
  });

  it('passes on a pixel the frame selected only when it is a pixel of the camera read; its record is the page\'s own', () => {
    const view = new FrameView();
    const heard = [];
    view.onSelect((pixel) => heard.push(pixel));
    view.select(3, 4);
    view.read(message(RIGHT));
    view.select(80, 20);
    view.select(5_000, 0);
    view.select(null, null);
    expect(heard).toEqual([null, { x: 80, y: 20 }, null, null]);
    expect(inspectPixel(view.scene, view.camera, 80, 20).color).toEqual(inspectPixel(RIGHT, trafficSignalCamera(), 80, 20).color);
  });
});
