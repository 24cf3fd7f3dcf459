// trigspline for JavaScript: the C library compiled to WebAssembly (glue.c
// flattens its option structs) and this thin wrapper.  Works in browsers
// (also from a file:// page) and in Node >= 18.
//
//   import { load } from './trigspline.mjs';
//   const ts = await load();
//   const s = ts.spline([0, 1, 2, 3], [1, 0.1, 0.1, 2], { shape: 'positive' });
//   s.eval(1.5); s.evalBatch(xs); s.report(); s.free();
//
// Memory: every Spline and Curve owns memory in the module's heap until its
// free() is called (or, with `using s = ts.spline(...)`, at the end of the
// block: both are disposable).  free() twice is harmless; a freed object
// throws on use.  Nothing is freed by the garbage collector.
//
// Errors: a TrigSplineError with .status ("TS_ERR_NEGATIVE"), .code (14),
// .index (the point, interval or query; null when none), .where ("point",
// "interval", "query" or null) and .message: the status name and the
// library's sentence (ts_error_message; for spline(), curve() and
// disaggregate() with the data and options of the call, naming the point,
// its x and f, or the bin or edge and its values).  Data that are not
// arrays of numbers are refused before the library sees them, with a
// message naming the argument (TS_ERR_NULL) or the entry that is not a number
// (TS_ERR_NONFINITE, .index = that point).

/* global WASM_BASE64, WASM_SIMD_BASE64 */
// Names, index = the C enum value: the library's vocabulary (ts_vocab_name,
// ts_status_name; the command line's names too), read when the first module
// loads (readNames); the tables are not restated here.
const STATUS_NAMES = [];
const WHERE = []; // null, 'point', 'interval', 'query'
export const NAMES = {}; // form, slopes, shape, extrapolate, term, param
// ts_vocab (include/trigspline.h)
const VOCAB = { status: 0, form: 1, slopes: 2, shape: 3, extrapolate: 4, param: 5, term: 7, where: 8,
  constraint: 9 };
function readNames(w, cstring) {
  if (STATUS_NAMES.length) return;
  const list = (v) => Array.from({ length: w.ts_vocab_count(v) }, (_, i) => cstring(w.ts_vocab_name(v, i)));
  STATUS_NAMES.push(...list(VOCAB.status));
  WHERE.push(null, ...list(VOCAB.where).slice(1));
  for (const kind of ['form', 'slopes', 'shape', 'extrapolate', 'term', 'param', 'constraint']) {
    NAMES[kind] = Object.freeze(list(VOCAB[kind]));
  }
  Object.freeze(STATUS_NAMES);
  Object.freeze(WHERE);
  Object.freeze(NAMES);
}
const ROW = 17; // doubles per report row (glue.c)
function extrapCode(name) {
  const k = NAMES.extrapolate.indexOf(name);
  if (k < 0) throw new TypeError(`extrapolate must be one of ${NAMES.extrapolate.join(', ')}`);
  return k;
}
const NO_INDEX = 0xffffffff;
// The data argument a (named what) unchanged, or a TrigSplineError naming what
// is wrong with it: not an array of numbers at all (TS_ERR_NULL: null, a
// string, ...), or an entry that is not a number (TS_ERR_NONFINITE with its
// index; the heap copy would make it NaN).  Numeric strings stay accepted.
function numbersOf(a, what, dim = 1) {
  if (ArrayBuffer.isView(a)) return a;
  if (a === null || typeof a !== 'object' || typeof a.length !== 'number') {
    const got = a === null ? 'null' : typeof a === 'string' ? 'a string' : typeof a;
    throw new TrigSplineError(1, `${what} must be an array of numbers, got ${got}`, null, null);
  }
  for (let i = 0; i < a.length; i++) {
    const v = a[i];
    if (typeof v !== 'number' && Number.isNaN(Number(v))) {
      const k = Math.floor(i / dim);
      const at = dim > 1 ? `${what}[${k}][${i % dim}]` : `${what}[${i}]`;
      const got = typeof v === 'string' ? `the string ${JSON.stringify(v)}`
        : v === null || v === undefined ? String(v) : `a value of type ${typeof v}`;
      throw new TrigSplineError(5, `${at} is not a number (${got})`, k, 'point');
    }
  }
  return a;
}
// Constraint records (docs/method.md §13; the command line's --constraint
// SPEC strings, or {kind, value, points: [[x, y], ...], spline, first,
// count}) as the two arrays glue.c's tsw_constraints reads: 5 doubles per
// record (kind, value, first, count, n_poly) and the polylines' x then y; a
// bound given by another Spline of the same module (§13.7): value its
// address, n_poly -1.
const SPEC_OPS = [['slope>=', 'slope-min'], ['slope<=', 'slope-max'], ['abs-slope<=', 'slope-abs'],
  ['|slope|<=', 'slope-abs'], ['slope-min=', 'slope-min'], ['slope-max=', 'slope-max'],
  ['slope-abs=', 'slope-abs'], ['lower=', 'lower'], ['upper=', 'upper']];
function constraintRecord(c) {
  const bad = (why) => new TrigSplineError(11, `constraint ${JSON.stringify(c)}: ${why}`, null, null);
  if (typeof c === 'object' && c !== null) {
    const kind = NAMES.constraint.indexOf(c.kind);
    if (kind < 0) throw bad(`kind must be one of ${NAMES.constraint.join(', ')}`);
    const spline = c.spline ?? null;
    if (spline !== null && ((c.kind !== 'lower' && c.kind !== 'upper') || c.points)) {
      throw bad('spline is a bound (lower or upper), without points');
    }
    return { kind, value: Number(c.value ?? 0), first: c.first ?? 0, count: c.count ?? 0, points: c.points ?? null, spline };
  }
  if (typeof c !== 'string') throw bad('a SPEC string or an object');
  const [spec, scope] = c.trim().split('@');
  let first = 0, count = 0;
  if (scope !== undefined) {
    const m = /^(\d+)(-(\d*))?$/.exec(scope);
    if (!m) throw bad('the scope is @I0-I1 (intervals)');
    first = Number(m[1]);
    count = m[2] === undefined ? 1 : m[3] === '' ? 0 : Number(m[3]) - first + 1;
    if (count < 0) throw bad('the scope is @I0-I1 (intervals)');
  }
  const k = NAMES.constraint.indexOf(spec);
  if (k >= 0 && k <= 3) return { kind: k, value: 0, first, count, points: null };
  for (const [pre, name] of SPEC_OPS) {
    if (!spec.startsWith(pre)) continue;
    const val = spec.slice(pre.length), kind = NAMES.constraint.indexOf(name);
    if ((name === 'lower' || name === 'upper') && val.startsWith('poly:')) {
      const points = val.slice(5).split(';').map((p) => p.split(',').map(Number));
      if (points.some((p) => p.length !== 2 || p.some(Number.isNaN))) throw bad('not a polyline X,Y;X,Y;...');
      return { kind, value: 0, first, count, points };
    }
    const value = Number(val);
    if (val.trim() === '' || Number.isNaN(value)) throw bad(`${JSON.stringify(val)} is not a number`);
    return { kind, value, first, count, points: null };
  }
  throw bad('unknown constraint (convex, concave, increasing, decreasing, lower=C, upper=C, '
    + 'lower=poly:X,Y;..., slope>=V, slope<=V, abs-slope<=V)');
}
function constraintArrays(list, ts) {
  if (list === undefined || list === null) return [null, null];
  const recs = (Array.isArray(list) ? list : [list]).map(constraintRecord);
  if (recs.length > 64) throw new TrigSplineError(10, 'at most 64 constraint records', null, null);
  const rec = [], pts = [];
  for (const r of recs) {
    if (r.spline !== null && r.spline !== undefined) {
      if (!(r.spline instanceof Spline) || r.spline.ts !== ts) {
        throw new TrigSplineError(11, `constraint ${r.kind}: spline must be a Spline of this module`, null, null);
      }
      rec.push(r.kind, r.spline.live(), r.first, r.count, -1);
      continue;
    }
    const np = r.points ? r.points.length : 0;
    rec.push(r.kind, r.value, r.first, r.count, np);
    if (np) {
      for (const p of r.points) pts.push(Number(p[0]));
      for (const p of r.points) pts.push(Number(p[1]));
    }
  }
  return [rec, pts.length ? pts : null];
}
const dispose = Symbol.dispose ?? Symbol.for('Symbol.dispose');

export class TrigSplineError extends Error {
  // text: the whole sentence (the library's, or an argument check of this
  // wrapper)
  constructor(code, text, index, where) {
    const name = STATUS_NAMES[code] ?? `status ${code}`;
    super(`${name}: ${text}`);
    this.name = 'TrigSplineError';
    this.status = name;
    this.code = code;
    this.index = index;
    this.where = where;
  }
}

function decodeBase64(b64) {
  const bin = atob(b64);
  const out = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
  return out;
}

// A module of one function using a SIMD128 instruction (i32.const 0;
// i8x16.splat; i8x16.popcnt): WebAssembly.validate accepts it exactly where
// the engine runs SIMD128.
const SIMD_PROBE = [0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0,
  253, 15, 253, 98, 11];
export function simdSupported() {
  try { return WebAssembly.validate(new Uint8Array(SIMD_PROBE)); } catch { return false; }
}
// Whether load() takes the SIMD128 module: options.simd (true, false) or, when
// that is not given, Node's environment TRIGSPLINE_SIMD=0 (the scalar one, for
// tests), else where the engine validates SIMD_PROBE.
function wantSimd(options) {
  if (options.simd !== undefined && options.simd !== null) return Boolean(options.simd) && simdSupported();
  const env = typeof process === 'object' ? process.env?.TRIGSPLINE_SIMD : undefined;
  if (env === '0') return false;
  return simdSupported();
}

// load(options): instantiate the module.  options.wasm: the wasm bytes or a
// WebAssembly.Module (default: trigspline-simd.wasm or trigspline.wasm next to
// this file, or the copy inlined in a page, WASM_SIMD_BASE64 or WASM_BASE64;
// the two modules are built from the same sources and give the same bits,
// the SIMD128 one where the engine has it: wantSimd);
// options.simd: false for the scalar module where SIMD128 exists too;
// options.maxMemoryMB: cap of the module's heap (default 2048).
export async function load(options = {}) {
  let wasm = options.wasm;
  let simd = wasm === undefined && wantSimd(options);
  if (wasm === undefined && typeof WASM_BASE64 === 'string') { // a page with it inlined
    simd &&= typeof WASM_SIMD_BASE64 === 'string';
    wasm = decodeBase64(simd ? WASM_SIMD_BASE64 : WASM_BASE64);
  }
  if (wasm === undefined) { // next to this file
    const url = new URL(simd ? 'trigspline-simd.wasm' : 'trigspline.wasm', import.meta.url);
    if (url.protocol === 'file:' && typeof process === 'object' && process.versions?.node) {
      const { readFile } = await import('node:fs/promises');
      wasm = await readFile(url);
    } else {
      const r = await fetch(url);
      if (!r.ok) throw new Error(`trigspline: cannot load ${url}: ${r.status}`);
      wasm = await r.arrayBuffer();
    }
  }
  const maxPages = Math.floor((options.maxMemoryMB ?? 2048) * 16);
  // 32 pages = the build's -sINITIAL_MEMORY=2MB (Makefile, target web)
  const memory = new WebAssembly.Memory({ initial: 32, maximum: Math.max(32, maxPages) });
  const imports = { env: { memory, emscripten_notify_memory_growth() {} } };
  const mod = wasm instanceof WebAssembly.Module ? wasm : await WebAssembly.compile(wasm);
  for (const imp of WebAssembly.Module.imports(mod)) {
    imports[imp.module] ??= {};
    if (!(imp.name in imports[imp.module])) {
      // wasi calls the library never makes (it does not print or exit)
      imports[imp.module][imp.name] = () => { throw new Error(`trigspline: ${imp.name} called`); };
    }
  }
  const inst = await WebAssembly.instantiate(mod, imports);
  if (inst.exports._initialize) inst.exports._initialize();
  const ts = new TrigSpline(inst.exports, memory);
  defaultModule ??= ts;
  return ts;
}

// The first module load() made: what the curve factories (curve.js) use
// unless given one.
let defaultModule = null;
export function getDefaultModule() { return defaultModule; }

class TrigSpline {
  constructor(w, memory) {
    this.w = w;
    this.memory = memory;
    readNames(w, (p) => this.cstring(p));
    this.NAMES = NAMES;
    this.STATUS_NAMES = STATUS_NAMES;
    this.TrigSplineError = TrigSplineError;
    this.version = this.cstring(w.ts_version());
    this.simd = w.tsw_simd() === 1; // the SIMD128 module (load(), wantSimd)
    const d = this.withScratch(8, (p) => { w.tsw_defaults(p); return Array.from(this.f64(p, 8)); });
    this.defaults = {
      form: NAMES.form[d[0]], slopes: NAMES.slopes[d[1]], alpha: d[2], beta: d[3],
      shape: NAMES.shape[d[4]], margin: d[5], certify: d[6] !== 0, extrapolate: NAMES.extrapolate[d[7]],
    };
    const c = this.withScratch(6, (p) => { w.tsw_curve_defaults(p); return Array.from(this.f64(p, 6)); });
    this.curveDefaults = {
      param: NAMES.param[c[0]], closed: c[1] !== 0, slopes: NAMES.slopes[c[2]], alpha: c[3],
      beta: c[4], margin: c[5],
    };
    this.errPtr = w.malloc(12);
  }

  // ---- heap helpers --------------------------------------------------
  f64(p, n) { return new Float64Array(this.memory.buffer, p, n); }
  u32(p, n) { return new Uint32Array(this.memory.buffer, p, n); }
  cstring(p) {
    const b = new Uint8Array(this.memory.buffer);
    let e = p;
    while (b[e]) e++;
    return new TextDecoder().decode(b.subarray(p, e));
  }
  alloc(bytes) {
    const p = this.w.malloc(Math.max(bytes, 8));
    if (!p) throw new TrigSplineError(2, this.strerror(2), null, null);
    return p;
  }
  // Copy an array of numbers into the heap (null stays NULL).
  put(a) {
    if (a === null || a === undefined) return 0;
    const p = this.alloc(a.length * 8);
    this.f64(p, a.length).set(a);
    return p;
  }
  withScratch(n, fn) {
    const p = this.alloc(n * 8);
    try {
      return fn(p);
    } finally { this.w.free(p); }
  }
  // Run fn with the arrays copied into the heap; free them afterwards.
  withArrays(arrays, fn) {
    const ps = [];
    try {
      for (const a of arrays) ps.push(this.put(a));
      return fn(...ps);
    } finally { for (const p of ps) if (p) this.w.free(p); }
  }
  resetError() {
    this.u32(this.errPtr, 3).set([0, NO_INDEX, 0]);
    this.w.tsw_message_clear();
  }
  // The error of the last failed call: the sentence glue.c wrote with the
  // call's data, or ts_error_message without context.
  error(code) {
    const e = this.u32(this.errPtr, 3);
    e[0] = code;
    const [, index, where] = e;
    let text = this.cstring(this.w.tsw_message());
    if (!text) {
      text = this.withScratch(64, (p) => {
        this.w.ts_error_message(this.errPtr, 0, p, 512);
        return this.cstring(p);
      });
    }
    return new TrigSplineError(code, text, index === NO_INDEX ? null : index,
      index === NO_INDEX ? null : WHERE[where] ?? null);
  }
  check(code) {
    if (code !== 0) throw this.error(code);
  }
  // an enum option: a name or a raw number (passed through, so an out-of-range
  // value reaches the library's TS_ERR_OPTION)
  enumValue(kind, v) {
    if (typeof v === 'number') return v;
    const i = NAMES[kind].indexOf(v);
    if (i < 0) {
      throw new TrigSplineError(11, `${this.strerror(11)}: unknown ${kind} "${v}" (one of ${NAMES[kind].join(', ')})`, null, null);
    }
    return i;
  }

  strerror(code) { return this.cstring(this.w.ts_strerror(code)); }
  // Top of the module's malloc heap in bytes (it never shrinks: a leak shows
  // as growth over many create/free cycles).
  heapTop() { return this.w.tsw_heap_top(); }

  // ---- construction --------------------------------------------------
  // spline(x, f, options): options.form, .slopes (a name, or an array of
  // n_points user slopes), .alpha / .beta / .margin (a number, or an array with
  // one value per interval), .shape, .lower / .upper ({m, c}, or a number c
  // for a constant line), .line (for above/below), .certify, .extrapolate,
  // .constraints (constraint records, docs/method.md §13: SPEC strings as the
  // command line's --constraint, or {kind, value, points, first, count}; a
  // bound given by another Spline: {kind: 'lower', spline}, §13.7, which may
  // be freed after this call: the fitted spline keeps its own copy).
  spline(x, f, options = {}) {
    const o = { ...this.defaults, ...options };
    numbersOf(x, 'x');
    numbersOf(f, 'f');
    const n = x.length;
    if (f.length !== n) {
      throw new TrigSplineError(10, `${this.strerror(10)}: ${f.length} values for ${n} x`, null, null);
    }
    const userSlopes = Array.isArray(o.slopes) || ArrayBuffer.isView(o.slopes) ? o.slopes : null;
    const slopes = userSlopes ? 6 : this.enumValue('slopes', o.slopes);
    const arr = (v) => (typeof v === 'number' ? null : v);
    const num = (v, dflt) => (typeof v === 'number' ? v : dflt);
    const shape = this.enumValue('shape', o.shape);
    const line = (l) => (l === undefined || l === null ? [0, 0]
      : typeof l === 'number' ? [0, l] : [l.m ?? 0, l.c ?? 0]);
    let lower = line(o.lower), upper = line(o.upper);
    if (o.line !== undefined && options.lower === undefined && options.upper === undefined) {
      if (shape === 2) lower = line(o.line);
      if (shape === 3) upper = line(o.line);
    }
    const alphas = arr(o.alpha), betas = arr(o.beta), margins = arr(o.margin);
    const [rec, pts] = constraintArrays(o.constraints, this);
    const outP = this.alloc(4);
    this.resetError();
    const st = this.withArrays([x, f, userSlopes, alphas, betas, margins, rec, pts], (px, pf, pu, pa, pb, pm, pr, pp) =>
      (this.w.tsw_constraints(pr, rec ? rec.length / 5 : 0, pp), this.w.tsw_spline_new(px, pf, n, this.enumValue('form', o.form), slopes, pu,
        userSlopes ? userSlopes.length : 0, num(o.alpha, this.defaults.alpha), pa,
        alphas ? alphas.length : 0, num(o.beta, this.defaults.beta), pb, betas ? betas.length : 0,
        shape, lower[0], lower[1], upper[0], upper[1], num(o.margin, this.defaults.margin), pm,
        margins ? margins.length : 0, o.certify ? 1 : 0, this.enumValue('extrapolate', o.extrapolate),
        outP, this.errPtr)));
    const sp = this.u32(outP, 1)[0];
    this.w.free(outP);
    if (st !== 0) throw this.error(st);
    return new Spline(this, sp);
  }

  // curve(points, options): points an array of [x, y] or [x, y, z] rows (or a
  // flat array with options.dim).  options.param, .closed, .slopes, .alpha,
  // .beta (numbers or per-segment arrays), .box ({xmin, xmax, ymin, ymax,
  // zmin, zmax}, absent or infinite sides unbounded), .margin.
  curve(points, options = {}) {
    const o = { ...this.curveDefaults, ...options };
    let dim = o.dim, flat = points;
    if (Array.isArray(points) && Array.isArray(points[0])) {
      dim = points[0].length;
      flat = points.flat();
      if (flat.length !== dim * points.length) {
        throw new TrigSplineError(21, `${this.strerror(21)}: rows of different lengths`, null, null);
      }
    }
    dim ??= 2;
    numbersOf(flat, 'points', dim);
    const n = Math.floor(flat.length / dim);
    const box = this.boxArray(o.box);
    const arr = (v) => (typeof v === 'number' ? null : v);
    const num = (v, dflt) => (typeof v === 'number' ? v : dflt);
    const alphas = arr(o.alpha), betas = arr(o.beta);
    const outP = this.alloc(4);
    this.resetError();
    const st = this.withArrays([flat, alphas, betas, box], (pp, pa, pb, pbox) =>
      this.w.tsw_curve_new(pp, n, dim, this.enumValue('param', o.param), o.closed ? 1 : 0,
        this.enumValue('slopes', o.slopes), num(o.alpha, this.curveDefaults.alpha), pa,
        alphas ? alphas.length : 0, num(o.beta, this.curveDefaults.beta), pb,
        betas ? betas.length : 0, pbox, num(o.margin, this.curveDefaults.margin), outP, this.errPtr));
    const cp = this.u32(outP, 1)[0];
    this.w.free(outP);
    if (st !== 0) throw this.error(st);
    return new Curve(this, cp);
  }

  boxArray(box) {
    if (!box) return null;
    const b = new Float64Array(12);
    ['x', 'y', 'z'].forEach((k, i) => {
      const lo = box[`${k}min`], hi = box[`${k}max`];
      if (lo !== undefined && lo !== null && lo !== -Infinity) { b[i] = 1; b[3 + i] = lo; }
      if (hi !== undefined && hi !== null && hi !== Infinity) { b[6 + i] = 1; b[9 + i] = hi; }
    });
    return b;
  }

  // disaggregate(edges, totals, grid, options): bin totals (edges.length =
  // totals.length + 1) to the totals over the grid's cells (grid.length - 1
  // values), or with options.kind 'rate' / 'derivative' the rate r or r' at
  // the grid's points (docs/method.md §12: totals kept, lo <= r <= hi, C¹).
  // options.lo, .hi (default 0 and Infinity), .alpha (tension).
  disaggregate(edges, totals, grid, options = {}) {
    numbersOf(edges, 'edges');
    numbersOf(totals, 'totals');
    numbersOf(grid, 'grid');
    const kinds = ['totals', 'rate', 'derivative'];
    const kind = kinds.indexOf(options.kind ?? 'totals');
    if (kind < 0) {
      throw new TrigSplineError(11, `${this.strerror(11)}: kind must be one of ${kinds.join(', ')}`, null, null);
    }
    if (edges.length !== totals.length + 1) {
      throw new TrigSplineError(10, `${this.strerror(10)}: ${edges.length} edges for ${totals.length} totals`, null, null);
    }
    const d = this.withScratch(3, (p) => { this.w.tsw_histo_defaults(p); return Array.from(this.f64(p, 3)); });
    const m = grid.length, nOut = kind === 0 ? Math.max(m - 1, 0) : m;
    const out = this.alloc(Math.max(m, 1) * 8);
    try {
      this.resetError();
      const st = this.withArrays([edges, totals, grid], (pe, pt, pg) =>
        this.w.tsw_disaggregate(pe, pt, totals.length, pg, m, kind, options.alpha ?? d[0],
          options.lo ?? d[1], options.hi ?? d[2], out, this.errPtr));
      this.check(st);
      return Float64Array.from(this.f64(out, nOut));
    } finally { this.w.free(out); }
  }

  // Slopes by a method of docs/method.md §6, as a Float64Array.
  slopes(method, x, f) {
    const n = x.length;
    if (f.length !== n) throw new TrigSplineError(10, this.strerror(10), null, null);
    const out = this.alloc(n * 8);
    try {
      this.resetError();
      const st = this.withArrays([x, f], (px, pf) =>
        this.w.ts_slopes_compute(this.enumValue('slopes', method), px, pf, n, out, this.errPtr));
      this.check(st);
      return this.f64(out, n).slice();
    } finally { this.w.free(out); }
  }

  // Error constants {first, line, second} of one interval (docs/method.md §8).
  errorConstants(form, a) {
    return this.withScratch(3, (p) => {
      this.resetError();
      this.check(this.w.tsw_error_constants(this.enumValue('form', form), a, p));
      const [first, line, second] = this.f64(p, 3);
      return { first, line, second };
    });
  }

  rows(p, n) {
    const r = this.f64(p, n * ROW), out = [];
    for (let i = 0; i < n; i++) out.push(rowObject(r.subarray(i * ROW, (i + 1) * ROW)));
    return out;
  }
}

function rowObject(r) {
  return {
    x0: r[0], x1: r[1], alpha: r[2], beta: r[3], a: r[4], B: [r[5], r[6], r[7], r[8]],
    term: NAMES.term[r[9]], hasLower: r[10] !== 0, hasUpper: r[11] !== 0,
    gapLower: r[12], atLower: r[13], gapUpper: r[14], atUpper: r[15], certified: r[16] !== 0,
  };
}

class Handle {
  constructor(ts, ptr) {
    this.ts = ts;
    this.ptr = ptr;
  }
  live() {
    if (!this.ptr) throw new Error('trigspline: used after free()');
    return this.ptr;
  }
  [dispose]() { this.free(); }
}

export class Spline extends Handle {
  constructor(ts, ptr) {
    super(ts, ptr);
    this.cur = ts.alloc(4); // the lookup cursor (ts_cursor), owned here
    ts.u32(this.cur, 1)[0] = 0;
    this.n = ts.w.ts_spline_intervals(ptr);
  }
  free() {
    if (this.ptr) {
      this.ts.w.ts_spline_free(this.ptr);
      this.ts.w.free(this.cur);
      this.ptr = 0;
      this.cur = 0;
    }
  }
  get intervals() { return this.n; }
  get form() { return NAMES.form[this.ts.w.ts_spline_form(this.live())]; }
  get shape() { return NAMES.shape[this.ts.w.ts_spline_shape(this.live())]; }
  get extrapolate() { return NAMES.extrapolate[this.ts.w.ts_spline_extrapolation(this.live())]; }
  get certified() { return this.ts.w.ts_spline_certified(this.live()) === 1; }
  get x() { return this.ts.f64(this.ts.w.ts_spline_x(this.live()), this.n + 1).slice(); }
  get f() { return this.ts.f64(this.ts.w.ts_spline_f(this.live()), this.n + 1).slice(); }
  get slopes() { return this.ts.f64(this.ts.w.ts_spline_slopes(this.live()), this.n + 1).slice(); }
  get alpha() { return this.ts.f64(this.ts.w.ts_spline_alpha(this.live()), this.n).slice(); }
  get beta() { return this.ts.f64(this.ts.w.ts_spline_beta(this.live()), this.n).slice(); }

  // S(x)
  eval(x) { return this.evalDeriv(x).y; }
  // {y, dy, d2y} at x
  evalDeriv(x) {
    const ts = this.ts, p = ts.alloc(24);
    try {
      const st = ts.w.ts_spline_eval_deriv(this.live(), x, this.cur, p, p + 8, p + 16);
      if (st !== 0) {
        ts.u32(ts.errPtr, 3).set([0, NO_INDEX, 0]);
        throw ts.error(st);
      }
      const [y, dy, d2y] = ts.f64(p, 3);
      return { y, dy, d2y };
    } finally { ts.w.free(p); }
  }
  // S^(deriv) at every x of xs into out (a new Float64Array by default);
  // deriv >= 0 (above 2 in the paper and c1 forms only).  A query outside the
  // data (under extrapolate 'error') or NaN throws TS_ERR_DOMAIN naming the
  // first one; with partial the NaN-filled result is returned instead.
  // extrapolate (a name of NAMES.extrapolate) overrides the spline's policy
  // for this call (ts_spline_eval_batch_mode; ±Inf under 'linear': the limit).
  evalBatch(xs, deriv = 0, out = null, partial = false, extrapolate = null) {
    const ts = this.ts, m = xs.length;
    const px = ts.put(xs), py = ts.alloc(m * 8);
    try {
      ts.resetError();
      const st = extrapolate === null
        ? ts.w.ts_spline_eval_batch(this.live(), deriv, px, m, py, this.cur, ts.errPtr)
        : ts.w.ts_spline_eval_batch_mode(this.live(), deriv, extrapCode(extrapolate), px, m, py,
          this.cur, ts.errPtr);
      if (st !== 0 && !(partial && st === 13)) throw ts.error(st);
      out ??= new Float64Array(m);
      out.set(ts.f64(py, m));
      return out;
    } finally { ts.w.free(px); ts.w.free(py); }
  }
  // The derivative of order nu (>= 0; above 2 in the paper and c1 forms
  // only) as a function of x (and an optional extrapolate name overriding the
  // spline's policy), as scipy's PPoly.derivative: s.derivative(3)(1.5).
  derivative(nu = 1) {
    return (x, extrapolate = null) => {
      const ts = this.ts, p = ts.alloc(8);
      try {
        const mode = extrapolate === null ? ts.w.ts_spline_extrapolation(this.live())
          : extrapCode(extrapolate);
        const st = ts.w.ts_spline_eval_mode(this.live(), x, nu, mode, this.cur, p);
        if (st !== 0) { ts.resetError(); throw ts.error(st); }
        return ts.f64(p, 1)[0];
      } finally { ts.w.free(p); }
    };
  }
  // Every x in [x0, xn] with S(x) = y, increasing (Float64Array; an interval
  // on which S == y gives its left end then NaN, as scipy's PPoly.solve).
  solve(y = 0) {
    const ts = this.ts, pc = ts.alloc(4);
    let cap = 4 * this.n + 4, pr = 0;
    try {
      for (let pass = 0; pass < 2; pass++) {
        pr = ts.alloc(cap * 8);
        const st = ts.w.ts_spline_solve(this.live(), y, pr, cap, pc);
        const count = ts.u32(pc, 1)[0];
        if (st === 0) return ts.f64(pr, count).slice();
        ts.w.free(pr);
        pr = 0;
        if (st !== 10 || pass) { ts.resetError(); throw ts.error(st); }
        cap = count; // TS_ERR_LENGTH: the count needed
      }
      return new Float64Array(0);
    } finally { if (pr) ts.w.free(pr); ts.w.free(pc); }
  }
  // The interval i with x_i <= x < x_{i+1} (the last one at xn); throws
  // TS_ERR_DOMAIN outside [x0, xn].
  findInterval(x) {
    const ts = this.ts, p = ts.alloc(4);
    try {
      const st = ts.w.ts_spline_find_interval(this.live(), x, this.cur, p);
      if (st !== 0) { ts.resetError(); throw ts.error(st); }
      return ts.u32(p, 1)[0];
    } finally { ts.w.free(p); }
  }
  integral(a, b) {
    const ts = this.ts, p = ts.alloc(8);
    try {
      const st = ts.w.ts_spline_integral(this.live(), a, b, p);
      if (st !== 0) { ts.resetError(); throw ts.error(st); }
      return ts.f64(p, 1)[0];
    } finally { ts.w.free(p); }
  }
  // a_i = alpha_i + beta_i
  a(i) {
    const ts = this.ts, p = ts.alloc(8);
    try {
      const st = ts.w.ts_spline_a(this.live(), i, p);
      if (st !== 0) { ts.resetError(); throw ts.error(st); }
      return ts.f64(p, 1)[0];
    } finally { ts.w.free(p); }
  }
  // {B: [4 control values], X: [4 abscissae]} of interval i
  control(i) {
    const ts = this.ts, p = ts.alloc(64);
    try {
      const st = ts.w.ts_spline_control(this.live(), i, p, p + 32);
      if (st !== 0) { ts.resetError(); throw ts.error(st); }
      const v = ts.f64(p, 8);
      return { B: Array.from(v.subarray(0, 4)), X: Array.from(v.subarray(4)) };
    } finally { ts.w.free(p); }
  }
  // The per-interval report (interval i, or all intervals).
  report(i) {
    const ts = this.ts;
    if (i === undefined) return Array.from({ length: this.n }, (_, k) => this.report(k));
    const p = ts.alloc(ROW * 8);
    try {
      const st = ts.w.tsw_report(this.live(), i, p);
      if (st !== 0) { ts.resetError(); throw ts.error(st); }
      return rowObject(ts.f64(p, ROW));
    } finally { ts.w.free(p); }
  }
  // Constraint records (docs/method.md §13): per record, per interval, null
  // outside its scope or {active, gap, at, certified}.
  constraintReport() {
    const ts = this.ts, nc = ts.w.ts_spline_constraints(this.live()), p = ts.alloc(40);
    try {
      return Array.from({ length: nc }, (_, k) => Array.from({ length: this.n }, (_, i) => {
        const st = ts.w.tsw_constraint_report(this.live(), k, i, p);
        if (st !== 0) { ts.resetError(); throw ts.error(st); }
        const v = ts.f64(p, 5);
        return v[0] ? { active: !!v[1], gap: v[2], at: v[3], certified: !!v[4] } : null;
      }));
    } finally { ts.w.free(p); }
  }
  // Certify against lines {lower, upper} ({m, c} or a constant): returns
  // {ok, reports, index}; ok false means TS_ERR_VIOLATED (index = the first
  // violating interval).  Other failures throw.
  certify({ lower, upper } = {}) {
    const ts = this.ts;
    const line = (l) => (typeof l === 'number' ? [0, l] : [l.m ?? 0, l.c ?? 0]);
    const lo = lower === undefined || lower === null ? null : line(lower);
    const hi = upper === undefined || upper === null ? null : line(upper);
    const p = ts.alloc(this.n * ROW * 8);
    try {
      ts.resetError();
      const st = ts.w.tsw_certify(this.live(), lo ? 1 : 0, lo ? lo[0] : 0, lo ? lo[1] : 0,
        hi ? 1 : 0, hi ? hi[0] : 0, hi ? hi[1] : 0, p, ts.errPtr);
      if (st !== 0 && st !== 19) throw ts.error(st);
      return { ok: st === 0, index: st === 19 ? ts.u32(ts.errPtr, 3)[1] : null, reports: ts.rows(p, this.n) };
    } finally { ts.w.free(p); }
  }
  // A bound on max|f - S| (docs/method.md §8): {bound, perInterval}.
  errorBound(fprimeMax, fsecondMax = Infinity, exactSlopes = false) {
    const ts = this.ts, p = ts.alloc((this.n + 1) * 8);
    try {
      const st = ts.w.ts_spline_error_bound(this.live(), fprimeMax, fsecondMax, exactSlopes ? 1 : 0, p, p + 8);
      if (st !== 0) { ts.resetError(); throw ts.error(st); }
      return { bound: ts.f64(p, 1)[0], perInterval: ts.f64(p + 8, this.n).slice() };
    } finally { ts.w.free(p); }
  }
}

export class Curve extends Handle {
  constructor(ts, ptr) {
    super(ts, ptr);
    this.cur = ts.alloc(4);
    ts.u32(this.cur, 1)[0] = 0;
    this.segments = ts.w.ts_curve_segments(ptr);
    this.dim = ts.w.ts_curve_dim(ptr);
    this.closed = ts.w.ts_curve_closed(ptr) === 1;
  }
  free() {
    if (this.ptr) {
      this.ts.w.ts_curve_free(this.ptr);
      this.ts.w.free(this.cur);
      this.ptr = 0;
      this.cur = 0;
    }
  }
  get knots() { return this.ts.f64(this.ts.w.ts_curve_knots(this.live()), this.segments + 1).slice(); }
  // {p, dp, d2p} at parameter t (arrays of dim numbers)
  eval(t) {
    const ts = this.ts, d = this.dim, p = ts.alloc(24 * d);
    try {
      const st = ts.w.ts_curve_eval(this.live(), t, this.cur, p, p + 8 * d, p + 16 * d);
      if (st !== 0) { ts.resetError(); throw ts.error(st); }
      const v = ts.f64(p, 3 * d);
      return { p: Array.from(v.subarray(0, d)), dp: Array.from(v.subarray(d, 2 * d)), d2p: Array.from(v.subarray(2 * d)) };
    } finally { ts.w.free(p); }
  }
  // m samples per segment: a Float64Array of rows (t, x, y[, z]).
  sample(m = 50) {
    const ts = this.ts, rp = ts.alloc(4);
    try {
      let st = ts.w.ts_curve_sample(this.live(), m, 0, 0, rp);
      if (st !== 0 && st !== 10) { ts.resetError(); throw ts.error(st); }
      const rows = ts.u32(rp, 1)[0], len = rows * (1 + this.dim), out = ts.alloc(len * 8);
      try {
        st = ts.w.ts_curve_sample(this.live(), m, out, len, rp);
        if (st !== 0) { ts.resetError(); throw ts.error(st); }
        return ts.f64(out, len).slice();
      } finally { ts.w.free(out); }
    } finally { ts.w.free(rp); }
  }
  // {alpha, beta} of segment i
  params(i) {
    const ts = this.ts, p = ts.alloc(16);
    try {
      const st = ts.w.ts_curve_params(this.live(), i, p, p + 8);
      if (st !== 0) { ts.resetError(); throw ts.error(st); }
      const [alpha, beta] = ts.f64(p, 2);
      return { alpha, beta };
    } finally { ts.w.free(p); }
  }
  // 4 rows of dim control values of segment i
  control(i) {
    const ts = this.ts, d = this.dim, p = ts.alloc(32 * d);
    try {
      const st = ts.w.ts_curve_control(this.live(), i, p);
      if (st !== 0) { ts.resetError(); throw ts.error(st); }
      const v = ts.f64(p, 4 * d);
      return [0, 1, 2, 3].map((l) => Array.from(v.subarray(l * d, (l + 1) * d)));
    } finally { ts.w.free(p); }
  }
  length(tol = 0) {
    const ts = this.ts, p = ts.alloc(8);
    try {
      const st = ts.w.ts_curve_length(this.live(), tol, p);
      if (st !== 0) { ts.resetError(); throw ts.error(st); }
      return ts.f64(p, 1)[0];
    } finally { ts.w.free(p); }
  }
  // Certificate against the curve's own box, or against box: {ok, index,
  // reports} with reports[i*dim + k] for segment i, coordinate k.
  certify(box) {
    const ts = this.ts, n = this.segments * this.dim, p = ts.alloc(n * ROW * 8);
    try {
      ts.resetError();
      const st = ts.withArrays([box ? ts.boxArray(box) : null], (pb) =>
        ts.w.tsw_curve_certify(this.live(), pb, p, ts.errPtr));
      if (st !== 0 && st !== 19) throw ts.error(st);
      return { ok: st === 0, index: st === 19 ? ts.u32(ts.errPtr, 3)[1] : null, reports: ts.rows(p, n) };
    } finally { ts.w.free(p); }
  }
}
