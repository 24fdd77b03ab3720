/**
 * The server's own verdict on an answer of the pink-pixel activity (sketch
 * 04): the pixel's ray traced again in the class scene with the student's
 * camera, and judged by lib/lesson/activity.js, as the page does. The page's verdict
 * is never taken on trust.
 */
import { Camera, classScene, inspectPixel, pinkPixelVerdict, answerText, toHex } from '../../lib/index.js';

const scene = classScene();

/**
 * @param {{ x: number, y: number, h: number, v: number, width: number, height: number, fov: number }} answer checked values
 * @returns {{ verdict: 'right'|'wrong', color: string, colorName: string, line: string }}
 */
export function judgeAnswer({ x, y, h, v, width, height, fov }) {
  const camera = new Camera({ width, height, fov, yaw: h, pitch: v });
  const record = inspectPixel(scene, camera, x, y);
  const { pink, colorName } = pinkPixelVerdict(record);
  return { verdict: pink ? 'right' : 'wrong', color: toHex(record.color), colorName, line: answerText({ x, y, h, v }) };
}
