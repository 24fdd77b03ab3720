/**
 * The selected pixel in words: its answer line and the one short sentence a
 * screen reader hears for it (lib/p5/page/announce.js says it once the arrow key
 * rests). Besides the colour and what the ray hit, the sentence says what a
 * task may ask of the pixel and only a picture would show: a light it is cut
 * off from (a shadow, outside a spot's cone), how many of an area light's
 * shadow rays reach it (the penumbra), and an edge where its rays hit
 * different things.
 */
import { kindOf } from '../../shapes/index.js';
import { colorName } from '../../math/color.js';
import { formatAngle } from '../../text/format.js';
import { shownName } from '../dom.js';

/**
 * The lesson's answer format for a pixel's own ray, one decimal: `Pixel: 10,12; H: -1.9; V: 3.2`.
 * @example
 * answerLine({ x: 10, y: 12, h: -1.94, v: 3.21 }); // 'Pixel: 10,12; H: -1.9; V: 3.2'
 */
export function answerLine({ x, y, h, v }) {
  return `Pixel: ${x},${y}; H: ${formatAngle(h)}; V: ${formatAngle(v)}`;
}

/**
 * What a screen reader says of a selected pixel: its answer line, its colour
 * name and what its ray hit, then its lights and rays where they tell more.
 * @example
 * pixelAnnouncement(inspectPixel(classScene(), camera, 11, 12)); // 'Pixel: 11,12; H: -5.7; V: -0.6. Pink, the pink sphere.'
 */
export function pixelAnnouncement(r) {
  const name = colorName(r.color);
  const hit = r.hit ? `the ${hitName(r.hit)}` : 'no hit, the background';
  const more = [...lightWords(r.hit), edgeWords(r)].filter(Boolean);
  return `${answerLine(r)}. ${name.charAt(0).toUpperCase()}${name.slice(1)}, ${hit}${more.map((m) => `; ${m}`).join('')}.`;
}

/** "pink sphere" for a sphere named pink; "ground" for one named ground; "sphere 2" for one with no name (the panel's name, from 1). */
function hitName(hit) {
  const kind = kindOf(hit.object);
  const name = shownName(hit.object?.name?.trim() ?? '');
  if (!name) return hit.name;
  return /^(pink|red|orange|yellow|green|cyan|blue|purple|white|gray|grey|black|brown)$/i.test(name) ? `${name} ${kind}` : name;
}

/**
 * The lights a hit point does not simply get, as the panel's Lights rows say
 * them: `in the shadow of bulb`, `outside the cone of spot`, `in the penumbra
 * of disc: 5 of 16 shadow rays reach it`. A light it faces away from is its
 * dark side, said by the colour; a light that reaches it whole, nothing.
 */
function lightWords(hit) {
  if (!hit) return [];
  const grouped = new Set((hit.areaLights ?? []).flatMap((g) => g.indices));
  const words = [];
  hit.lights.forEach((l, i) => {
    if (grouped.has(i) || !l.facing) return;
    const light = lightName(l.light, `light ${i + 1}`);
    if (l.beam === 0) words.push(`outside the cone of ${light}`);
    else if (l.inShadow) words.push(`${l.transmission > 0 ? 'partly in the shadow' : 'in the shadow'} of ${light}`);
  });
  (hit.areaLights ?? []).forEach((g, a) => {
    if (g.reached === g.samples || !g.rays.some((l) => l.facing)) return;
    const light = lightName(g.light, `area light ${a + 1}`);
    if (g.samples === 1) words.push(`in the shadow of ${light}`);
    else if (g.reached === 0) words.push(`in the full shadow of ${light}: none of its ${g.samples} shadow rays reach it`);
    else words.push(`in the penumbra of ${light}: ${g.reached} of ${g.samples} shadow rays reach it`);
  });
  return words.slice(0, 3); // the sentence stays short: the panel's table has them all
}

const lightName = (light, fallback) => (light?.name ? shownName(light.name) : fallback);

/** Several rays per pixel that do not all hit one thing: `an edge: of its 4 rays, 3 hit the pink sphere, 1 nothing`. */
function edgeWords({ samples, records = [] }) {
  if (!samples) return '';
  const counts = new Map();
  for (const s of samples) counts.set(s.hit, (counts.get(s.hit) ?? 0) + 1);
  if (counts.size < 2) return '';
  const said = (what) => {
    const object = records.find((e) => e.name === what)?.object; // a ray's hit is the shape's name: "pink" is the pink sphere
    return what === null ? 'nothing' : `the ${object ? hitName({ object, name: what }) : shownName(what)}`;
  };
  const parts = [...counts].sort((a, b) => b[1] - a[1]).slice(0, 3).map(([what, n], i) => `${n} ${i === 0 ? 'hit ' : ''}${said(what)}`);
  return `an edge: of its ${samples.length} rays, ${parts.join(', ')}`;
}
