// Opens the "why trigspline" page (make demo: out/why/index.html) in Debian's
// headless Chromium through playwright-core, takes a screenshot of every plot
// and checks its pixels: a drawn plot has many non-white pixels and, where our
// curve is drawn, pixels of its colour (#1a7f37, within 40 per channel: anti-
// aliasing).  Also a screenshot of the whole page (to out/why/screenshot.png).
// Usage: node tests/browser/why_page.mjs PAGE.html
// Prints "why_page: N passed, M failed" last.
import { chromium } from 'playwright-core';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const pagePath = path.resolve(process.argv[2] || 'out/why/index.html');
let passed = 0, failed = 0;
const check = (cond, what) => { if (cond) passed++; else { failed++; console.log('FAIL:', what); } };

const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'ts-chromium-'));
let browser;
try {
  // a fresh profile directory (playwright passes it as --user-data-dir)
  browser = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
           '--disable-component-update', '--disable-sync', '--no-first-run'],
    viewport: { width: 1200, height: 900 },
  });
  const page = await browser.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  // the page is self-contained: refuse any request that is not the file itself
  await page.route('**/*', (r) => (r.request().url().startsWith('file:') ? r.continue() : r.abort()));
  const resp = await page.goto(pathToFileURL(pagePath).href, { waitUntil: 'load' });
  check(resp === null || resp.ok(), 'page loads');
  check((await page.title()).includes('Why trigspline'), 'title');
  const plots = page.locator('.svg svg');
  const n = await plots.count();
  check(n >= 5, `at least 5 plots rendered (got ${n})`);
  for (let i = 0; i < n; i++) {
    const plot = plots.nth(i);
    await plot.scrollIntoViewIfNeeded();
    const box = await plot.boundingBox();
    check(box && box.width > 300 && box.height > 150, `plot ${i} has a size (${JSON.stringify(box)})`);
    const png = await plot.screenshot();
    // decode the screenshot in the browser (canvas) and count pixels
    const stats = await page.evaluate(async (b64) => {
      const img = new Image();
      img.src = 'data:image/png;base64,' + b64;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.width; c.height = img.height;
      const g = c.getContext('2d');
      g.drawImage(img, 0, 0);
      const d = g.getImageData(0, 0, c.width, c.height).data;
      let ink = 0, green = 0;
      for (let k = 0; k < d.length; k += 4) {
        const r = d[k], gg = d[k + 1], bb = d[k + 2];
        if (r < 200 || gg < 200 || bb < 200) ink++;
        if (Math.abs(r - 0x1a) < 40 && Math.abs(gg - 0x7f) < 40 && Math.abs(bb - 0x37) < 40) green++;
      }
      return { ink, green, total: d.length / 4 };
    }, png.toString('base64'));
    check(stats.ink > 0.01 * stats.total, `plot ${i} is drawn (${stats.ink} of ${stats.total} pixels inked)`);
    const hasOurs = await plot.evaluate((el) => el.textContent.includes('trigspline (ours)'));
    if (hasOurs)
      check(stats.green > 200, `plot ${i}: our curve is visible (${stats.green} pixels of its colour)`);
  }
  await page.screenshot({ path: path.join(path.dirname(pagePath), 'screenshot.png'), fullPage: true });
  check(errors.length === 0, `no script errors (${errors.join('; ')})`);
} catch (e) {
  check(false, `browser run: ${e && e.stack ? e.stack : e}`);
} finally {
  if (browser) await browser.close();
  fs.rmSync(profile, { recursive: true, force: true });
}
console.log(`why_page: ${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
