// The charts gallery (out/charts/index.html, make demo) in Debian's Chromium
// driven by playwright-core, opened from a file:// URL: every request that
// is not file: or data: is refused and counted (the plugins and the page must
// make none); the plugins draw the certified curve (dense straight pieces,
// layers ordered in pixels) where the libraries' own smoothing draws
// Beziers; the frame time of 20 layers x 1000 points re-fitted and drawn
// (reported, not asserted).  TS_CHARTS_PAGE: the gallery; TS_WEB_ARTIFACTS:
// screenshot and timings.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { writeFileSync, mkdtempSync, rmSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { createRequire } from 'node:module';

const PAGE = process.env.TS_CHARTS_PAGE, ART = process.env.TS_WEB_ARTIFACTS;
if (!PAGE || !ART) throw new Error('TS_CHARTS_PAGE and TS_WEB_ARTIFACTS must be set (bindings/web/test/run.sh)');
const require = createRequire(join(import.meta.dirname ?? new URL('.', import.meta.url).pathname, '..', 'package.json'));
const { chromium } = require('playwright-core');

let context, profile, page;
const requests = [], external = [], pageErrors = [];

before(async () => {
  assert.ok(existsSync(PAGE), `${PAGE} missing (make demo writes it)`);
  profile = mkdtempSync(join(tmpdir(), 'tscharts-chromium-'));
  context = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium', headless: true, viewport: { width: 1040, height: 900 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--no-first-run'],
  });
  await context.route('**/*', (route) => {
    const u = route.request().url();
    requests.push(u);
    if (/^(file|data):/.test(u)) return route.continue();
    external.push(u);
    return route.abort();
  });
  page = await context.newPage();
  page.on('pageerror', (e) => pageErrors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') pageErrors.push(m.text()); });
  await page.goto(pathToFileURL(PAGE).href);
  await page.waitForSelector('body[data-ready="1"]', { timeout: 60000 });
});

after(async () => {
  await context?.close();
  if (profile) rmSync(profile, { recursive: true, force: true });
});

test('the gallery opens from file:// with no network request and no error', async () => {
  await page.screenshot({ path: join(ART, 'charts-gallery.png'), fullPage: true });
  assert.deepEqual(external, [], `requests leaving the page: ${external.join(', ')}`);
  assert.ok(requests.every((u) => /^(file|data):/.test(u)));
  assert.deepEqual(pageErrors, []);
  const n = await page.evaluate(() => window.gallery.panels);
  assert.equal(n, 16);
  // every panel drew something: SVG paths, or non-blank canvas pixels
  const inked = await page.evaluate(() => window.gallery.drawn.map(({ plot }) => {
    if (plot.tagName === 'svg') return plot.querySelectorAll('path.layer').length;
    const canvas = plot.tagName === 'CANVAS' ? plot : plot.querySelector('canvas');
    const { data } = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height);
    let k = 0;
    for (let i = 3; i < data.length; i += 4) if (data[i] > 0) k++;
    return k;
  }));
  inked.forEach((v, i) => assert.ok(v > 0, `panel ${i} empty`));
  // the captions: a crossing on the left of d3-shape#81, none on the right
  const cost = await page.locator('#d3-81 .cost').allInnerTexts();
  assert.match(cost[0], /under the layer below it/);
  assert.match(cost[1], /^0 crossings/);
});

test('Chart.js plugin: dense certified points, stacked layers ordered; off: Chart.js\'s own', async () => {
  const r = await page.evaluate(() => window.gallery.drawn.filter((d) => d.id.startsWith('chartjs')).map((d, j) => {
    const chart = window.gallery.charts[window.gallery.drawn.indexOf(d)];
    const metas = chart.getSortedVisibleDatasetMetas().sort((a, b) => a.index - b.index);
    const pts = metas.map((m) => m.dataset.points);
    let disorder = 0;
    for (let k = 1; k < pts.length; k++) {
      for (let q = 0; q < pts[k].length; q++) if (pts[k][q].y > pts[k - 1][q].y) disorder++;
    }
    const base = metas[0].vScale.getBasePixel();
    const below = pts[0].filter((p) => p.y > base).length;
    return { id: d.id, side: d.side, dense: pts[0].length, data: metas[0].data.length, disorder, below, j };
  }));
  for (const c of r) {
    if (c.side === 'after') {
      assert.ok(c.dense > 4 * c.data, `${c.id}: ${c.dense} drawn points for ${c.data}`);
      assert.equal(c.disorder, 0, `${c.id}: layers out of order`);
      assert.equal(c.below, 0, `${c.id}: below the base`);
    } else {
      assert.equal(c.dense, c.data, `${c.id}: the plugin is off by default`);
    }
  }
});

test('ECharts plugin: smooth: \'trigspline\' draws straight pieces through dense ordered samples', async () => {
  const r = await page.evaluate(() => window.gallery.drawn.filter((d) => d.id.startsWith('echarts')).map((d) => {
    const chart = window.gallery.charts[window.gallery.drawn.indexOf(d)];
    const els = chart.getZr().storage.getDisplayList(true).filter((e) => e.type === 'ec-polyline');
    return {
      id: d.id, side: d.side,
      lines: els.map((el) => {
        const calls = { M: 0, L: 0, C: 0 }, ys = [];
        el.buildPath({
          moveTo: (x, y) => { calls.M++; ys.push(y); }, lineTo: (x, y) => { calls.L++; ys.push(y); },
          bezierCurveTo: () => { calls.C++; }, closePath() {},
        }, el.shape);
        return { calls, ys, z: el.z2 ?? 0 };
      }),
    };
  }));
  for (const c of r) {
    assert.ok(c.lines.length >= 1, `${c.id}: no line element`);
    if (c.side === 'after') {
      for (const l of c.lines) assert.ok(l.calls.C === 0 && l.calls.L > 100, `${c.id}: ${JSON.stringify(l.calls)}`);
      // stacked tops: some order of the lines has every sample ordered (pixels)
      const lines = c.lines.map((l) => l.ys).sort((a, b) => b.reduce((s, v) => s + v, 0) - a.reduce((s, v) => s + v, 0));
      for (let k = 1; k < lines.length; k++) {
        assert.ok(lines[k].every((y, q) => y <= lines[k - 1][q]), `${c.id}: lines ${k - 1}, ${k} cross`);
      }
    } else {
      assert.ok(c.lines.some((l) => l.calls.C > 0), `${c.id}: ECharts' own smoothing draws Beziers`);
    }
  }
});

test('ECharts plugin: turning smooth: \'trigspline\' off gives ECharts\' own drawing back, and on again ours', async () => {
  const r = await page.evaluate(() => {
    const i = window.gallery.drawn.findIndex((d) => d.id === 'echarts-uk' && d.side === 'after');
    const chart = window.gallery.charts[i];
    const beziers = () => chart.getZr().storage.getDisplayList(true).filter((e) => e.type === 'ec-polyline')
      .map((el) => {
        let c = 0;
        el.buildPath({ moveTo() {}, lineTo() {}, bezierCurveTo() { c++; }, closePath() {} }, el.shape);
        return c;
      });
    const n = chart.getOption().series.length;
    chart.setOption({ series: Array.from({ length: n }, () => ({ smooth: true })) });
    const off = beziers();
    chart.setOption({ series: Array.from({ length: n }, () => ({ smooth: 'trigspline' })) });
    return { off, on: beziers() };
  });
  assert.ok(r.off.every((c) => c > 0), `off: ${r.off}`);
  assert.ok(r.on.every((c) => c === 0), `on: ${r.on}`);
});

test('frame time: 20 layers x 1000 points re-fitted and drawn (reported)', async () => {
  const t = await page.evaluate(async () => {
    const { stackTrig, areaTrig, stackPixels, ts } = window.gallery;
    const L = 20, N = 1000;
    let seed = 12345;
    const rnd = () => { seed = (seed * 1103515245 + 12345) % 2147483648; return seed / 2147483648; };
    const frameData = () => Array.from({ length: N }, (_, i) => {
      const row = { x: i };
      for (let k = 0; k < L; k++) row[`s${k}`] = rnd() < 0.6 ? 0 : rnd() * (rnd() < 0.05 ? 1000 : 1);
      return row;
    });
    const keys = Array.from({ length: L }, (_, k) => `s${k}`);
    const canvas = document.createElement('canvas');
    canvas.width = 1000; canvas.height = 400;
    document.body.append(canvas);
    const ctx = canvas.getContext('2d');
    const x = d3.scaleLinear([0, N - 1], [0, 1000]);
    const fit = stackTrig().x((d) => d.data.x).samples(2).module(ts); // 2 samples a pixel
    const phases = ['stack', 'fit', 'draw', 'total', 'monotoneX', 'pixels'];
    const times = Object.fromEntries(phases.map((k) => [k, []]));
    const sets = Array.from({ length: 8 }, frameData);
    for (let f = 0; f < 48; f++) {
      const rows = sets[f % sets.length];
      const t0 = performance.now();
      const series = d3.stack().keys(keys)(rows);
      const t1 = performance.now();
      const layers = fit(series);
      const t2 = performance.now();
      const y = d3.scaleLinear([0, d3.max(layers[L - 1].y1)], [400, 0]);
      ctx.clearRect(0, 0, 1000, 400);
      const area = areaTrig().x(x).y(y).context(ctx);
      layers.forEach((l, k) => { ctx.beginPath(); area(l); ctx.fillStyle = d3.schemeTableau10[k % 10]; ctx.fill(); });
      ctx.getImageData(0, 0, 1, 1); // wait for the raster
      const t3 = performance.now();
      times.stack.push(t1 - t0); times.fit.push(t2 - t1); times.draw.push(t3 - t2); times.total.push(t3 - t0);
      // the same frame with d3's own curve (what drawing costs without trigspline)
      const t4 = performance.now();
      const s2 = d3.stack().keys(keys)(rows);
      const y2 = d3.scaleLinear([0, d3.max(s2[L - 1], (d) => d[1])], [400, 0]);
      ctx.clearRect(0, 0, 1000, 400);
      const a2 = d3.area().x((d) => x(d.data.x)).y0((d) => y2(d[0])).y1((d) => y2(d[1])).curve(d3.curveMonotoneX).context(ctx);
      s2.forEach((s, k) => { ctx.beginPath(); a2(s); ctx.fillStyle = d3.schemeTableau10[k % 10]; ctx.fill(); });
      ctx.getImageData(0, 0, 1, 1);
      times.monotoneX.push(performance.now() - t4);
      // the plugins' core on the same data in pixels (what a Chart.js frame re-fits)
      const px = rows.map((r) => x(r.x));
      const tops = series.map((s) => s.map((d) => y(d[1])));
      const t5 = performance.now();
      stackPixels(ts, px, tops, 400, -1);
      times.pixels.push(performance.now() - t5);
      await new Promise((res) => requestAnimationFrame(res));
    }
    canvas.remove();
    const stat = (a) => {
      const s = a.slice(8).sort((p, q) => p - q); // the first frames warm the JIT up
      return { median: s[Math.floor(s.length / 2)], p90: s[Math.floor(s.length * 0.9)] };
    };
    return Object.fromEntries(phases.map((k) => [k, stat(times[k])]));
  });
  const f = (s) => `median ${s.median.toFixed(1)} ms (p90 ${s.p90.toFixed(1)})`;
  const text = '20 layers x 1000 points on a 1000 x 400 canvas, headless Chromium (software raster), 40 frames after 8 warm-up:\n'
    + `  d3.stack + stackTrig (2 samples per interval) + areaTrig + canvas fill: ${f(t.total)}\n`
    + `    of which d3.stack ${f(t.stack)}, stackTrig re-fit ${f(t.fit)}, areaTrig + fill ${f(t.draw)}\n`
    + `  the same frame with d3.area().curve(curveMonotoneX) (no trigspline): ${f(t.monotoneX)}\n`
    + `  the plugins' re-fit alone (stackPixels, knots only at 1 px per interval): ${f(t.pixels)}`;
  console.log(text);
  writeFileSync(join(ART, 'charts-frame-times.txt'), `${text}\n`);
  assert.ok(t.total.median > 0);
});
