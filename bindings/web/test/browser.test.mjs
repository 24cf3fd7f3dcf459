// The explorer in a real browser: Debian's Chromium driven by playwright-core
// (nothing downloaded; every request that is not to the loopback server, a
// file:, data: or blob: URL is refused and counted).  Environment as for
// node.test.mjs, plus TS_WEB_ARTIFACTS (screenshot, timings).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createServer } from 'node:http';
import { readFileSync, writeFileSync, mkdtempSync, rmSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { tmpdir } from 'node:os';
import { join, extname } from 'node:path';
import { pathToFileURL } from 'node:url';
import { createRequire } from 'node:module';

const env = (k) => {
  if (!process.env[k]) throw new Error(`${k} not set (run through bindings/web/test/run.sh)`);
  return process.env[k];
};
const OUT = env('TS_WEB_OUT'), ART = env('TS_WEB_ARTIFACTS');
const require = createRequire(join(import.meta.dirname ?? new URL('.', import.meta.url).pathname, '..', 'package.json'));
const { chromium } = require('playwright-core');
const lib = await import(join(OUT, 'trigspline.mjs'));

let server, base, context, profile;
const external = [];
const pageErrors = [];

before(async () => {
  const types = { '.html': 'text/html', '.mjs': 'text/javascript', '.wasm': 'application/wasm' };
  server = createServer((req, res) => {
    const name = decodeURIComponent(new URL(req.url, 'http://x').pathname).replace(/^\/+/, '') || 'index.html';
    if (name.includes('..')) { res.writeHead(403).end(); return; }
    try {
      const body = readFileSync(join(OUT, name));
      res.writeHead(200, { 'content-type': types[extname(name)] ?? 'application/octet-stream' }).end(body);
    } catch { res.writeHead(404).end(); }
  });
  await new Promise((r) => server.listen(0, '127.0.0.1', r));
  base = `http://127.0.0.1:${server.address().port}`;
  profile = mkdtempSync(join(tmpdir(), 'tsweb-chromium-'));
  context = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    acceptDownloads: true,
    viewport: { width: 1360, height: 900 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--no-first-run'],
  });
  await context.route('**/*', (route) => {
    const u = route.request().url();
    if (u.startsWith(base) || /^(file|data|blob):/.test(u)) return route.continue();
    external.push(u);
    return route.abort();
  });
});

after(async () => {
  await context?.close();
  await new Promise((r) => server?.close(r));
  if (profile) rmSync(profile, { recursive: true, force: true });
});

async function openExplorer(url = `${base}/index.html`) {
  const page = await context.newPage();
  page.on('pageerror', (e) => pageErrors.push(String(e)));
  await page.goto(url);
  await page.waitForSelector('body[data-ready="1"]', { timeout: 30000 });
  return page;
}
const state = (page) => page.evaluate(() => JSON.parse(JSON.stringify(window.explorer.state)));
const certText = (page) => page.locator('#cert').innerText();

// A real mouse drag of data point i to data coordinates (x, y).
async function dragPoint(page, i, x, y, steps = 12) {
  const [px, py] = await page.evaluate((k) => window.explorer.toScreen(...window.explorer.state.points[k]), i);
  const [qx, qy] = await page.evaluate(([a, b]) => window.explorer.toScreen(a, b), [x, y]);
  await page.mouse.move(px, py);
  await page.mouse.down();
  for (let k = 1; k <= steps; k++) {
    await page.mouse.move(px + ((qx - px) * k) / steps, py + ((qy - py) * k) / steps);
    await page.evaluate(() => new Promise(requestAnimationFrame));
  }
  await page.mouse.up();
  await page.evaluate(() => new Promise(requestAnimationFrame));
}

const TABLE1 = [[0, 2], [2, 1.58], [3, 1.55], [5, 1.54], [15, 1.8], [25, 1.54], [27, 1.55], [28, 1.58], [30, 2]];

test('drag a point towards the bound: the curve stays in the region, the certificate changes', async () => {
  const page = await openExplorer();
  await page.evaluate((P) => window.explorer.set({ points: P, scheme: 'positive', form: 'paper', slopes: 'arithmetic', alpha: 1 }), TABLE1);
  const before = await certText(page);
  await dragPoint(page, 3, 5, 0.02);
  const s = await state(page);
  assert.ok(Math.abs(s.points[3][1] - 0.02) < 0.05, `point at ${s.points[3]}`);
  const r = await page.evaluate(() => { const q = window.explorer.result; return { ok: q.ok, min: Math.min(...q.ys), rows: q.rows }; });
  assert.ok(r.ok);
  assert.ok(r.min >= 0, `sampled minimum ${r.min}`);
  for (const row of r.rows) assert.ok(row.certified && row.gapLower >= 0, JSON.stringify(row));
  // the exact minimum of every interval (the certificate) and the one the
  // module computes for the same data agree
  const sp = (await lib.load()).spline(s.points.map((p) => p[0]), s.points.map((p) => p[1]), { shape: 'positive', form: 'paper', slopes: 'arithmetic', alpha: 1 });
  assert.deepEqual(r.rows.map((q) => q.gapLower), sp.report().map((q) => q.gapLower));
  sp.free();
  assert.notEqual(await certText(page), before);
  // the unconstrained cubic spline drawn for comparison does dip below zero
  const cubicMin = await page.evaluate(() => Math.min(...document.getElementById('cubic').getAttribute('d').split(/[ML]/).filter(Boolean).map((p) => +p.split(',')[1])));
  const zeroPx = await page.evaluate(() => window.explorer.toScreen(0, 0)[1] - document.getElementById('plot').getBoundingClientRect().top);
  assert.ok(cubicMin !== null && zeroPx > 0);
  // across the bound: refused, the point named
  await dragPoint(page, 3, 5, -0.3);
  assert.match(await page.locator('#status').innerText(),
               /Refused: TS_ERR_NEGATIVE: point 3 \(x = [-\d.e]+, f = -[\d.e]+\) is negative/);
  assert.equal(await page.locator('circle.pt.bad').count(), 1);
  assert.equal(await page.locator('#curve').count(), 0);
  // an infeasible interval (data above the steep line y = 10x with alpha = 10,
  // tests/api/test_shape.c): marked, with the library's reason
  await page.evaluate(() => window.explorer.set({ points: [[0, 1], [1, 10.3], [2, 21], [3, 31]], scheme: 'above', lower: { m: 10, c: 0 }, alpha: 10, form: 'paper', slopes: 'arithmetic' }));
  assert.match(await page.locator('#status').innerText(),
               /Refused: TS_ERR_INFEASIBLE: interval 0 \[0, 1\]: no beta >= 0 keeps/);
  assert.match(await page.locator('rect.badint[data-interval="0"] title').textContent(), /TS_ERR_INFEASIBLE/);
  await page.close();
});

test('alpha (all and per interval), scheme switch, line ends, curve with a box, URL state', async () => {
  const page = await openExplorer();
  await page.evaluate((P) => window.explorer.set({ points: P, scheme: 'positive', form: 'paper', slopes: 'arithmetic', alpha: 1 }), TABLE1);
  const t0 = await certText(page);
  await page.evaluate(() => { const a = document.getElementById('alpha'); a.value = '-1'; a.dispatchEvent(new Event('input')); });
  assert.equal((await state(page)).alpha, 0.1);
  assert.notEqual(await certText(page), t0);
  // per interval: click row 2, move its slider
  await page.locator('#cert tr[data-interval="2"]').click();
  await page.evaluate(() => { const a = document.getElementById('ialpha'); a.value = '0.5'; a.dispatchEvent(new Event('input')); });
  const s = await state(page);
  assert.equal(s.alphas[2], 3.16);
  assert.equal(s.alphas[1], 0.1);
  assert.equal((await page.evaluate(() => window.explorer.result.rows[2].alpha)), 3.16);
  // scheme between: two lines; drag the upper line's right end
  await page.selectOption('#scheme', 'between');
  assert.equal((await state(page)).scheme, 'between');
  assert.equal(await page.locator('rect[data-line]').count(), 4);
  const up0 = (await state(page)).upper;
  const h = page.locator('rect[data-line="upper"][data-end="1"]');
  const bb = await h.boundingBox();
  await page.mouse.move(bb.x + 6, bb.y + 6);
  await page.mouse.down();
  await page.mouse.move(bb.x + 6, bb.y + 30, { steps: 5 });
  await page.mouse.up();
  await page.evaluate(() => new Promise(requestAnimationFrame));
  const up1 = (await state(page)).upper;
  assert.notDeepEqual(up1, up0);
  assert.ok(up1.m < 0, 'right end moved down');
  const res = await page.evaluate(() => window.explorer.result);
  if (res.ok) for (const r of res.rows) assert.ok(r.certified && r.gapUpper > 0 && r.gapLower > 0);
  else assert.match(await page.locator('#status').innerText(), /Refused: TS_ERR_/);
  // the URL holds the state: a second page opened on it shows the same
  await page.waitForTimeout(300);
  const url = page.url();
  const page2 = await openExplorer(url);
  assert.deepEqual(await state(page2), await state(page));
  await page2.close();
  // parametric curve kept inside a box
  await page.locator('input[name=mode][value=curve]').check();
  await page.evaluate(() => window.explorer.set({ mode: 'curve', points: [[0, 1], [1, 4], [2, 1], [3, 4]], closed: true, alpha: 0.37, beta: 0.01, box: { on: true, xmin: -0.5, xmax: 3.5, ymin: 0.5, ymax: 4.5 } }));
  assert.match(await page.locator('#status').innerText(), /^certified inside the box/);
  const corner = await page.locator('rect[data-corner="max"]').boundingBox();
  await page.mouse.move(corner.x + 6, corner.y + 6);
  await page.mouse.down();
  await page.mouse.move(corner.x + 16, corner.y + 40, { steps: 4 });
  await page.mouse.up();
  await page.evaluate(() => new Promise(requestAnimationFrame));
  const cs = await state(page);
  assert.ok(cs.box.ymax < 4.5);
  const st = await page.locator('#status').innerText();
  assert.match(st, /certified inside the box|Refused: TS_ERR_SIDE/);
  await page.close();
});

function runNative(cli, args, data) {
  const dir = mkdtempSync(join(tmpdir(), 'tsweb-'));
  try {
    writeFileSync(join(dir, 'data.csv'), data);
    const r = spawnSync(cli, args, { cwd: dir, encoding: 'utf8' });
    assert.equal(r.status, 0, r.stderr);
    return (f) => readFileSync(join(dir, f), 'utf8');
  } finally { /* read before removing */ }
}

test('exports are the CLI\'s output for the same data and options; screenshot', async () => {
  const page = await openExplorer();
  await page.evaluate((P) => window.explorer.set({ points: P, scheme: 'between', lower: { m: 1, c: 0.1 }, upper: { m: 8, c: 6 }, form: 'c1', slopes: 'arithmetic', alpha: 0.2, overlay: { cubic: true, pchip: true } }),
    [[0, 2.5], [1, 7], [2, 8], [4, 29], [5, 8], [6, 21], [8, 30]]);
  await page.locator('#cert tr[data-interval="3"]').click();
  await page.evaluate(() => { const a = document.getElementById('ialpha'); a.value = '-1'; a.dispatchEvent(new Event('input')); });
  const s = await state(page);
  for (const kind of ['csv', 'json', 'svg']) {
    const [dl] = await Promise.all([page.waitForEvent('download'), page.locator(`button[data-export="${kind}"]`).click()]);
    const got = readFileSync(await dl.path(), 'utf8');
    const args = [...lib.cliArgs(s), ...lib.EXPORTS[kind].args];
    const read = runNative(env('TS_WEB_CLI'), args, lib.dataCsv(s));
    assert.equal(got, read(lib.EXPORTS[kind].file), `${kind}: trigspline ${args.join(' ')}`);
    const shipped = runNative(env('TS_WEB_CLI_SHIPPED'), args, lib.dataCsv(s))(lib.EXPORTS[kind].file);
    const num = /-?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?/g;
    assert.equal(got.replace(num, '#'), shipped.replace(num, '#'), `${kind}: the shipped CLI's text`);
  }
  assert.match(await page.locator('#cmdline').innerText(), /^trigspline fit data\.csv --shape between --lower 1,0\.1 --upper 8,6 --form c1 --slopes arithmetic --alphas /);
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: join(ART, 'explorer.png'), fullPage: true });
  await page.close();
});

test('1000 knots: a drag re-fits and re-certifies per frame', async () => {
  const page = await openExplorer();
  // positive data, 1000 knots (a deterministic sequence)
  const P = Array.from({ length: 1000 }, (_, i) => [i, 1.05 + Math.sin(i * 0.37) * Math.cos(i * 0.011)]);
  await page.evaluate((Q) => window.explorer.set({ points: Q, scheme: 'positive', form: 'paper', slopes: 'arithmetic', alpha: 1, overlay: { cubic: false, pchip: false } }), P);
  await page.evaluate(() => { window.explorer.timings.length = 0; });
  await dragPoint(page, 500, 500, 0.01, 60);
  const t = await page.evaluate(() => window.explorer.timings.filter((q) => q.n === 1000));
  const res = await page.evaluate(() => ({ ok: window.explorer.result.ok, cert: window.explorer.result.rows.every((r) => r.certified), n: window.explorer.result.rows.length }));
  assert.ok(res.ok && res.cert && res.n === 999);
  assert.ok(t.length >= 30, `${t.length} frames`);
  const q = (a, p) => { const b = a.slice().sort((u, v) => u - v); return b[Math.min(b.length - 1, Math.floor(p * b.length))]; };
  const fit = t.map((u) => u.fit), total = t.map((u) => u.total);
  const summary = {
    frames: t.length,
    fit_certify_ms: { median: q(fit, 0.5), p95: q(fit, 0.95), max: Math.max(...fit) },
    total_with_drawing_ms: { median: q(total, 0.5), p95: q(total, 0.95), max: Math.max(...total) },
  };
  writeFileSync(join(ART, 'drag_timings_1000_knots.json'), `${JSON.stringify(summary, null, 2)}\n`);
  console.log(`# 1000 knots, ${t.length} drag frames: fit+certify median ${summary.fit_certify_ms.median.toFixed(2)} ms (p95 ${summary.fit_certify_ms.p95.toFixed(2)}), with drawing median ${summary.total_with_drawing_ms.median.toFixed(2)} ms (p95 ${summary.total_with_drawing_ms.p95.toFixed(2)})`);
  // generous bound (a shared, loaded machine): the median fit+certify of a frame under 16 ms
  assert.ok(summary.fit_certify_ms.median < 16, JSON.stringify(summary));
  await page.close();
});

test('works from a file URL; the curve factory page; no network, no page errors', async () => {
  const page = await openExplorer(pathToFileURL(join(OUT, 'index.html')).href);
  assert.equal(await page.locator('#curve').count(), 1);
  await page.close();
  const ex = await context.newPage();
  ex.on('pageerror', (e) => pageErrors.push(String(e)));
  await ex.goto(pathToFileURL(join(OUT, 'example.html')).href);
  await ex.waitForSelector('body[data-ready="1"]');
  assert.equal(await ex.locator('#note').innerText(), 'drawn');
  await ex.screenshot({ path: join(ART, 'example.png') });
  await ex.close();
  assert.deepEqual(external, []);
  assert.deepEqual(pageErrors, []);
});
