// d3-shape style curve factories: d3.line().curve(curveTrigPositive) and the
// like.  A factory takes a drawing context (CanvasRenderingContext2D, a
// d3-path, or anything with moveTo/lineTo/closePath) and returns the d3 curve
// object (lineStart, lineEnd, point, areaStart, areaEnd).  The points of one
// line are fitted by the trigspline module registered by load() (or .module(ts))
// and drawn as `samples` straight pieces per interval.
//
// Bounds are in data units.  d3 hands the curve pixel coordinates, so give
// the scales: d3.line().x(...).y(...).curve(curveTrigPositive.scales(x, y));
// each point is mapped back with x.invert / y.invert, the spline is fitted and
// certified in data space and its samples mapped forward again.  Without
// scales the coordinates are taken as they come.
//
// Points whose x does not increase (or decrease: an area's baseline) are drawn
// as a parametric curve (no bounds); data the scheme refuses (e.g. a negative
// value with curveTrigPositive) are drawn as straight segments.

import { getDefaultModule } from './trigspline.js';

function make(base) {
  function factory(context) { return new TrigCurve(context, factory.config); }
  factory.config = base;
  const with_ = (patch) => make({ ...base, ...patch });
  factory.alpha = (a) => with_({ options: { ...base.options, alpha: a } });
  factory.form = (f) => with_({ options: { ...base.options, form: f } });
  factory.slopes = (s) => with_({ options: { ...base.options, slopes: s } });
  factory.samples = (n) => with_({ samples: n });
  factory.scales = (x, y) => with_({ x, y });
  factory.module = (ts) => with_({ ts });
  return factory;
}

const lineOf = (l) => (typeof l === 'number' ? { m: 0, c: l } : l);

export const curveTrig = make({ options: { shape: 'none' }, samples: 24 });
export const curveTrigPositive = make({ options: { shape: 'positive' }, samples: 24 });
export const curveTrigMonotone = make({ options: { shape: 'monotone' }, samples: 24 });
export const curveTrigAbove = (lower) => make({ options: { shape: 'above', lower: lineOf(lower) }, samples: 24 });
export const curveTrigBelow = (upper) => make({ options: { shape: 'below', upper: lineOf(upper) }, samples: 24 });
export const curveTrigBetween = (lower, upper) =>
  make({ options: { shape: 'between', lower: lineOf(lower), upper: lineOf(upper) }, samples: 24 });

class TrigCurve {
  constructor(context, config) {
    this.ctx = context;
    this.cfg = config;
    this.area = NaN;
  }
  areaStart() { this.area = 0; }
  areaEnd() { this.area = NaN; }
  lineStart() { this.pts = []; }
  point(x, y) { this.pts.push([+x, +y]); }
  lineEnd() {
    const P = this.pts, c = this.ctx;
    if (P.length) {
      const draw = this.path(P);
      draw.forEach(([x, y], k) => (k === 0 && !this.area ? c.moveTo(x, y) : c.lineTo(x, y)));
      if (this.area === 1 || (this.area !== 0 && P.length === 1)) c.closePath();
    }
    if (this.area === this.area) this.area = 1 - this.area; // d3: second line of an area continues
  }
  // The drawn points (context coordinates) for the data points P.
  path(P) {
    const { x: sx, y: sy, samples } = this.cfg;
    const ts = this.cfg.ts ?? getDefaultModule();
    if (P.length < 2 || !ts) return P;
    const toData = (p) => [sx ? sx.invert(p[0]) : p[0], sy ? sy.invert(p[1]) : p[1]];
    const toCtx = (x, y) => [sx ? sx(x) : x, sy ? sy(y) : y];
    const D = P.map(toData);
    let inc = true, dec = true;
    for (let i = 1; i < D.length; i++) {
      inc &&= D[i][0] > D[i - 1][0];
      dec &&= D[i][0] < D[i - 1][0];
    }
    try {
      if (inc || dec) {
        const S = dec ? D.slice().reverse() : D;
        const s = ts.spline(S.map((p) => p[0]), S.map((p) => p[1]), this.cfg.options);
        try {
          const xs = [];
          for (let i = 0; i + 1 < S.length; i++) {
            for (let j = 0; j < samples; j++) xs.push(S[i][0] + (S[i + 1][0] - S[i][0]) * (j / samples));
          }
          xs.push(S[S.length - 1][0]);
          const ys = s.evalBatch(xs);
          const out = xs.map((x, k) => toCtx(x, ys[k]));
          return dec ? out.reverse() : out;
        } finally { s.free(); }
      }
      const cv = ts.curve(D, { alpha: this.cfg.options.alpha ?? 1 });
      try {
        const r = cv.sample(samples + 1), out = [];
        for (let k = 0; k < r.length; k += 3) out.push(toCtx(r[k + 1], r[k + 2]));
        return out;
      } finally { cv.free(); }
    } catch (e) {
      if (e && e.name === 'TrigSplineError') return P;
      throw e;
    }
  }
}
