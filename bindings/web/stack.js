// Stacked areas whose layers never cross: fit each layer's THICKNESS with the
// certified positive scheme (shape 'positive', docs/method.md §5) and draw the
// cumulative sums.  A curve drawn through each layer's stacked top on its own
// (d3's curveMonotoneX, curveBasis, ...) does not know the layer below, so the
// two curves can cross between the points; here layer k is drawn as
//   y1_k(x) = base(x) + S_1(x) + ... + S_k(x),  y0_k = y1_{k-1},
// with every S_j >= 0, so y1_k >= y0_k at every drawn x.  All layers are
// sampled at the same abscissae and drawn as straight pieces between them:
// two ordered polylines on the same abscissae stay ordered between them, so
// the drawn paths are ordered too, not only the samples (and in floating
// point: adding a number >= 0 never decreases a sum).
//
//   const series = d3.stack().keys(keys)(data);          // any offset below
//   const layers = stackTrig().x((d) => d.data.date)(series);
//   const area = areaTrig().x(xScale).y(yScale);
//   svg.selectAll('path').data(layers).join('path').attr('d', area);
//
// Offsets (d3.stack().offset(...)); the thicknesses d[1] - d[0] are fitted in
// every case, what differs is the baseline:
//   none        baseline 0: nothing below 0 and no crossing.
//   expand      drawn as C_k / C_n (C the cumulative fitted sums): layers in
//               [0, 1], the top exactly 1, no crossing (the fitted fractions
//               alone would not add up to 1 between the points).
//   silhouette  baseline -C_n / 2: symmetric about 0, no crossing.
//   wiggle      (and any other contiguous offset) d3's baseline values are
//               interpolated by an unconstrained spline (shape 'none') and the
//               sums added to it: no crossing; the baseline itself has no
//               property to keep (in d3 it is a sum of slopes).
//   diverging   refused (TypeError): a series changing sign moves between the
//               positive and the negative stack, and a zero collapses onto
//               the axis, so the layers are not contiguous and no drawing
//               through the points can keep them apart.  Stack non-negative
//               data with stackOffsetNone.
// offset('auto') (the default) tells them apart from the stacked values.
//
// Layers whose thickness the scheme refuses (TS_ERR_PRECISION on extreme
// data) are drawn with straight pieces, which are >= 0 as well: the
// guarantee does not depend on the certificate succeeding (layers.linear
// counts them).  The form is 'c1' unless .options() says otherwise: C¹ in x,
// and evaluated about 4 times faster than the geometric form (no inversion
// of x(θ)), which matters when every frame is re-fitted; certify is off
// (docs/options.md): the positive scheme's control values are a proof by
// themselves, the exact minimum is computed only where they are not, and
// layers.certified still says whether every layer is certified.

import { getDefaultModule } from './trigspline.js';

const OFFSETS = ['auto', 'none', 'expand', 'silhouette', 'baseline'];

// The abscissae at which every layer is drawn: the knots and `per` evenly
// spaced samples inside each interval.
function sampleAbscissae(x, per) {
  const n = x.length, xs = new Float64Array((n - 1) * per + 1);
  let k = 0;
  for (let i = 0; i + 1 < n; i++) {
    xs[k++] = x[i];
    for (let j = 1; j < per; j++) xs[k++] = x[i] + (x[i + 1] - x[i]) * (j / per);
  }
  xs[k] = x[n - 1];
  return xs;
}

// Samples per interval: `samples` when given, else about `budget` samples in
// all (at most 16 per interval, at least 1: the knots themselves).
function perInterval(intervals, samples, budget) {
  if (samples > 0) return Math.max(1, Math.floor(samples));
  return Math.max(1, Math.min(16, Math.floor(budget / Math.max(1, intervals))));
}

// y (length n, every value >= 0) at xs by straight pieces (the fallback).
function linearAt(x, y, xs, out) {
  let i = 0;
  for (let k = 0; k < xs.length; k++) {
    const t = xs[k];
    while (i + 2 < x.length && t > x[i + 1]) i++;
    const h = x[i + 1] - x[i], u = h > 0 ? (t - x[i]) / h : 0;
    const v = y[i] + (y[i + 1] - y[i]) * u;
    out[k] = v > 0 ? v : 0;
  }
  return out;
}

// The fitting core, shared with the chart plugins (charts.js).
//   x: strictly increasing abscissae (n); thick: one array of n thicknesses
//   (>= 0) per layer, bottom first; xs: the drawing abscissae.
// Returns {sums: [C_1, ..., C_m] (Float64Array at xs, C_k >= C_{k-1} >= 0),
// linear: layers drawn with straight pieces, clamped: evaluated values below
// 0 set to 0 (0 when every certificate holds: the library's evaluation
// keeps a certified curve >= 0), certified: every fitted layer certified}.
export function fitThicknesses(ts, x, thick, xs, options = {}) {
  const m = xs.length, sums = [];
  let prev = new Float64Array(m), linear = 0, clamped = 0, certified = true;
  const S = new Float64Array(m);
  for (const t of thick) {
    let zero = true;
    for (let i = 0; i < t.length; i++) if (t[i] !== 0) { zero = false; break; }
    if (zero) {
      S.fill(0);
    } else {
      let s = null;
      try {
        s = ts.spline(x, t, { form: 'c1', certify: false, ...options, shape: 'positive' });
        certified &&= s.certified;
        s.evalBatch(xs, 0, S);
        for (let k = 0; k < m; k++) if (!(S[k] >= 0)) { S[k] = 0; clamped++; }
      } catch (e) {
        if (!(e && e.name === 'TrigSplineError')) throw e;
        linearAt(x, t, xs, S);
        linear++;
      } finally { s?.free(); }
    }
    const C = new Float64Array(m);
    for (let k = 0; k < m; k++) C[k] = prev[k] + S[k];
    sums.push(C);
    prev = C;
  }
  return { sums, linear, clamped, certified };
}

// The offset of a stack from its values (bottom layer first): base[i] and
// top[i] are the stack's lower and upper ends at point i.
function detectOffset(base, top) {
  const near = (a, b, scale) => Math.abs(a - b) <= 1e-9 * Math.max(1, Math.abs(scale));
  if (base.every((b) => b === 0)) {
    return top.every((t) => t === 0 || near(t, 1, 1)) && top.some((t) => t !== 0) ? 'expand' : 'none';
  }
  if (base.every((b, i) => near(b, -(top[i] - b) / 2, top[i] - b))) return 'silhouette';
  return 'baseline';
}

// stackTrig(): fit a d3.stack() result.  Configure with
//   .x(accessor(point, i))  the abscissa of each stack point (default: i);
//   .offset(name)           'auto' (default), 'none', 'expand', 'silhouette'
//                           or 'baseline' (wiggle and other offsets);
//   .samples(n)             samples per interval (default: about 4000 in all);
//   .options(o)             further spline options (form, slopes, alpha, ...);
//   .module(ts)             the trigspline module (default: the first load()).
// Calling it with the series returns one layer per series (same order):
// {key, index, x, y0, y1} with x, y0, y1 Float64Arrays (y0 <= y1), and on the
// array: x, offset (the one used), linear, clamped, certified.
export function stackTrig() {
  const cfg = { x: (d, i) => i, offset: 'auto', samples: 0, options: {}, ts: null };
  function fit(series) {
    const ts = cfg.ts ?? getDefaultModule();
    if (!ts) throw new Error('stackTrig: no trigspline module (call load() first, or .module(ts))');
    const L = series.length;
    if (!L) return Object.assign([], { x: new Float64Array(0), offset: cfg.offset, linear: 0, clamped: 0, certified: true });
    // bottom first: d3 gives each series its place in the stack as .index
    const order = series.map((s, k) => k).sort((a, b) => (series[a].index ?? a) - (series[b].index ?? b));
    const n = series[order[0]].length;
    const x = Float64Array.from(series[order[0]], (d, i) => +cfg.x(d, i));
    for (let i = 1; i < n; i++) {
      if (!(x[i] > x[i - 1])) throw new TypeError(`stackTrig: x must increase (point ${i}: ${x[i]} after ${x[i - 1]})`);
    }
    const thick = [], base = new Float64Array(n), top = new Float64Array(n);
    order.forEach((k, pos) => {
      const s = series[k];
      if (s.length !== n) throw new TypeError(`stackTrig: series ${k} has ${s.length} points, not ${n}`);
      const t = new Float64Array(n), under = pos ? series[order[pos - 1]] : null;
      for (let i = 0; i < n; i++) {
        const d = s[i], lo = +d[0], hi = +d[1];
        if (!Number.isFinite(lo) || !Number.isFinite(hi)) {
          throw new TypeError(`stackTrig: series ${k} point ${i} is not a finite number`);
        }
        if (pos === 0) base[i] = lo;
        else if (lo !== +under[i][1]) {
          throw new TypeError(`stackTrig: layers not contiguous at point ${i} (series ${k}): `
            + 'stackOffsetDiverging or negative values; stack non-negative data with stackOffsetNone');
        }
        if (!(hi >= lo)) throw new TypeError(`stackTrig: series ${k} point ${i}: negative thickness`);
        t[i] = hi - lo;
        top[i] = hi;
      }
      thick.push(t);
    });
    const offset = cfg.offset === 'auto' ? detectOffset(Array.from(base), Array.from(top)) : cfg.offset;
    const xs = n > 1 ? sampleAbscissae(x, perInterval(n - 1, cfg.samples, 4000)) : x.slice();
    const fitted = n > 1 ? fitThicknesses(ts, x, thick, xs, cfg.options)
      : { sums: thick.map((t, k) => thick.slice(0, k + 1).reduce((a, b) => a.map((v, i) => v + b[i]))), linear: 0, clamped: 0, certified: true };
    const m = xs.length, sums = fitted.sums, total = sums[L - 1];
    let b = new Float64Array(m);
    if (offset === 'silhouette') for (let k = 0; k < m; k++) b[k] = -total[k] / 2;
    else if (offset === 'baseline') b = n > 1 ? baselineAt(ts, x, base, xs) : base.slice();
    const at = (C) => {
      const y = new Float64Array(m);
      if (offset === 'expand') for (let k = 0; k < m; k++) y[k] = total[k] > 0 ? C[k] / total[k] : 0;
      else for (let k = 0; k < m; k++) y[k] = b[k] + C[k];
      return y;
    };
    const out = new Array(L);
    let below = at(new Float64Array(m));
    order.forEach((k, pos) => {
      const y1 = at(sums[pos]);
      out[k] = { key: series[k].key, index: series[k].index ?? pos, x: xs, y0: below, y1 };
      below = y1;
    });
    return Object.assign(out, { x: xs, offset, linear: fitted.linear, clamped: fitted.clamped, certified: fitted.certified });
  }
  fit.x = (f) => { cfg.x = typeof f === 'function' ? f : () => f; return fit; };
  fit.offset = (o) => {
    if (!OFFSETS.includes(o)) throw new TypeError(`stackTrig: offset must be one of ${OFFSETS.join(', ')}`);
    cfg.offset = o;
    return fit;
  };
  fit.samples = (k) => { cfg.samples = k; return fit; };
  fit.options = (o) => { cfg.options = { ...o }; return fit; };
  fit.module = (ts) => { cfg.ts = ts; return fit; };
  return fit;
}

// A baseline without constraint (wiggle): the trigspline of the baseline
// values; straight pieces when the scheme refuses them.
function baselineAt(ts, x, base, xs) {
  const out = new Float64Array(xs.length);
  let s = null;
  try {
    s = ts.spline(x, base, { form: 'c1', shape: 'none' });
    return s.evalBatch(xs, 0, out);
  } catch (e) {
    if (!(e && e.name === 'TrigSplineError')) throw e;
    let i = 0;
    for (let k = 0; k < xs.length; k++) {
      while (i + 2 < x.length && xs[k] > x[i + 1]) i++;
      out[k] = base[i] + (base[i + 1] - base[i]) * ((xs[k] - x[i]) / (x[i + 1] - x[i]));
    }
    return out;
  } finally { s?.free(); }
}

// areaTrig(): the area generator for stackTrig's layers (d3.area's role).
//   .x(scale) .y(scale)  map data to drawing coordinates (default: identity);
//   .context(ctx)        draw into a canvas context or d3-path (null: return
//                        an SVG path string, as d3.area does);
//   area(layer)          the closed band between layer.y0 and layer.y1;
//   area.line(layer)     the top edge only (for a stroke).
export function areaTrig() {
  const cfg = { x: (v) => v, y: (v) => v, ctx: null, digits: 3 };
  const emit = (draw) => {
    if (cfg.ctx) { draw(cfg.ctx); return undefined; }
    const parts = [], r = (v) => +v.toFixed(cfg.digits);
    draw({
      moveTo: (a, b) => parts.push(`M${r(a)},${r(b)}`),
      lineTo: (a, b) => parts.push(`L${r(a)},${r(b)}`),
      closePath: () => parts.push('Z'),
    });
    return parts.join('');
  };
  // the layers of one stack share their abscissae: mapped once
  let lastX = null, lastScale = null, lastPx = null;
  const mapX = (x) => {
    if (x !== lastX || cfg.x !== lastScale) {
      lastPx = Float64Array.from(x, (v) => cfg.x(v));
      lastX = x;
      lastScale = cfg.x;
    }
    return lastPx;
  };
  function area(layer) {
    const { y0, y1 } = layer, px = mapX(layer.x), m = px.length;
    return emit((c) => {
      for (let k = 0; k < m; k++) (k ? c.lineTo : c.moveTo).call(c, px[k], cfg.y(y1[k]));
      for (let k = m - 1; k >= 0; k--) c.lineTo(px[k], cfg.y(y0[k]));
      c.closePath();
    });
  }
  area.line = (layer) => emit((c) => {
    const px = mapX(layer.x);
    for (let k = 0; k < px.length; k++) (k ? c.lineTo : c.moveTo).call(c, px[k], cfg.y(layer.y1[k]));
  });
  area.x = (s) => { cfg.x = s; return area; };
  area.y = (s) => { cfg.y = s; return area; };
  area.context = (c) => { cfg.ctx = c ?? null; return area; };
  area.digits = (d) => { cfg.digits = d; return area; };
  return area;
}
