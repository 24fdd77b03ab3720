/**
 * A tracer view's check of its scene before it traces it again or inspects a
 * pixel of it: a sketch may have broken the scene since it was built (a
 * radius set to NaN, null pushed into scene.lights). The page then says what
 * is wrong in the mistake panel, with the sketch's line, and the view
 * changes nothing: the last good picture stays, nothing is thrown into the
 * sketch's draw() and nothing reaches the console.
 */
import { Scene } from '../../scene/scene.js';
import { checkScene } from '../../scene/check.js';

/**
 * True when `scene` holds as it is now (lib/scene/check.js), or is no Scene
 * at all (the renderer's own TypeError is for the caller); else false, the
 * mistake shown on the page.
 * @param {any} scene
 * @returns {boolean}
 */
export function sceneHolds(scene) {
  if (!(scene instanceof Scene)) return true;
  try {
    checkScene(scene);
    return true;
  } catch (error) {
    if (!(error instanceof TypeError || error instanceof RangeError)) throw error;
    import('./error-panel.js').then((panel) => panel.showError(error)); // loaded here, not above: importing the view touches no page
    return false;
  }
}
