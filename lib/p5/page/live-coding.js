/**
 * Live coding in class, for every sketch that imports lib/p5: a mistake is
 * shown on the page (error-panel.js) over the last good picture
 * (last-picture.js), and a save's reload keeps the page's place
 * (keep-place.js). Each installs itself on import.
 */
import './error-panel.js';
import './keep-place.js';
import './last-picture.js';
