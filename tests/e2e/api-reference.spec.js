// The API reference as a teacher uses it: the names a sketch uses first, the kit's own plumbing
// apart at the end, and a box that finds a name or a word.
import { test, expect } from '@playwright/test';
import { expectQuietConsole } from './helpers.js';

expectQuietConsole(test);

test('the teacher\'s names first, the kit\'s own apart; the find box keeps what matches and says how many', async ({ page }) => {
  await page.goto('/api/');
  const internal = page.locator('#internal');
  for (const name of ['fmt', 'joinInSlices', 'pageRenderState']) {
    await expect(internal.locator(`section.item[id="${name}"]`), name).toHaveCount(1);
    await expect(page.locator(`#library section.item[id="${name}"], #p5 section.item[id="${name}"]`), name).toHaveCount(0);
  }
  await expect(page.locator('#library section.item[id="Sphere"]')).toHaveCount(1);
  await expect(page.locator('#p5 section.item[id="createTracerView"]')).toHaveCount(1);

  const total = await page.locator('section.item').count();
  const find = page.getByLabel('Find a name or a word');
  await find.fill('discriminant');
  await expect(page.locator('#found')).toHaveText(new RegExp(`^\\d+ of ${total} names$`));
  await expect(page.locator('section.item[id="intersectQuadratic"]')).toBeVisible();
  await expect(page.locator('section.item[id="toHex"]')).toBeHidden(); // a colour's hex: no discriminant in it
  await expect(page.locator('.toc a[href="#toHex"]')).toBeHidden();
  await expect(page.locator('.toc a[href="#intersectQuadratic"]')).toBeVisible();
  await find.fill('penumbra area');
  await expect(page.locator('section.item[id="AreaLight"]')).toBeVisible();
  await expect(page.locator('section.item[id="Sphere"]')).toBeHidden();
  await find.fill('no such word anywhere');
  await expect(page.locator('#found')).toHaveText(`0 of ${total} names`);
  await find.fill('');
  await expect(page.locator('section.item:visible')).toHaveCount(total);
  await expect(page.locator('#found')).toHaveText('');
});
