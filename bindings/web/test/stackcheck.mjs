// Crossing measurements of stacked smooth areas: random stacked data sets,
// each drawn by every method into pixel coordinates (an 800 x 400 plot, value
// 0 at the bottom), the drawn paths sampled densely and compared layer by
// layer.  Used by stack.test.mjs (a slice, in make test-web) and by
// stack_full.mjs (1e5 data sets, make test-web-stack-full).
//
// What is sampled is what each library draws: the moveTo / lineTo /
// bezierCurveTo calls of d3's curves, of Chart.js's control points
// (_updateBezierControlPoints, what its LineElement draws) and of ECharts'
// line element (ECPolyline.buildPath), and trigspline's paths (areaTrig and
// the plugins' stackPixels).  Beziers are flattened at 32 steps; every
// layer is then read at 16 abscissae per data interval plus the data points
// (linear interpolation in the flattened path).
import * as d3 from 'd3';
import { _updateBezierControlPoints } from 'chart.js/helpers';
import { ECPolyline } from 'echarts/lib/chart/line/poly.js';

export const W = 800, H = 400;

// mulberry32: a small seeded generator (the data sets are reproducible)
export function rng(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

// One data set: 1-20 layers, 2-40 points, x even (half) or uneven; each value
// 0 with probability 0.6, else uniform in (0, 1], times 1000 with
// probability 0.05 (a spike).
export function dataset(r) {
  const L = 1 + Math.floor(r() * 20), n = 2 + Math.floor(r() * 39);
  const x = [0];
  const even = r() < 0.5;
  for (let i = 1; i < n; i++) x.push(x[i - 1] + (even ? 1 : 0.2 + 1.8 * r()));
  const keys = Array.from({ length: L }, (_, k) => `s${k}`);
  const rows = x.map((xi) => {
    const row = { x: xi };
    for (const k of keys) {
      let v = r() < 0.6 ? 0 : 1 - r();
      if (v && r() < 0.05) v *= 1000;
      row[k] = v;
    }
    return row;
  });
  return { keys, rows };
}

// A drawing context that records a path as a flattened polyline.
function recorder() {
  const xs = [], ys = [];
  let cx = 0, cy = 0;
  return {
    xs, ys,
    moveTo(x, y) { xs.push(x); ys.push(y); cx = x; cy = y; },
    lineTo(x, y) { xs.push(x); ys.push(y); cx = x; cy = y; },
    bezierCurveTo(x1, y1, x2, y2, x, y) {
      for (let j = 1; j <= 32; j++) {
        const t = j / 32, u = 1 - t;
        xs.push(u * u * u * cx + 3 * u * u * t * x1 + 3 * u * t * t * x2 + t * t * t * x);
        ys.push(u * u * u * cy + 3 * u * u * t * y1 + 3 * u * t * t * y2 + t * t * t * y);
      }
      cx = x; cy = y;
    },
    closePath() {},
  };
}

// The pixel scales of a data set (stacked with offset none).
export function scales(ds) {
  const series = d3.stack().keys(ds.keys)(ds.rows);
  let top = 0;
  for (const s of series) for (const d of s) top = Math.max(top, d[1]);
  const x0 = ds.rows[0].x, xn = ds.rows[ds.rows.length - 1].x;
  const X = d3.scaleLinear([x0, xn], [0, W]);
  const Y = d3.scaleLinear([0, top > 0 ? top : 1], [H, 0]);
  return { series, X, Y };
}

// Each method: data set -> the drawn top edge of every layer (bottom first)
// as {xs, ys} in pixels.
export function methods(ts) {
  const d3curve = (curve) => (ds) => {
    const { series, X, Y } = scales(ds);
    return series.map((s) => {
      const rec = recorder();
      d3.line().x((d) => X(d.data.x)).y((d) => Y(d[1])).curve(curve).context(rec)(s);
      return rec;
    });
  };
  const tops = (ds) => {
    const { series, X, Y } = scales(ds);
    return { px: ds.rows.map((r) => X(r.x)), layers: series.map((s) => s.map((d) => Y(d[1]))) };
  };
  const chartjs = (mode) => (ds) => {
    const { px, layers } = tops(ds);
    return layers.map((py) => {
      const pts = px.map((x, i) => ({ x, y: py[i], skip: false }));
      _updateBezierControlPoints(pts, { tension: 0.4, cubicInterpolationMode: mode, capBezierPoints: true },
        { left: 0, top: 0, right: W, bottom: H }, false, 'x');
      const rec = recorder();
      rec.moveTo(pts[0].x, pts[0].y);
      for (let i = 1; i < pts.length; i++) {
        const a = pts[i - 1], b = pts[i];
        rec.bezierCurveTo(a.cp2x, a.cp2y, b.cp1x, b.cp1y, b.x, b.y);
      }
      return rec;
    });
  };
  const echarts = (smoothMonotone) => (ds) => {
    const { px, layers } = tops(ds);
    return layers.map((py) => {
      const points = new Float32Array(2 * px.length); // ECharts' layout is Float32
      px.forEach((x, i) => { points[2 * i] = x; points[2 * i + 1] = py[i]; });
      const shape = { points, smooth: 0.5, smoothMonotone, connectNulls: false };
      const el = new ECPolyline({ shape });
      const rec = recorder();
      el.buildPath(rec, shape);
      return rec;
    });
  };
  return {
    'trigspline stackTrig + areaTrig (d3)': (ds) => {
      const { series, X, Y } = scales(ds);
      const layers = ts.stackTrig().x((d) => d.data.x)(series);
      if (layers.clamped) throw new Error(`${layers.clamped} evaluated values below 0`);
      return layers.map((l) => {
        const rec = recorder();
        ts.areaTrig().x(X).y(Y).context(rec)(l);
        const m = l.x.length; // the band: top edge first, then the bottom back
        return { xs: rec.xs.slice(0, m), ys: rec.ys.slice(0, m) };
      });
    },
    'trigspline plugins (Chart.js, ECharts: stackPixels)': (ds) => {
      const { px, layers } = tops(ds);
      const r = ts.stackPixels(ts.module, px, layers, H, -1);
      return r.ys.map((ys) => ({ xs: r.xs, ys }));
    },
    'd3 curveMonotoneX': d3curve(d3.curveMonotoneX),
    'd3 curveBasis': d3curve(d3.curveBasis),
    'd3 curveCardinal': d3curve(d3.curveCardinal),
    'd3 curveCatmullRom': d3curve(d3.curveCatmullRom),
    'Chart.js tension 0.4': chartjs('default'),
    "Chart.js cubicInterpolationMode 'monotone'": chartjs('monotone'),
    'ECharts smooth: true': echarts(undefined),
    "ECharts smooth + smoothMonotone 'x'": echarts('x'),
  };
}

// The value of a flattened path at x (pointer kept in st for increasing x).
function at(p, x, st) {
  const { xs, ys } = p;
  while (st.i + 2 < xs.length && xs[st.i + 1] < x) st.i++;
  const x0 = xs[st.i], x1 = xs[st.i + 1];
  if (!(x1 > x0)) return x <= x0 ? ys[st.i] : ys[st.i + 1];
  const u = Math.min(1, Math.max(0, (x - x0) / (x1 - x0)));
  return ys[st.i] + (ys[st.i + 1] - ys[st.i]) * u;
}

// Sample the drawn tops: the worst crossing (pixels a layer's top goes below
// the top of the layer under it) and the worst dip below the baseline (y = H).
export function measure(paths, px) {
  const grid = [];
  for (let i = 0; i + 1 < px.length; i++) for (let j = 0; j < 16; j++) grid.push(px[i] + (px[i + 1] - px[i]) * (j / 16));
  grid.push(px[px.length - 1]);
  const st = paths.map(() => ({ i: 0 }));
  let cross = 0, below = 0, crossWidth = 0;
  for (const x of grid) {
    let prev = H, crossed = false;
    for (let k = 0; k < paths.length; k++) {
      const y = at(paths[k], x, st[k]);
      below = Math.max(below, y - H);
      if (k) {
        const d = y - prev; // > 0: this top is under the one below it
        if (d > cross) cross = d;
        if (d > 1e-6) crossed = true;
      }
      prev = y;
    }
    if (crossed) crossWidth++;
  }
  return { cross, below, crossFraction: crossWidth / grid.length };
}

// Run `count` data sets from `seed`; per method: the data sets with a
// crossing deeper than 1e-6 px and than 0.5 px, with a dip below the
// baseline, the worst depths, and the time.
export function run(ts, count, seed = 1) {
  const M = methods(ts), names = Object.keys(M);
  const stats = Object.fromEntries(names.map((k) => [k, { cross: 0, visible: 0, below: 0, maxCross: 0, maxBelow: 0, ms: 0 }]));
  const r = rng(seed);
  let layers = 0, points = 0;
  for (let c = 0; c < count; c++) {
    const ds = dataset(r);
    layers += ds.keys.length;
    points += ds.keys.length * ds.rows.length;
    const { X } = scales(ds);
    const px = ds.rows.map((row) => X(row.x));
    for (const k of names) {
      const t0 = performance.now();
      const m = measure(M[k](ds), px);
      const s = stats[k];
      s.ms += performance.now() - t0;
      if (m.cross > 1e-6) s.cross++;
      if (m.cross > 0.5) s.visible++;
      if (m.below > 1e-6) s.below++;
      s.maxCross = Math.max(s.maxCross, m.cross);
      s.maxBelow = Math.max(s.maxBelow, m.below);
    }
  }
  return { count, layers, points, stats };
}

export function table(res) {
  const pct = (v) => `${((100 * v) / res.count).toFixed(2)} %`;
  const lines = [`${res.count} stacked data sets (${res.layers} layers, ${res.points} values; 1-20 layers, `
    + '60 % zeros, spikes x1000), 800 x 400 px',
  '| method | crossing > 1e-6 px | crossing > 0.5 px | below baseline | worst crossing px | worst dip px | ms |',
  '|---|---|---|---|---|---|---|'];
  for (const [k, s] of Object.entries(res.stats)) {
    lines.push(`| ${k} | ${s.cross} (${pct(s.cross)}) | ${s.visible} (${pct(s.visible)}) | ${s.below} (${pct(s.below)}) `
      + `| ${s.maxCross.toFixed(2)} | ${s.maxBelow.toFixed(2)} | ${s.ms.toFixed(0)} |`);
  }
  return lines.join('\n');
}
