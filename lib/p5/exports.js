/**
 * The names the p5 adapter exports, in a module of their own below its entry
 * point: the entry (index.js) registers the addon, installs the page's error
 * panel and hands these names on; the panel's "did you mean …" hints
 * (mistake-hints.js) read them here, so nothing the panel loads imports the
 * entry that installs it (no circle of imports).
 */
export { sketchbookAddon, FACTORIES } from './addon.js';
export { TracerView } from './tracer/view.js';
export { orbit } from './tracer/gpu-orbit.js'; // turn a view's camera about the point it looks at (as a drag on a GPU view does)
export { SceneView } from './scene-view/view.js';
export { PhotonView } from './tracer/photon-view.js';
export { Inspector, answerLine } from './pixel/inspector.js';
export { formatAngle, formatLabel, fmt } from '../text/format.js';
export { SceneAnimation } from './controls/animation.js';
export { exampleInLink } from './controls/example-picker.js';
export { pageRenderState } from './page/page-state.js';
// A scene in the page's link (#scene=…), page parts built from text (never parsed as HTML), text to the clipboard:
export { readSceneLink, sceneLinkURL, linkNotice } from './page/scene-link.js';
export { element, copyText } from './dom.js';
// A part of the page's one voice for screen readers: said with the pixel, once the keys rest.
export { createAnnouncer } from './page/announce.js';
export { showInBox, downloadText } from './controls/text-box.js';
