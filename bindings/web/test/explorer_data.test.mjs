// The explorer's data in Chromium: paste and file drop read by the command's
// own reader (its options and messages), dates on x, the command's overshoot
// warning next to the certificate, round axis ticks, the points by keyboard.
// Debian's Chromium driven by playwright-core, no network (as browser.test.mjs).
// Environment: TS_WEB_OUT (out/web), TS_WEB_CLI (the CLI built with musl's
// libm: the wasm CLI's twin), TS_WEB_ARTIFACTS (screenshots; the one after the
// paste is also written to TS_WEB_OUT/explorer-paste.png).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createServer } from 'node:http';
import { readFileSync, writeFileSync, mkdtempSync, rmSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { tmpdir } from 'node:os';
import { join, extname } from 'node:path';
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
const external = [], pageErrors = [];

before(async () => {
  const types = { '.html': 'text/html', '.mjs': 'text/javascript', '.wasm': 'application/wasm' };
  server = createServer((req, res) => {
    const name = decodeURIComponent(new URL(req.url, 'http://x').pathname).replace(/^\/+/, '') || 'index.html';
    if (name.includes('..')) { res.writeHead(403).end(); return; }
    let body; // read before any header is written: a missing file (the browser's favicon) is a 404
    try { body = readFileSync(join(OUT, name)); } catch { res.writeHead(404).end(); return; }
    res.writeHead(200, { 'content-type': types[extname(name)] ?? 'application/octet-stream' }).end(body);
  });
  await new Promise((r) => server.listen(0, '127.0.0.1', r));
  base = `http://127.0.0.1:${server.address().port}`;
  profile = mkdtempSync(join(tmpdir(), 'tsweb-chromium-'));
  context = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium', headless: true, viewport: { width: 1360, height: 900 },
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
  assert.deepEqual(external, []);
});

async function openExplorer() {
  const page = await context.newPage();
  page.on('pageerror', (e) => pageErrors.push(String(e)));
  await page.goto(`${base}/index.html`);
  await page.waitForSelector('body[data-ready="1"]', { timeout: 30000 });
  return page;
}
const state = (page) => page.evaluate(() => JSON.parse(JSON.stringify(window.explorer.state)));

// A paste as the browser delivers it (a ClipboardEvent carrying text/plain)
// on the element matching selector, then the read it starts.
async function paste(page, selector, text) {
  await page.evaluate(([sel, t]) => {
    const dt = new DataTransfer();
    dt.setData('text/plain', t);
    const target = document.querySelector(sel);
    target.focus?.();
    target.dispatchEvent(new ClipboardEvent('paste', { clipboardData: dt, bubbles: true, cancelable: true }));
  }, [selector, text]);
  await page.evaluate(() => window.explorer.reading);
}

// A file dropped on the page (a DragEvent carrying a File).
async function drop(page, name, text) {
  await page.evaluate(([n, t]) => {
    const dt = new DataTransfer();
    dt.items.add(new File([t], n, { type: 'text/csv' }));
    const target = document.getElementById('plot');
    target.dispatchEvent(new DragEvent('dragover', { dataTransfer: dt, bubbles: true, cancelable: true }));
    target.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, [name, text]);
  // the File is read asynchronously before the read starts
  await page.waitForFunction(() => !/^reading|^$/.test(document.getElementById('readreport').textContent));
  await page.evaluate(() => window.explorer.reading);
}

const tickLabels = (page, cls) => page.$$eval(`text.${cls}`, (T) => T.map((t) => ({ text: t.textContent, v: +t.dataset.v })));
const utc = (...a) => Date.UTC(...a) / 1000;

const RAIN = 'day;rain\n1;0\n2;3,5\n3;NA\n4;12\n5;0\n6;1,5\n';

test('paste: semicolons, decimal commas and NA read as the command reads them; the NA row reported', async () => {
  const page = await openExplorer();
  await paste(page, '#csv', RAIN);
  const s = await state(page);
  assert.deepEqual(s.points, [[1, 0], [2, 3.5], [4, 12], [5, 0], [6, 1.5]]);
  assert.deepEqual(s.names, ['day', 'rain']);
  const rep = await page.locator('#readreport').innerText();
  // the command's own report of the skipped row: file, line 4, the column
  assert.match(rep, /pasted\.csv:4: missing value in column 2 \("rain"\): row skipped/);
  assert.match(rep, /1 row with a missing value skipped/);
  assert.match(rep, /--decimal-comma/);
  assert.match(rep, /read as: trigspline fit pasted\.csv --decimal-comma --missing skip/);
  // the same text through the "Use this CSV" button gives the same points
  await page.evaluate(() => window.explorer.set({}));
  await page.locator('#csv').fill(RAIN);
  await page.locator('#apply').click();
  await page.evaluate(() => window.explorer.reading);
  assert.deepEqual((await state(page)).points, [[1, 0], [2, 3.5], [4, 12], [5, 0], [6, 1.5]]);
  // the data table and the textarea show the read values with the data's names
  assert.match(await page.locator('#csv').inputValue(), /^day,rain\n1,0\n2,3\.5\n4,12\n5,0\n6,1\.5\n$/);
  // --missing error: the command's refusal, with its line and column
  await page.selectOption('#rmissing', 'error');
  await page.evaluate(() => window.explorer.reading);
  assert.match(await page.locator('#readreport').innerText(), /^pasted\.csv:4:3: missing value in column 2 \("rain"\)/);
  assert.match(await page.locator('#readreport').innerText(), /read as: trigspline fit pasted\.csv --decimal-comma --missing error/);
  await page.selectOption('#rmissing', 'skip');
  await page.evaluate(() => window.explorer.reading);
  await paste(page, '#csv', RAIN);
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: join(ART, 'explorer-paste.png'), fullPage: true });
  await page.screenshot({ path: join(OUT, 'explorer-paste.png'), fullPage: true });
  await page.close();
});

test('malformed data: the command\'s message with line and column; the data stay', async () => {
  const page = await openExplorer();
  const before = (await state(page)).points;
  await paste(page, '#csv', 'x,f\n1,2\n2,abc\n3,4\n');
  assert.match(await page.locator('#readreport').innerText(), /^pasted\.csv:3:3: expected a number, found "abc"/);
  assert.match(await page.locator('#status').innerText(), /^Not read: pasted\.csv:3:3: /);
  assert.deepEqual((await state(page)).points, before);
  // a delimiter chosen: the command's own option (here: it makes the rows one field wide)
  await page.selectOption('#rdelim', ';');
  await paste(page, '#csv', 'x,f\n1,2\n2,3\n');
  assert.match(await page.locator('#readreport').innerText(), /pasted\.csv:\d+: 1 field per row/);
  await page.close();
});

test('a dropped R write.csv file: quoted header, row names, ISO dates, NA; dates on the x axis', async () => {
  const page = await openExplorer();
  // what R's write.csv(data.frame(date = as.Date(...), flow = c(3.2, 4.1, NA, 2.5))) writes
  const R = '"","date","flow"\n"1","2024-01-01",3.2\n"2","2024-01-02",4.1\n"3","2024-01-05",NA\n"4","2024-01-07",2.5\n';
  await drop(page, 'flow.csv', R);
  const s = await state(page);
  assert.deepEqual(s.points, [[utc(2024, 0, 1), 3.2], [utc(2024, 0, 2), 4.1], [utc(2024, 0, 7), 2.5]]);
  assert.equal(s.xTime, true);
  assert.deepEqual(s.names, ['date', 'flow']);
  const rep = await page.locator('#readreport').innerText();
  assert.match(rep, /^Read 3 points from flow\.csv/);
  assert.match(rep, /flow\.csv:4: missing value in column 3 \("flow"\): row skipped/);
  assert.match(rep, /--columns 2,3/);
  // x ticks: dates, increasing, at whole days
  const xt = await tickLabels(page, 'xtick');
  assert.ok(xt.length >= 3, JSON.stringify(xt));
  for (const t of xt) {
    assert.match(t.text, /^\d{4}-\d{2}-\d{2}$/);
    assert.equal(t.text, new Date(t.v * 1000).toISOString().slice(0, 10));
    assert.equal(t.v % 86400, 0);
  }
  // the certificate table and the exports speak dates too
  assert.match(await page.locator('#cert').innerText(), /2024-01-01\s+2024-01-02/);
  assert.match(lib.dataCsv(s), /^date,flow\n2024-01-01,3\.2\n2024-01-02,4\.1\n2024-01-07,2\.5\n$/);
  await page.close();
});

test('ISO date-times pasted anywhere on the page: time ticks', async () => {
  const page = await openExplorer();
  await paste(page, 'body', 'time,level\n2024-03-05T00:00Z,1\n2024-03-05T06:30Z,2\n2024-03-05T09:00Z,1.5\n2024-03-05T12:00Z,1.2\n');
  const s = await state(page);
  assert.deepEqual(s.points.map((p) => p[0]), [utc(2024, 2, 5), utc(2024, 2, 5, 6, 30), utc(2024, 2, 5, 9), utc(2024, 2, 5, 12)]);
  const xt = await tickLabels(page, 'xtick');
  assert.ok(xt.length >= 3);
  const steps = new Set(xt.slice(1).map((t, k) => t.v - xt[k].v));
  assert.equal(steps.size, 1, 'equal steps');
  assert.ok([3600, 7200, 10800, 21600].includes([...steps][0]), `a whole number of hours: ${[...steps][0]}`);
  for (const t of xt) assert.equal(t.text, new Date(t.v * 1000).toISOString().slice(0, 16).replace('T', ' '));
  await page.close();
});

// The command's warning for the same data and options (the musl-built CLI,
// the wasm CLI's twin), without its "trigspline: " prefix.
function cliWarning(s) {
  const dir = mkdtempSync(join(tmpdir(), 'tsweb-'));
  try {
    writeFileSync(join(dir, 'data.csv'), lib.dataCsv(s));
    const r = spawnSync(env('TS_WEB_CLI'), [...lib.cliArgs(s), '-o', 'out.csv'], { cwd: dir, encoding: 'utf8' });
    assert.equal(r.status, 0, r.stderr);
    const w = r.stderr.split('\n').find((l) => l.startsWith('trigspline: warning: '));
    return w ? w.slice('trigspline: '.length) : '';
  } finally { rmSync(dir, { recursive: true, force: true }); }
}

test('the overshoot warning of the command next to "certified"', async () => {
  const page = await openExplorer();
  const T1 = [[0, 2], [2, 1.58], [3, 1.55], [5, 1.54], [15, 1.8], [25, 1.54], [27, 1.55], [28, 1.58], [30, 2]];
  const settled = () => page.waitForSelector('#overshoot[data-state="done"]', { state: 'attached' });
  // the paper's Table 1 at alpha = 0.05: certified, and the command warns of a 146 % dip
  await page.evaluate((P) => window.explorer.set({ points: P, scheme: 'positive', form: 'paper', slopes: 'arithmetic', alpha: 0.05 }), T1);
  await settled();
  const s = await state(page);
  const want = cliWarning(s);
  assert.match(want, /^warning: the curve dips .* 146% of the data range/);
  assert.equal(await page.locator('#overshoot').innerText(), want);
  assert.match(await page.locator('#status').innerText(), /^9 of 9 intervals certified|^8 of 8 intervals certified/);
  assert.equal(await page.locator('#status').getAttribute('class'), 'ok warn');
  // alpha = 1: no warning from the command, none shown
  await page.evaluate(() => { const a = document.getElementById('alpha'); a.value = '0'; a.dispatchEvent(new Event('input')); });
  await settled();
  assert.equal(cliWarning(await state(page)), '');
  assert.equal(await page.locator('#overshoot').innerText(), '');
  assert.equal(await page.locator('#status').getAttribute('class'), 'ok');
  await page.close();
});

// A tick step is 1, 2 or 5 times a power of ten; every tick a whole multiple
// of it, printed as that number with the step's decimals.
function assertRound(ticks, what) {
  assert.ok(ticks.length >= 3 && ticks.length <= 12, `${what}: ${ticks.length} ticks`);
  const step = ticks[1].v - ticks[0].v;
  const p = 10 ** Math.floor(Math.log10(step) + 1e-9), m = step / p;
  assert.ok([1, 2, 5].some((k) => Math.abs(m - k) < 1e-9), `${what}: step ${step}`);
  const dec = Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
  for (const t of ticks) {
    const k = t.v / step;
    assert.ok(Math.abs(k - Math.round(k)) < 1e-6, `${what}: ${t.v} is not a multiple of ${step}`);
    assert.equal(+t.text, +(Math.round(k) * step).toFixed(dec), `${what}: label ${t.text}`);
    assert.ok(!/\d{12,}/.test(t.text) && (t.text.split('.')[1] ?? '').length === dec, `${what}: label ${t.text}`);
  }
}

test('axis ticks are round numbers (steps 1, 2, 5 times a power of ten)', async () => {
  const page = await openExplorer();
  for (const P of [null, [[0, 0.398], [1, 0.631], [2, 1.58], [3, 2.51]], [[-3.7, 1e-4], [0.2, 3.3e-4], [9.1, 2.2e-4]],
    [[1000, 125000], [2500, 310000], [4100, 99000]]]) {
    if (P) await page.evaluate((Q) => window.explorer.set({ points: Q, scheme: 'positive', form: 'paper', slopes: 'arithmetic', alpha: 1 }), P);
    assertRound(await tickLabels(page, 'xtick'), `x ${JSON.stringify(P)}`);
    assertRound(await tickLabels(page, 'ytick'), `y ${JSON.stringify(P)}`);
  }
  await page.close();
});

test('keyboard: Tab reaches the points, arrows move the focused one, the focus is visible, points are labelled', async () => {
  const page = await openExplorer();
  await page.evaluate(() => window.explorer.set({ points: [[0, 2], [2, 1.58], [3, 1.55], [5, 1.54], [15, 1.8]], scheme: 'positive', form: 'paper', slopes: 'arithmetic', alpha: 1 }));
  // from the top of the page: the first Tab stops that reach a data point
  await page.evaluate(() => document.activeElement?.blur());
  let k = 0;
  for (; k < 20; k++) {
    await page.keyboard.press('Tab');
    if (await page.evaluate(() => document.activeElement?.classList?.contains('pt'))) break;
  }
  assert.ok(k < 20, 'a point is reachable with Tab');
  const focused = () => page.evaluate(() => {
    const a = document.activeElement;
    return { i: +a.dataset.i, label: a.getAttribute('aria-label'), role: a.getAttribute('role'), stroke: getComputedStyle(a).strokeWidth };
  });
  let f = await focused();
  assert.equal(f.i, 0);
  assert.equal(f.role, 'button');
  assert.equal(f.label, 'point 1 of 5: x = 0, f = 2');
  const other = await page.evaluate(() => getComputedStyle(document.querySelector('circle.pt[data-i="1"]')).strokeWidth);
  assert.notEqual(f.stroke, other, 'the focused point is drawn differently');
  // one tab stop for all points: the next Tab leaves them
  assert.equal(await page.locator('circle.pt[tabindex="0"]').count(), 1);
  // arrows: a tenth of a tick step (x ticks 2 apart here, y ticks 0.05), Shift ten times that
  await page.keyboard.press('PageDown');
  f = await focused();
  assert.equal(f.i, 1);
  const p0 = (await state(page)).points[1];
  await page.keyboard.press('ArrowUp');
  await page.keyboard.press('ArrowRight');
  let p1 = (await state(page)).points[1];
  const xs = await tickLabels(page, 'xtick'), ys = await tickLabels(page, 'ytick');
  const dx = (xs[1].v - xs[0].v) / 10, dy = (ys[1].v - ys[0].v) / 10;
  assert.ok(Math.abs(p1[0] - (p0[0] + dx)) < 1e-12 && Math.abs(p1[1] - (p0[1] + dy)) < 1e-12, `${p0} -> ${p1}`);
  await page.keyboard.press('Shift+ArrowDown');
  p1 = (await state(page)).points[1];
  assert.ok(Math.abs(p1[1] - (p0[1] + dy - 10 * dy)) < 1e-12, `${p1}`);
  // the label follows, the certificate is recomputed, focus stays on the point
  f = await focused();
  assert.equal(f.i, 1);
  assert.match(f.label, new RegExp(`^point 2 of 5: x = ${+p1[0].toPrecision(5)}, f = `));
  const rows = await page.evaluate(() => window.explorer.result.rows.map((r) => r.certified));
  assert.deepEqual(rows, [true, true, true, true]);
  // x stays between the neighbours
  for (let j = 0; j < 30; j++) await page.keyboard.press('Shift+ArrowRight');
  const s = await state(page);
  assert.ok(s.points[1][0] < s.points[2][0]);
  // End, Delete
  await page.keyboard.press('End');
  assert.equal((await focused()).i, 4);
  await page.keyboard.press('Delete');
  assert.equal((await state(page)).points.length, 4);
  assert.equal((await focused()).i, 3);
  assert.deepEqual(pageErrors, []);
  await page.close();
});
