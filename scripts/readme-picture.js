/**
 * Writes docs/class-scene.png, the README's picture: the class scene traced
 * by the library in Node (npm run build does not need it; run by hand).
 */
import { writeFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import { Camera, classScene, render } from '../lib/index.js';

const camera = new Camera({ width: 640, height: 480, fov: 30 });
const png = new PNG({ width: camera.width, height: camera.height });
png.data = Buffer.from(render(classScene(), camera));
writeFileSync('docs/class-scene.png', PNG.sync.write(png));
console.log('docs/class-scene.png written');
