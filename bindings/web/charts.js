// Chart.js and ECharts: their smoothing of line and stacked-area charts
// replaced by the certified curve, one option to turn it on.
//
//   Chart.js   Chart.register(chartjsTrigspline);
//              new Chart(canvas, { type: 'line', data, options: {
//                plugins: { trigspline: { enabled: true } } } });
//   ECharts    installEChartsTrigspline(echarts);
//              series: [{ type: 'line', stack: 'a', areaStyle: {},
//                         smooth: 'trigspline' }, ...]
//              (without the plugin installed, ECharts reads that `smooth` as
//              true: its own smoothing.)
//
// Both work on the points as the chart placed them (pixels, after stacking,
// each animation frame for Chart.js): a stack's layers are taken bottom first,
// each layer's thickness (its distance from the layer below, or from the
// value axis' base for the bottom one) is fitted with the certified positive
// scheme and the layers are drawn as the cumulative sums, all at the same
// abscissae, as stackTrig does (stack.js): the layers of a stack do not cross
// and none goes below the base.  A lone line whose values are all on the
// positive side of the base gets the same (it never dips below the base);
// one with values on both sides is drawn by the unconstrained spline.  Data
// the curve cannot take (gaps, x not increasing, a stack with negative
// values, a horizontal chart) are left to the library's own drawing.
// Nothing is fetched: the trigspline module is the first one load() made
// (or the plugin option `module`).

import { getDefaultModule } from './trigspline.js';
import { fitThicknesses } from './stack.js';

// Samples per interval for a pixel width w over `intervals` intervals: one
// every ~2 px, at most 16.
function pixelSamples(w, intervals, samples) {
  if (samples > 0) return Math.floor(samples);
  return Math.max(1, Math.min(16, Math.round(w / Math.max(1, intervals) / 2)));
}

// The core of both plugins.  px: increasing pixel abscissae (n); layers: the
// pixel ordinates of each layer's top, bottom layer first; base: the base
// pixel(s) (a number or an array of n); dir: -1 when larger values are
// higher up (smaller pixel), +1 when the axis is reversed.  Returns
// {xs, ys: one Float64Array per layer, base: the base at xs, positive} or null when a layer is
// below the one under it by more than half a pixel (negative values) and
// there is more than one layer.
export function stackPixels(ts, px, layers, base, dir, samples = 0) {
  const n = px.length;
  const baseAt = (i) => (typeof base === 'number' ? base : base[i]);
  const thick = [];
  let positive = true;
  for (let k = 0; k < layers.length; k++) {
    const t = new Float64Array(n);
    for (let i = 0; i < n; i++) {
      const below = k ? layers[k - 1][i] : baseAt(i);
      const v = dir * (layers[k][i] - below);
      if (v < -0.5) positive = false;
      t[i] = v > 0 ? v : 0;
    }
    thick.push(t);
  }
  const per = pixelSamples(px[n - 1] - px[0], n - 1, samples);
  const xs = new Float64Array((n - 1) * per + 1);
  let q = 0;
  for (let i = 0; i + 1 < n; i++) for (let j = 0; j < per; j++) xs[q++] = px[i] + (px[i + 1] - px[i]) * (j / per);
  xs[q] = px[n - 1];
  const m = xs.length;
  const baseXs = new Float64Array(m);
  if (typeof base === 'number') baseXs.fill(base);
  else {
    // the base between the points: straight (it is an axis line, or the
    // category-wise base ECharts draws straight too)
    for (let i = 0, k = 0; k < m; k++) {
      while (i + 2 < n && xs[k] > px[i + 1]) i++;
      baseXs[k] = base[i] + (base[i + 1] - base[i]) * ((xs[k] - px[i]) / (px[i + 1] - px[i]));
    }
  }
  if (!positive) {
    if (layers.length > 1) return null;
    const ys = new Float64Array(m);
    let s = null;
    try {
      s = ts.spline(px, layers[0], { form: 'c1', shape: 'none' });
      s.evalBatch(xs, 0, ys);
    } catch (e) {
      if (!(e && e.name === 'TrigSplineError')) throw e;
      return null;
    } finally { s?.free(); }
    return { xs, ys: [ys], base: baseXs, positive: false };
  }
  const { sums } = fitThicknesses(ts, px, thick, xs);
  const ys = sums.map((C) => {
    const y = new Float64Array(m);
    for (let k = 0; k < m; k++) y[k] = baseXs[k] + dir * C[k];
    return y;
  });
  return { xs, ys, base: baseXs, positive: true };
}

const increasing = (a) => a.every((v, i) => Number.isFinite(v) && (i === 0 || v > a[i - 1]));

// ---- Chart.js (v3, v4) -----------------------------------------------------

export const chartjsTrigspline = {
  id: 'trigspline',
  defaults: { enabled: false, samples: 0, module: null },
  beforeDatasetsDraw(chart, _args, opts) {
    if (!opts || !opts.enabled) return;
    const ts = opts.module ?? getDefaultModule();
    if (!ts) return;
    const groups = new Map();
    for (const meta of chart.getSortedVisibleDatasetMetas().slice().sort((a, b) => a.index - b.index)) {
      if (meta.type !== 'line' || !meta.dataset || !meta.vScale || meta.data.length < 2) continue;
      if (meta.vScale.axis !== 'y') continue; // horizontal lines: left as they are
      const stacked = meta.vScale.options.stacked;
      const key = stacked ? `${meta.vScale.id}|${meta.stack}` : `#${meta.index}`;
      if (!groups.has(key)) groups.set(key, []);
      groups.get(key).push(meta);
    }
    for (const metas of groups.values()) {
      const els = metas.map((m) => m.data);
      const px = els[0].map((p) => p.x);
      if (!increasing(px) || els.some((e) => e.length !== px.length || e.some((p, i) => p.skip || p.x !== px[i]))) continue;
      const vs = metas[0].vScale;
      const dir = vs.options.reverse ? 1 : -1;
      const r = stackPixels(ts, px, els.map((e) => e.map((p) => p.y)), vs.getBasePixel(), dir, opts.samples);
      if (!r) continue;
      metas.forEach((meta, k) => {
        const ys = r.ys[k];
        meta.dataset.points = Array.from(r.xs, (x, q) => ({
          x, y: ys[q], skip: false, cp1x: x, cp1y: ys[q], cp2x: x, cp2y: ys[q],
        }));
        meta.dataset._pointsUpdated = true; // no control points of its own
      });
    }
  },
};

// ---- ECharts (v5) ----------------------------------------------------------

const DRAWN = Symbol('trigspline drawing'); // an element's dense points
const PATCHED = Symbol('trigspline patched'); // on a prototype, on echarts
// Draw an element's dense points instead of its own path (ECharts' line and
// area elements, ECPolyline / ECPolygon: their buildPath smooths the points).
function patchBuildPath(el) {
  const proto = Object.getPrototypeOf(el);
  if (proto[PATCHED]) return;
  const own = proto.buildPath;
  proto.buildPath = function buildPath(ctx, shape) {
    const d = this[DRAWN];
    if (!d) return own.call(this, ctx, shape);
    const { xs, top, bottom } = d;
    for (let k = 0; k < xs.length; k++) (k ? ctx.lineTo : ctx.moveTo).call(ctx, xs[k], top[k]);
    if (bottom) {
      for (let k = xs.length - 1; k >= 0; k--) ctx.lineTo(xs[k], bottom[k]);
      ctx.closePath();
    }
    return undefined;
  };
  proto[PATCHED] = true;
}

function markDrawn(el, d) {
  if (!el) return;
  if (d) patchBuildPath(el);
  el[DRAWN] = d;
  if (el.dirtyShape) el.dirtyShape();
  else if (el.dirty) el.dirty();
}

// installEChartsTrigspline(echarts, {module, samples}): once per echarts
// namespace; then `smooth: 'trigspline'` on a line series (on each series of
// a stack, or on one of them: a stack is drawn by one rule) turns it on.
export function installEChartsTrigspline(echarts, options = {}) {
  if (echarts[PATCHED]) return;
  echarts[PATCHED] = true;
  echarts.registerPostUpdate((ecModel, api) => {
    const ts = options.module ?? getDefaultModule();
    if (!ts) return;
    const line = [];
    ecModel.eachSeriesByType('line', (sm) => line.push(sm));
    // chains bottom -> top through stackedOnSeries
    const below = new Map(), above = new Map();
    for (const sm of line) {
      const on = sm.getData().getCalculationInfo('stackedOnSeries');
      if (on && line.includes(on)) { below.set(sm, on); above.set(on, sm); }
    }
    for (const root of line.filter((sm) => !below.has(sm))) {
      const chain = [root];
      while (above.has(chain[chain.length - 1])) chain.push(above.get(chain[chain.length - 1]));
      const on = chain.some((sm) => sm.get('smooth') === 'trigspline');
      if (!on || !drawChain(ts, chain, api, options.samples ?? 0)) {
        // ECharts' own drawing (again, when the option was turned off)
        for (const sm of chain) {
          const v = api.getViewOfSeriesModel(sm);
          for (const el of [v && v._polyline, v && v._polygon]) if (el && el[DRAWN]) markDrawn(el, null);
        }
      }
    }
  });
}

function drawChain(ts, chain, api, samples) {
  const views = chain.map((sm) => api.getViewOfSeriesModel(sm));
  const pts = chain.map((sm) => sm.getData().getLayout('points'));
  if (views.some((v) => !v) || pts.some((p) => !p || p.length < 4)) return false;
  const coordSys = chain[0].coordinateSystem;
  if (!coordSys || coordSys.type !== 'cartesian2d' || coordSys.getBaseAxis().dim !== 'x') return false;
  const n = pts[0].length / 2;
  const px = Array.from({ length: n }, (_, i) => pts[0][2 * i]);
  if (!increasing(px) || pts.some((p) => p.length !== 2 * n || px.some((x, i) => p[2 * i] !== x))) return false;
  const layers = pts.map((p) => Array.from({ length: n }, (_, i) => p[2 * i + 1]));
  if (layers.some((l) => l.some((v) => !Number.isFinite(v)))) return false;
  // the base of the bottom layer: what ECharts fills down to, else value 0
  const valueAxis = coordSys.getOtherAxis(coordSys.getBaseAxis());
  const poly0 = views[0]._polygon;
  const on = poly0 && poly0.shape.stackedOnPoints;
  const base = on && on.length === 2 * n ? Array.from({ length: n }, (_, i) => on[2 * i + 1])
    : valueAxis.toGlobalCoord(valueAxis.dataToCoord(0));
  const dir = valueAxis.inverse ? 1 : -1;
  const r = stackPixels(ts, px, layers, base, dir, samples);
  if (!r) return false;
  views.forEach((v, k) => {
    markDrawn(v._polyline, { xs: r.xs, top: r.ys[k] });
    markDrawn(v._polygon, { xs: r.xs, top: r.ys[k], bottom: k ? r.ys[k - 1] : r.base });
  });
  return true;
}
