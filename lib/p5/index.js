/**
 * The p5 adapter of the Raytracing Sketchbook, a p5 addon (2.x; 1.11 too). Importing it
 * registers the addon: every sketch then has the kit's factories as methods,
 *
 *   p.createTracerView({ scene, camera })   the traced picture, progressive, clickable
 *   p.createInspector({ view })             the whole story of the selected pixel
 *   p.drawSideView({ … }) and the other diagrams, the controls of the lesson's pages
 *
 * (the full list: FACTORIES in ./addon.js; in global mode the same names are
 * bare functions). The only part of lib/ that imports p5.
 */
import { sketchbookAddon } from './addon.js';
import { registerAddon } from './register.js';
import './page/live-coding.js'; // mistakes shown on the page (data-error); a save's reload keeps the page's place

registerAddon(sketchbookAddon); // p5.registerAddon on 2.x; on 1.x, p5.prototype and registerMethod

export * from './exports.js'; // every name the addon exports, listed there (the mistake hints read them without loading this entry)
