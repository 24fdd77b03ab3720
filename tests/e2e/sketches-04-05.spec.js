// Sketches 04 (find the pink pixel) and 05 (value boxes), used the way a
// student would: type into the boxes, press Check or Enter, click pixels,
// add and remove spheres, share the scene as a link. Bad values must leave
// the traced picture exactly as it was.
import { test, expect } from '@playwright/test';
import { clickPixel, expectQuietConsole, watchConsole, waitForDone } from './helpers.js';
import { Camera, classScene, inspectPixel, colorName } from '../../lib/index.js';

const PINK = '/sketches/04-find-the-pink-pixel.html';
const BOXES = '/sketches/05-value-boxes.html';
const ANSWER = /^Pixel: \d+,\d+; H: -?\d+\.\d; V: -?\d+\.\d$/; // the inspector's: the ray's own angles

expectQuietConsole(test);

async function open(page, url) {
  await page.goto(url);
  await waitForDone(page);
}

/** The traced picture, pixel for pixel, as a PNG data URL. */
const picture = (page) => page.locator('[data-tracer]').evaluate((c) => c.toDataURL('image/png'));

/** Types into a box and presses Enter. */
async function enter(page, name, value) {
  const box = page.locator(`input[name="${name}"]`);
  await box.fill(value);
  await box.press('Enter');
}

/** The colour name of every pixel of the class scene through the sketch's camera (yaw, pitch), by the library itself (as the page runs it). */
function colourNames(yaw = 0, pitch = 0) {
  const camera = new Camera({ width: 32, height: 24, fov: 30, yaw, pitch });
  const scene = classScene();
  const names = [];
  for (let y = 0; y < 24; y++) for (let x = 0; x < 32; x++) names.push({ x, y, name: colorName(inspectPixel(scene, camera, x, y).color) });
  return names;
}

test.describe('04 · Find the pink pixel', () => {
  test('a pink pixel is a right answer; the answer line repeats the values given, the ray\'s own angles are labelled', async ({ page }) => {
    await open(page, PINK);
    const pink = colourNames().filter((p) => p.name === 'pink');
    expect(pink.length).toBeGreaterThan(10);
    const { x, y } = pink[Math.floor(pink.length / 2)];
    await page.locator('input[name="x"]').fill(String(x));
    await page.locator('input[name="y"]').fill(String(y));
    await page.locator('[data-check]').click();
    const result = page.locator('[data-result]');
    await expect(result).toHaveAttribute('data-result', 'pink');
    await expect(result).toContainText('Pink');
    await expect(page.locator('[data-answer-line]')).toHaveText(`Pixel: ${x},${y}; H: 0; V: 0`);
    // The ray's own angles are the inspector's, and the page says they are the ray's.
    const ray = await page.locator('[data-inspector] [data-answer]').textContent();
    expect(ray).toMatch(ANSWER);
    const [, h, v] = /H: (\S+); V: (\S+)$/.exec(ray);
    await expect(page.locator('[data-answer-detail]')).toHaveText(new RegExp(`^The ray through that pixel: H ${h}, V ${v} `));
    await expect(page.locator('[data-inspector]')).toContainText('ray, with its own H and V');
  });

  test('the slide\'s example comes back as typed, with the verdict beside it', async ({ page }) => {
    await open(page, PINK);
    for (const [name, value] of [['x', '10'], ['y', '12'], ['h', '30'], ['v', '-82']]) await page.locator(`input[name="${name}"]`).fill(value);
    await page.locator('[data-check]').click();
    await expect(page.locator('[data-answer-line]')).toHaveText('Pixel: 10,12; H: 30; V: -82');
    const row = page.locator('.answer-row');
    await expect(row.locator('[data-result]')).toHaveAttribute('data-result', /^(pink|not-pink)$/);
    // Beside it: the verdict follows the answer in its row (wrapping below it only when the row is full).
    expect(await page.locator('[data-answer-line]').evaluate((a) => a.nextElementSibling.hasAttribute('data-result'))).toBe(true);
  });

  test('an answer line typed back in gives the same answer line (it did not: the ray\'s angles doubled)', async ({ page }) => {
    await open(page, PINK);
    await clickPixel(page.locator('[data-tracer]'), 14, 9);
    const line = await page.locator('[data-answer-line]').textContent();
    expect(line).toBe('Pixel: 14,9; H: 0; V: 0');
    await page.locator('input[name="h"]').fill('-1.9');
    await page.locator('input[name="v"]').fill('3.2');
    await page.locator('[data-check]').click();
    await expect(page.locator('[data-answer-line]')).toHaveText('Pixel: 14,9; H: -1.9; V: 3.2');
    await page.locator('input[name="h"]').fill('0');
    await page.locator('input[name="v"]').fill('0');
    await page.locator('[data-check]').click();
    await expect(page.locator('[data-answer-line]')).toHaveText(line);
  });

  test('pasting a whole answer line into a box fills all four boxes', async ({ page }) => {
    await open(page, PINK);
    await clickPixel(page.locator('[data-tracer]'), 3, 3);
    const box = page.locator('input[name="h"]');
    await box.focus();
    await box.evaluate((input) => {
      const data = new DataTransfer();
      data.setData('text/plain', 'Pixel: 10,12; H: 30; V: -82');
      input.dispatchEvent(new ClipboardEvent('paste', { clipboardData: data, bubbles: true, cancelable: true }));
    });
    for (const [name, value] of [['x', '10'], ['y', '12'], ['h', '30'], ['v', '-82']]) {
      await expect(page.locator(`input[name="${name}"]`)).toHaveValue(value);
    }
    await page.locator('[data-check]').click();
    await expect(page.locator('[data-answer-line]')).toHaveText('Pixel: 10,12; H: 30; V: -82');
    // An ordinary paste of one number goes into its box alone.
    await page.locator('input[name="x"]').evaluate((input) => {
      const data = new DataTransfer();
      data.setData('text/plain', '7');
      input.dispatchEvent(new ClipboardEvent('paste', { clipboardData: data, bubbles: true, cancelable: true }));
    });
    await expect(page.locator('input[name="y"]')).toHaveValue('12');
  });

  test('near V = ±90 the camera\'s H stays what was typed, and the picture does not jump', async ({ page }) => {
    await open(page, PINK);
    await page.locator('input[name="x"]').fill('10'); // the pixel boxes start empty
    await page.locator('input[name="y"]').fill('12');
    const pixels = (c) => Array.from(c.getContext('2d').getImageData(0, 0, c.width, c.height).data);
    const shots = {};
    for (const v of ['89.9', '90', '-89.9', '-90']) {
      await page.locator('input[name="h"]').fill('30');
      await page.locator('input[name="v"]').fill(v);
      await page.locator('[data-check]').click();
      await expect(page.locator('[data-answer-line]')).toHaveText(`Pixel: 10,12; H: 30; V: ${v}`);
      await waitForDone(page);
      shots[v] = await page.locator('[data-tracer]').evaluate(pixels);
    }
    // A tenth of a degree of V changes a few pixels at most (a 40° turn of H would change most of them).
    const changed = (a, b) => { let n = 0; for (let i = 0; i < a.length; i += 4) if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 30) n++; return n; };
    expect(changed(shots['89.9'], shots['90'])).toBeLessThan(32 * 24 * 0.05);
    expect(changed(shots['-89.9'], shots['-90'])).toBeLessThan(32 * 24 * 0.05);
  });

  test('the boxes keep what was typed until Check: click 3,3, then Tab through 10, 12, 30, -82', async ({ page }) => {
    await open(page, PINK);
    await clickPixel(page.locator('[data-tracer]'), 3, 3);
    await expect(page.locator('[data-answer-line]')).toHaveText(/^Pixel: 3,3;/);
    await page.locator('input[name="x"]').focus();
    await page.keyboard.press('ControlOrMeta+A');
    for (const [i, value] of ['10', '12', '30', '-82'].entries()) {
      if (i > 0) await page.keyboard.press('Tab'); // Tab selects the next box's text: typing replaces it
      await page.keyboard.type(value);
    }
    await page.keyboard.press('Tab'); // leaving V turns the camera, but judges nothing yet
    await waitForDone(page);
    for (const [name, value] of [['x', '10'], ['y', '12'], ['h', '30'], ['v', '-82']]) {
      await expect(page.locator(`input[name="${name}"]`)).toHaveValue(value);
    }
    await page.locator('[data-check]').click();
    await expect(page.locator('[data-answer-line]')).toHaveText(/^Pixel: 10,12;/);
    await expect(page.locator('[data-result]')).not.toContainText('Pixel: 3,3');
    await expect(page.locator('input[name="x"]')).toHaveValue('10');
    await expect(page.locator('input[name="y"]')).toHaveValue('12');
    // The verdict is the library's for pixel 10,12 through the camera typed.
    const expected = colorName(inspectPixel(classScene(), new Camera({ width: 32, height: 24, fov: 30, yaw: 30, pitch: -82 }), 10, 12).color);
    await expect(page.locator('[data-result]')).toHaveAttribute('data-color-name', expected);
  });

  test('a background pixel is not pink, and the page says what it is instead', async ({ page }) => {
    await open(page, PINK);
    await page.locator('input[name="x"]').fill('0');
    await page.locator('input[name="y"]').fill('0');
    await page.locator('[data-check]').click();
    const result = page.locator('[data-result]');
    await expect(result).toHaveAttribute('data-result', 'not-pink');
    await expect(result).toHaveAttribute('data-color-name', 'white');
    await expect(result).toContainText('white');
    await expect(result).toContainText('background');
    await expect(page.locator('[data-answer-line]')).toHaveText(/^Pixel: 0,0; /);
  });

  test('the shaded side of the pink sphere is on the sphere but not pink', async ({ page }) => {
    await open(page, PINK);
    const names = colourNames();
    const dark = names.find((p) => p.name === 'red');
    await page.locator('input[name="x"]').fill(String(dark.x));
    await page.locator('input[name="y"]').fill(String(dark.y));
    await page.locator('[data-check]').click();
    await expect(page.locator('[data-result]')).toHaveAttribute('data-color-name', 'red');
    await expect(page.locator('[data-result]')).toContainText('pink sphere');
  });

  test('clicking a pixel fills the boxes and checks it', async ({ page }) => {
    await open(page, PINK);
    await clickPixel(page.locator('[data-tracer]'), 0, 0);
    await expect(page.locator('input[name="x"]')).toHaveValue('0');
    await expect(page.locator('input[name="y"]')).toHaveValue('0');
    await expect(page.locator('[data-result]')).toHaveAttribute('data-result', 'not-pink');
  });

  test('changing the camera\'s H turns the camera: a new picture, traced to the end', async ({ page }) => {
    await open(page, PINK);
    await enter(page, 'x', '10'); // the pixel boxes start empty: an answer first
    await enter(page, 'y', '12');
    const before = await picture(page);
    const answerBefore = await page.locator('[data-answer-line]').textContent();
    const detailBefore = await page.locator('[data-answer-detail]').textContent();
    await enter(page, 'h', '20');
    await waitForDone(page);
    expect(await picture(page)).not.toEqual(before);
    // The answer line says the camera's new H; the same pixel's ray is 20° further right.
    const h = (line) => Number(/H:? (-?[\d.]+)/.exec(line)[1]);
    const answerAfter = await page.locator('[data-answer-line]').textContent();
    expect(h(answerAfter) - h(answerBefore)).toBe(20);
    const rayBefore = h(detailBefore), rayAfter = h(await page.locator('[data-answer-detail]').textContent());
    expect(rayAfter - rayBefore).toBeCloseTo(20, 0);
    // What the page draws is what the library traces through that camera.
    const pink = colourNames(20, 0).filter((p) => p.name === 'pink');
    await page.locator('[data-show-pink]').check();
    await expect(page.locator('[data-pink-count]')).toHaveAttribute('data-pink-count', String(pink.length));
  });

  for (const [name, value, field] of [
    ['x', '40', 'Pixel x'], ['x', '', 'Pixel x'], ['y', 'abc', 'Pixel y'], ['y', '2.5', 'Pixel y'],
    ['h', 'abc', 'Camera H'], ['v', '120', 'Camera V'], ['v', '', 'Camera V'],
  ]) {
    test(`a bad ${field} (${JSON.stringify(value)}) gets a message naming it, and the picture stays`, async ({ page }) => {
      await open(page, PINK);
      const before = await picture(page);
      const answerBefore = await page.locator('[data-answer-line]').textContent();
      await page.locator(`input[name="${name}"]`).fill(value);
      await page.locator('[data-check]').click();
      const message = page.locator(`[data-message-for="${name}"]`);
      await expect(message).toContainText(field);
      await expect(page.locator(`input[name="${name}"]`)).toHaveAttribute('aria-invalid', 'true');
      await expect(page.locator('[data-result]')).toHaveAttribute('data-result', 'error');
      await waitForDone(page);
      expect(await picture(page)).toEqual(before);
      await expect(page.locator('[data-answer-line]')).toHaveText(answerBefore);
      // Fixing the box clears the message.
      await page.locator(`input[name="${name}"]`).fill(name === 'x' || name === 'y' ? '3' : '0');
      await page.locator('[data-check]').click();
      await expect(message).toBeEmpty();
    });
  }

  test('"highlight every pink pixel" marks exactly the pink pixels, over the picture, not in it', async ({ page }) => {
    await open(page, PINK);
    const before = await picture(page);
    const names = colourNames();
    const pink = names.filter((p) => p.name === 'pink');
    await page.locator('[data-show-pink]').check();
    await expect(page.locator('[data-pink-count]')).toHaveAttribute('data-pink-count', String(pink.length));
    await expect(page.locator('[data-pink-count]')).toContainText(`${pink.length} of 768`);
    // The marks canvas: something drawn at the centre of each pink pixel, nothing at the others.
    const marked = await page.locator('[data-pink-marks]').evaluate((c) => {
      const g = c.getContext('2d'), k = c.width / 32, out = [];
      for (let y = 0; y < 24; y++) {
        for (let x = 0; x < 32; x++) if (g.getImageData(Math.floor((x + 0.5) * k), Math.floor((y + 0.5) * k), 1, 1).data[3] > 0) out.push(`${x},${y}`);
      }
      return out;
    });
    expect(marked.sort()).toEqual(pink.map((p) => `${p.x},${p.y}`).sort());
    expect(await picture(page)).toEqual(before);
    await page.locator('[data-show-pink]').uncheck();
    await expect(page.locator('[data-pink-count]')).toBeEmpty();
  });
});

test.describe('05 · Value boxes', () => {
  const radius = 'objects[1].radius'; // the pink sphere's

  test('a good value re-renders the picture and goes into the link', async ({ page }) => {
    await open(page, BOXES);
    const before = await picture(page);
    await enter(page, radius, '6');
    await waitForDone(page);
    expect(await picture(page)).not.toEqual(before);
    await expect(page).toHaveURL(/#scene=z\.[A-Za-z0-9_-]+$/); // compressed, in the fragment (lib/p5/page/scene-link.js)
    await expect(page.locator(`[data-message-for="${radius}"]`)).toBeEmpty();
  });

  for (const [name, value, field] of [
    [radius, '-1', 'radius'], [radius, 'abc', 'radius'], [radius, '', 'radius'],
    ['objects[2].center.0', 'abc', 'centre x'], ['objects[3].material.reflection', '1.5', 'reflection'],
    ['objects[1].material.color', 'pinkish', 'colour'], ['objects[5].material.emission', '-1', 'emission'],
  ]) {
    test(`a bad ${field} (${JSON.stringify(value)}) gets a message naming it, and the picture stays`, async ({ page }) => {
      await open(page, BOXES);
      const before = await picture(page);
      await enter(page, name, value);
      await expect(page.locator(`[data-message-for="${name}"]`)).toContainText(field);
      await expect(page.locator(`input[name="${name}"]`)).toHaveAttribute('aria-invalid', 'true');
      await waitForDone(page);
      expect(await picture(page)).toEqual(before);
      expect(new URL(page.url()).searchParams.get('scene')).toBeNull();
    });
  }

  test('add a sphere, then remove it: the picture comes back exactly', async ({ page }) => {
    await open(page, BOXES);
    const rows = page.locator('[data-table="sphere"] tbody tr');
    await expect(rows).toHaveCount(7);
    const before = await picture(page);
    await page.getByRole('button', { name: 'Add sphere' }).click();
    await expect(rows).toHaveCount(8);
    await waitForDone(page);
    expect(await picture(page)).not.toEqual(before);
    await page.locator('[data-remove="7"]').click();
    await expect(rows).toHaveCount(7);
    await waitForDone(page);
    expect(await picture(page)).toEqual(before);
  });

  test('remove a sphere, add a point light', async ({ page }) => {
    await open(page, BOXES);
    const before = await picture(page);
    await page.locator('[data-remove="1"]').click(); // the pink sphere
    await expect(page.locator('[data-table="sphere"] tbody tr')).toHaveCount(6);
    await expect(page.locator('[data-table="sphere"]')).not.toContainText('pink');
    await waitForDone(page);
    const withoutPink = await picture(page);
    expect(withoutPink).not.toEqual(before);
    await page.getByRole('button', { name: 'Add point light' }).click();
    await expect(page.locator('[data-table="pointLight"] tbody tr')).toHaveCount(1);
    await waitForDone(page);
    expect(await picture(page)).not.toEqual(withoutPink);
  });

  test('the link shares the scene: opening it shows the same values and the same picture', async ({ page, context }) => {
    await open(page, BOXES);
    await enter(page, radius, '6');
    await enter(page, 'objects[1].material.color', '#3366ff');
    await waitForDone(page);
    const shared = await picture(page);
    const link = page.url();

    const other = await context.newPage();
    const otherErrors = watchConsole(other);
    await open(other, link);
    await expect(other.locator(`input[name="${radius}"]`)).toHaveValue('6');
    await expect(other.locator('input[name="objects[1].material.color"]')).toHaveValue('#3366ff');
    expect(await picture(other)).toEqual(shared);
    await expect(other.locator('[data-link-problem]')).toBeEmpty();
    expect(otherErrors).toEqual([]);
  });

  for (const [what, scene] of [
    ['garbage', 'not*base64!'],
    ['a sphere with radius -1', Buffer.from(JSON.stringify({ objects: [{ type: 'sphere', center: [0, 0, -10], radius: -1 }] })).toString('base64url')],
  ]) {
    test(`a bad scene in the link (${what}) says so and shows the class scene`, async ({ page }) => {
      await open(page, BOXES);
      const classPicture = await picture(page);
      await open(page, `${BOXES}?scene=${encodeURIComponent(scene)}`);
      await expect(page.locator('[data-link-problem]')).toContainText('could not be read');
      if (what.includes('radius')) await expect(page.locator('[data-link-problem]')).toContainText('radius');
      await expect(page.locator(`input[name="${radius}"]`)).toHaveValue('4');
      expect(await picture(page)).toEqual(classPicture);
    });
  }

  test('"Copy scene as code" writes code that rebuilds the scene', async ({ page }) => {
    await open(page, BOXES);
    await enter(page, radius, '5');
    await waitForDone(page);
    await page.getByRole('button', { name: 'Copy scene as code' }).click();
    const code = page.locator('[data-scene-code]');
    await expect(code).toBeVisible();
    const text = await code.inputValue();
    expect(text).toContain('new Sphere(');
    expect(text).toContain('new Sphere([0, 0, -20], 5,');
    expect(text).toContain("from '../lib/index.js'");
  });
});
