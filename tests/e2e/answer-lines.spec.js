// Sketch 04's boxes and the slide's line, as students really enter it: typed (not pasted) into the
// first box, pasted after an earlier verdict, and with a decimal comma.
import { test, expect } from '@playwright/test';
import { clickPixel, expectQuietConsole, waitForDone } from './helpers.js';

const PINK = '/sketches/04-find-the-pink-pixel.html';
const LINE = 'Pixel: 10,12; H: 30; V: -82';

expectQuietConsole(test);

const box = (page, name) => page.locator(`input[name="${name}"]`);

async function expectBoxes(page, values) {
  for (const [name, value] of Object.entries(values)) await expect(box(page, name), name).toHaveValue(value);
}

/** Pastes `text` into the box `name` as the browser does (a paste event with the clipboard's text). */
function paste(page, name, text) {
  return box(page, name).evaluate((input, text) => {
    const data = new DataTransfer();
    data.setData('text/plain', text);
    input.dispatchEvent(new ClipboardEvent('paste', { clipboardData: data, bubbles: true, cancelable: true }));
  }, text);
}

test.beforeEach(async ({ page }) => {
  await page.goto(PINK);
  await waitForDone(page);
});

test('the slide\'s line typed into the first box and Enter fills every box and checks it, as a paste does', async ({ page }) => {
  await box(page, 'x').fill(LINE);
  await box(page, 'x').press('Enter');
  await expectBoxes(page, { x: '10', y: '12', h: '30', v: '-82' });
  await expect(page.locator('[data-message-for="x"]')).toHaveText('');
  await expect(page.locator('[data-answer-line]')).toHaveText(LINE);
  await expect(page.locator('[data-result]')).toHaveAttribute('data-result', /^(pink|not-pink)$/);
});

test('the line typed into a box then Tab fills the boxes and waits for Check, with no message', async ({ page }) => {
  await box(page, 'h').fill('pixel 3, 4; h 10; v -5');
  await box(page, 'h').press('Tab');
  await expectBoxes(page, { x: '3', y: '4', h: '10', v: '-5' });
  await expect(page.locator('.sf-message')).toHaveText(['', '', '', '']);
  await expect(page.locator('[data-result]')).toHaveText('Not checked yet: press Check.');
});

test('a new paste takes away the last verdict: its ✔ judged another answer', async ({ page }) => {
  await box(page, 'x').fill('16');
  await box(page, 'y').fill('12');
  await page.locator('[data-check]').click();
  await expect(page.locator('[data-result]')).toHaveText(/^✔ /); // the middle of the pink sphere
  await paste(page, 'x', 'Pixel: 0,0; H: 0; V: 0');
  await expectBoxes(page, { x: '0', y: '0', h: '0', v: '0' });
  await expect(page.locator('[data-result]')).not.toContainText('✔');
  await expect(page.locator('[data-result]')).toHaveText('Not checked yet: press Check.');
  await expect(page.locator('[data-answer-line]')).toHaveText('');
  await page.locator('[data-check]').click();
  await expect(page.locator('[data-result]')).toHaveText(/^✘ /); // the sky in the corner
  await expect(page.locator('[data-answer-line]')).toHaveText('Pixel: 0,0; H: 0; V: 0');
});

test('2,5 says to use a point in an angle box, and one number to a box in a pixel box; the picture stays', async ({ page }) => {
  await clickPixel(page.locator('[data-tracer]'), 16, 12);
  const before = await page.locator('[data-tracer]').evaluate((c) => c.toDataURL());
  await box(page, 'h').fill('2,5');
  await box(page, 'h').press('Enter');
  await expect(page.locator('[data-message-for="h"]')).toHaveText('Camera H must be a number, got "2,5": write decimals with a point, 2.5');
  await box(page, 'h').fill('0');
  await box(page, 'x').fill('2,5');
  await box(page, 'x').press('Enter');
  await expect(page.locator('[data-message-for="x"]')).toHaveText('Pixel x must be a whole number, got "2,5": one number to a box');
  expect(await page.locator('[data-tracer]').evaluate((c) => c.toDataURL())).toBe(before);
});
