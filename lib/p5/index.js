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
import './live-coding.js'; // mistakes shown on the page (data-error); a save's reload keeps the page's place

registerAddon(sketchbookAddon); // p5.registerAddon on 2.x; on 1.x, p5.prototype and registerMethod

export { sketchbookAddon, FACTORIES } from './addon.js';
export { TracerView } from './tracer-view.js';
export { orbit } from './gpu-orbit.js'; // turn a view's camera about the point it looks at (as a drag on a GPU view does)
export { SceneView } from './scene-view.js';
export { PhotonView } from './photon-view.js';
export { Inspector, answerLine } from './inspector.js';
export { formatAngle, formatLabel, fmt } from '../format.js';
export { SceneAnimation } from './animation.js';
export { exampleInLink } from './example-picker.js';
export { pageRenderState } from './page-state.js';
// A scene in the page's link (#scene=…), page parts built from text (never parsed as HTML), text to the clipboard:
export { readSceneLink, sceneLinkURL, linkNotice } from './scene-link.js';
export { element, copyText } from './dom.js';
// A part of the page's one voice for screen readers: said with the pixel, once the keys rest.
export { createAnnouncer } from './announce.js';
export { showInBox, downloadText } from './text-box.js';
