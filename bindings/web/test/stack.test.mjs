// Stacked areas (stack.js, charts.js) in Node: no crossing and nothing below
// the baseline on random stacked data sets, beside what d3's curves,
// Chart.js's and ECharts' own smoothing draw on the same data (stackcheck.mjs);
// d3-shape#81's data; the offsets.  TS_WEB_OUT as for node.test.mjs;
// TS_STACK_COUNT: the number of random data sets (default 2000; the 1e5 run
// is make test-web-stack-full).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import * as d3 from 'd3';
import * as sc from './stackcheck.mjs';

const OUT = process.env.TS_WEB_OUT;
if (!OUT) throw new Error('TS_WEB_OUT not set (run through bindings/web/test/run.sh)');
const lib = await import(join(OUT, 'trigspline.mjs'));
const ts = await lib.load();
const COUNT = +(process.env.TS_STACK_COUNT ?? 2000);

test(`${COUNT} random stacked data sets: trigspline never crosses nor dips; the others measured`, () => {
  const res = sc.run({ ...lib, module: ts }, COUNT, 1);
  const text = sc.table(res);
  console.log(text);
  if (process.env.TS_WEB_ARTIFACTS) writeFileSync(join(process.env.TS_WEB_ARTIFACTS, 'stack-crossings.md'), `${text}\n`);
  for (const k of Object.keys(res.stats).filter((name) => name.startsWith('trigspline'))) {
    const s = res.stats[k];
    assert.equal(s.cross, 0, `${k}: ${s.cross} data sets with a crossing`);
    assert.equal(s.below, 0, `${k}: ${s.below} data sets below the baseline`);
  }
  // the measurement can fail: the methods that do cross are seen crossing
  assert.ok(res.stats['d3 curveMonotoneX'].visible > COUNT / 10);
  assert.ok(res.stats['d3 curveCardinal'].below > COUNT / 10);
});

// d3-shape#81: two layers, the last four points of the issue's series
// (bottom 0, 186, 2294, 2812.11; top layer 0, 0, 0, 18500).
const issue81 = [0, 186, 2294, 2812.11].map((a, i) => ({ x: i, a, b: [0, 0, 0, 18500][i] }));

test('d3-shape#81: curveMonotoneX crosses by about -471 over a third of x; stackTrig does not', () => {
  const series = d3.stack().keys(['a', 'b'])(issue81);
  // the stacked tops by curveMonotoneX, in data units (identity scales)
  const tops = series.map((s) => {
    const xs = [], ys = [];
    let cx = 0, cy = 0;
    d3.line().x((d) => d.data.x).y((d) => d[1]).curve(d3.curveMonotoneX).context({
      moveTo(x, y) { cx = x; cy = y; xs.push(x); ys.push(y); },
      lineTo(x, y) { cx = x; cy = y; xs.push(x); ys.push(y); },
      bezierCurveTo(x1, y1, x2, y2, x, y) {
        for (let j = 1; j <= 1000; j++) {
          const t = j / 1000, u = 1 - t;
          xs.push(u * u * u * cx + 3 * u * u * t * x1 + 3 * u * t * t * x2 + t * t * t * x);
          ys.push(u * u * u * cy + 3 * u * u * t * y1 + 3 * u * t * t * y2 + t * t * t * y);
        }
        cx = x; cy = y;
      },
      closePath() {},
    })(s);
    return { xs, ys };
  });
  let worst = 0, crossed = 0;
  for (let k = 0; k < tops[1].xs.length; k++) {
    const d = tops[1].ys[k] - tops[0].ys[k]; // same x: both curves use x's thirds
    if (d < worst) worst = d;
    if (d < -1e-9) crossed++;
  }
  // the issue's figures: -471 (rounded), over 33 % of the x range (1 of 3 intervals)
  assert.ok(worst < -470 && worst > -472, `monotoneX worst ${worst}`);
  assert.ok(Math.abs(crossed / tops[1].xs.length - 1 / 3) < 0.02, `crossed over ${crossed / tops[1].xs.length}`);
  const layers = lib.stackTrig().x((d) => d.data.x).samples(1000)(series);
  assert.equal(layers.offset, 'none');
  assert.ok(layers.certified);
  for (let k = 0; k < layers.x.length; k++) {
    assert.ok(layers[1].y1[k] >= layers[0].y1[k] && layers[0].y1[k] >= layers[0].y0[k] && layers[0].y0[k] === 0);
  }
  // it passes through the data
  const at = (x) => layers.x.indexOf(x);
  for (const [i, row] of issue81.entries()) {
    assert.ok(Math.abs(layers[0].y1[at(i)] - row.a) <= 1e-9 * 21312.11);
    assert.ok(Math.abs(layers[1].y1[at(i)] - (row.a + row.b)) <= 1e-9 * 21312.11);
  }
});

test('offsets: none, expand, silhouette, wiggle keep the layers apart; diverging is refused', () => {
  const r = sc.rng(7);
  for (let c = 0; c < 50; c++) {
    const ds = sc.dataset(r);
    for (const [name, offset] of [['none', d3.stackOffsetNone], ['expand', d3.stackOffsetExpand],
      ['silhouette', d3.stackOffsetSilhouette], ['baseline', d3.stackOffsetWiggle]]) {
      const series = d3.stack().keys(ds.keys).offset(offset)(ds.rows);
      const layers = lib.stackTrig().x((d) => d.data.x)(series);
      const L = layers.length, m = layers.x.length;
      const allZero = ds.rows.every((row) => ds.keys.every((k) => row[k] === 0));
      // the detected offset (wiggle and silhouette coincide when the first
      // point is empty, and with one layer wiggle's baseline is 0)
      if (!allZero && name !== 'baseline' && !(name === 'silhouette' && L === 1)) {
        assert.equal(layers.offset, name === 'expand' && allZero ? 'none' : name, `data set ${c}`);
      }
      const bottom = layers.find((l) => l.index === 0), top = layers.find((l) => l.index === L - 1);
      for (let q = 0; q < m; q++) {
        for (const l of layers) assert.ok(l.y1[q] >= l.y0[q], `${name}: layer ${l.index} upside down at ${q}`);
        for (const l of layers) {
          if (l.index) assert.equal(l.y0[q], layers.find((b) => b.index === l.index - 1).y1[q]);
        }
        if (layers.offset === 'none') assert.equal(bottom.y0[q], 0);
        if (layers.offset === 'expand') assert.ok(bottom.y0[q] === 0 && (top.y1[q] === 1 || top.y1[q] === 0));
        if (layers.offset === 'silhouette') assert.ok(Math.abs(bottom.y0[q] + top.y1[q]) <= 1e-12 * Math.abs(top.y1[q]));
      }
      // the layers pass through d3's stacked values at the data points
      const per = (m - 1) / (ds.rows.length - 1);
      for (const l of layers) {
        const s = series.find((t) => t.key === l.key);
        for (let i = 0; i < ds.rows.length; i++) {
          const scale = Math.max(1, Math.abs(top.y1[i * per]), Math.abs(bottom.y0[i * per]));
          assert.ok(Math.abs(l.y1[i * per] - s[i][1]) <= 1e-9 * scale, `${name} ${l.key} at ${i}: ${l.y1[i * per]} vs ${s[i][1]}`);
        }
      }
    }
  }
  const mixed = [{ x: 0, a: 1, b: -1 }, { x: 1, a: -2, b: 3 }, { x: 2, a: 1, b: 0 }];
  const div = d3.stack().keys(['a', 'b']).offset(d3.stackOffsetDiverging)(mixed);
  assert.throws(() => lib.stackTrig().x((d) => d.data.x)(div), /not contiguous/);
  assert.throws(() => lib.stackTrig().x(() => 1)(d3.stack().keys(['a'])(mixed.slice(0, 2))), /x must increase/);
});

test('areaTrig: SVG path of the band and its top edge; a canvas-like context gets the same points', () => {
  const series = d3.stack().keys(['a', 'b'])(issue81);
  const layers = lib.stackTrig().x((d) => d.data.x).samples(2)(series);
  const area = lib.areaTrig().digits(2);
  const d = area(layers[1]);
  assert.match(d, /^M0,0(L[-0-9.]+,[-0-9.]+){13}Z$/); // 7 samples on top, 7 back, closed
  assert.equal(area.line(layers[1]).split('L').length, 7);
  const calls = [];
  lib.areaTrig().context({ moveTo: (x, y) => calls.push(['M', x, y]), lineTo: (x, y) => calls.push(['L', x, y]),
    closePath: () => calls.push(['Z']) })(layers[0]);
  assert.equal(calls.length, 15);
  assert.deepEqual(calls[0], ['M', 0, 0]);
});
