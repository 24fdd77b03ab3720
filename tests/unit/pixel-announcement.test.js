// The one line a screen reader hears for a selected pixel names the shape as the panel does:
// its own name, else its kind and its number counted from 1 ("sphere 1"), never the index from 0.
import { describe, it, expect } from 'vitest';
import { Scene, Sphere, Plane, PointLight, AreaLight, SpotLight, Camera, classScene, inspectPixel } from '../../lib/index.js';
import { pixelAnnouncement } from '../../lib/p5/pixel/inspector.js';

const camera = new Camera({ width: 32, height: 24 });

describe('pixelAnnouncement', () => {
  it('says "the sphere 1" for the first unnamed sphere, as the panel and its CSV name it', () => {
    const scene = new Scene().add(new Sphere([0, 0, -20], 4, { color: 'pink' })).add(new PointLight([-10, 20, 0]));
    const r = inspectPixel(scene, camera, 16, 12);
    expect(r.hit.name).toBe('sphere 1');
    expect(pixelAnnouncement(r)).toMatch(/, the sphere 1\.$/);
  });

  it('counts per kind: an unnamed sphere after an unnamed plane is still "sphere 1"', () => {
    const scene = new Scene().add(new Plane([0, -30, 0], [0, 1, 0])).add(new Sphere([0, 0, -20], 4)).add(new PointLight([-10, 20, 0]));
    expect(pixelAnnouncement(inspectPixel(scene, camera, 16, 12))).toMatch(/, the sphere 1\.$/);
  });

  it('keeps a shape\'s own name, and a colour name before its kind', () => {
    const named = (name) => new Scene().add(new Sphere([0, 0, -20], 4, { name })).add(new PointLight([-10, 20, 0]));
    expect(pixelAnnouncement(inspectPixel(named('pink'), camera, 16, 12))).toMatch(/, the pink sphere\.$/);
    expect(pixelAnnouncement(inspectPixel(named('moon'), camera, 16, 12))).toMatch(/, the moon\.$/);
  });

  // What a task asks of a pixel that only the picture showed: the shadows (06, 14), the spot's cone (14), an edge (11).
  const lit = () => new Scene({ background: [0.5, 0.7, 1] })
    .add(new Plane([0, -4, 0], [0, 1, 0], { color: [0.85, 0.85, 0.85], name: 'floor' }))
    .add(new Sphere([2, -1, -20], 3, { color: [1, 0.32, 0.36], name: 'pink ball' }));
  const eye = new Camera({ width: 48, height: 36 });
  const every = (scene, camera = eye) => {
    const out = [];
    for (let y = 0; y < camera.height; y += 2) for (let x = 0; x < camera.width; x += 2) out.push(pixelAnnouncement(inspectPixel(scene, camera, x, y)));
    return out;
  };

  it('says the penumbra and the full shadow of an area light by its shadow rays, and nothing of a light that reaches the point whole', () => {
    const said = every(lit().add(new AreaLight([4, 10, -12], 2, { samples: 16, intensity: 0.8, name: 'disc' })));
    const penumbra = said.filter((t) => /; in the penumbra of disc: ([1-9]|1[0-5]) of 16 shadow rays reach it\.$/.test(t));
    expect(penumbra.length).toBeGreaterThan(0);
    expect(said.some((t) => /the floor; in the full shadow of disc: none of its 16 shadow rays reach it\.$/.test(t))).toBe(true);
    expect(said.some((t) => /, the floor\.$/.test(t))).toBe(true); // lit whole: no more words
    expect(said.some((t) => /16 of 16/.test(t))).toBe(false);
    for (const t of said) expect(t.split(/\s+/).length).toBeLessThanOrEqual(40);
  });

  it('says a point light\'s shadow and a spot\'s cone, by the lights\' names', () => {
    const said = every(lit()
      .add(new PointLight([4, 10, -12], { name: 'bulb' }))
      .add(new SpotLight([-7, 12, -18], [-7, -4, -23], { angle: 20, name: 'spot' })));
    expect(said.some((t) => /the floor; (outside the cone of spot; )?in the shadow of bulb\.$/.test(t))).toBe(true);
    expect(said.some((t) => /the floor; outside the cone of spot\.$/.test(t))).toBe(true);
    expect(said.some((t) => /, the floor\.$/.test(t))).toBe(true); // in the spot's cone and the bulb's light
  });

  it('says an edge when a pixel\'s rays hit different things, with the shapes named as the sentence names them', () => {
    const said = every(classScene(), new Camera({ width: 64, height: 48, samples: 4 }));
    const edges = said.filter((t) => /; an edge: of its 4 rays, \d hit the [a-z ]+, \d (the [a-z ]+|nothing)/.test(t));
    expect(edges.length).toBeGreaterThan(0);
    expect(edges.some((t) => /the pink sphere/.test(t))).toBe(true); // "pink" is the pink sphere, as the hit is said
    const one = said.filter((t) => !/an edge/.test(t));
    expect(one.length).toBeGreaterThan(edges.length); // most pixels' rays all hit one thing: no more words
  });
});
