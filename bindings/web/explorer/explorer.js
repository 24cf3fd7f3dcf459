// The explorer page (index.html): the state, its fit, the drawing and the
// controls.  Every change goes through update(): fit and certify with the
// wasm module, draw, fill the certificate table, write the state into the URL.
/* global createTrigsplineCli */
import { load, NAMES } from '../trigspline.js';
import { exportState, cliArgs, runCli, dataCsv, isoText } from '../export.js';
import { numberTicks, dateTicks, niceStep } from './ticks.js';
import { readTable } from './reader.js';

const ts = await load();
const $ = (id) => document.getElementById(id);
// the choices of the enum selects: the library's names (NAMES), not restated in index.html
for (const [id, skip] of [['form', []], ['param', []], ['slopes', ['user', 'periodic']]]) {
  $(id).replaceChildren(...NAMES[id].filter((n) => !skip.includes(n)).map((n) => new Option(n)));
}
const svg = $('plot');
const W = 760, H = 480, M = { l: 58, r: 14, t: 14, b: 40 };
const NS = 'http://www.w3.org/2000/svg';

// The paper's Table 1 (data/paper/table1_positive.csv) as the first view.
const DEFAULT = {
  mode: 'function',
  points: [[0, 2], [2, 1.58], [3, 1.55], [5, 1.54], [15, 1.8], [25, 1.54], [27, 1.55], [28, 1.58], [30, 2]],
  scheme: 'positive', form: ts.defaults.form, slopes: ts.defaults.slopes, alpha: ts.defaults.alpha,
  alphas: null, beta: 0,
  margin: ts.defaults.margin, lower: { m: 0, c: 1.45 }, upper: { m: 0, c: 2.2 },
  closed: false, param: 'centripetal', box: { on: true, xmin: -1, xmax: 31, ymin: 1.2, ymax: 2.4 },
  overlay: { cubic: true, pchip: false },
  xTime: false, names: null, // x as dates (seconds since 1970, UTC); the data's column names
};
let state = readHash() ?? structuredClone(DEFAULT);
let view = null; // {x0, x1, y0, y1}
let selected = null; // interval with its own α slider
let result = null; // {ok, error, rows, path, bad}
const timings = []; // per update(): {fit, total} in ms

function readHash() {
  const h = location.hash.slice(1);
  if (!h.startsWith('s=')) return null;
  try { return { ...structuredClone(DEFAULT), ...JSON.parse(decodeURIComponent(h.slice(2))) }; } catch { return null; }
}
let hashTimer = 0;
function writeHash() {
  clearTimeout(hashTimer);
  hashTimer = setTimeout(() => history.replaceState(null, '', `#s=${encodeURIComponent(JSON.stringify(state))}`), 150);
}

// ---- coordinates --------------------------------------------------------
function fitView() {
  const P = state.points;
  let x0 = Math.min(...P.map((p) => p[0])), x1 = Math.max(...P.map((p) => p[0]));
  let y0 = Math.min(...P.map((p) => p[1])), y1 = Math.max(...P.map((p) => p[1]));
  if (state.mode === 'function') {
    if (state.scheme === 'positive') y0 = Math.min(y0, 0);
    for (const l of lines()) for (const x of [x0, x1]) { y0 = Math.min(y0, l.m * x + l.c); y1 = Math.max(y1, l.m * x + l.c); }
  } else if (state.box.on) {
    x0 = Math.min(x0, state.box.xmin); x1 = Math.max(x1, state.box.xmax);
    y0 = Math.min(y0, state.box.ymin); y1 = Math.max(y1, state.box.ymax);
  }
  const dx = (x1 - x0) || 1, dy = (y1 - y0) || 1;
  view = { x0: x0 - 0.06 * dx, x1: x1 + 0.06 * dx, y0: y0 - 0.12 * dy, y1: y1 + 0.12 * dy };
}
const sx = (x) => M.l + ((x - view.x0) / (view.x1 - view.x0)) * (W - M.l - M.r);
const sy = (y) => H - M.b - ((y - view.y0) / (view.y1 - view.y0)) * (H - M.t - M.b);
const ix = (px) => view.x0 + ((px - M.l) / (W - M.l - M.r)) * (view.x1 - view.x0);
const iy = (py) => view.y0 + ((H - M.b - py) / (H - M.t - M.b)) * (view.y1 - view.y0);
function svgPoint(ev) {
  const p = svg.createSVGPoint();
  p.x = ev.clientX; p.y = ev.clientY;
  return p.matrixTransform(svg.getScreenCTM().inverse());
}
function lines() {
  const s = state.scheme, L = [];
  if (s === 'above' || s === 'between') L.push({ ...state.lower, which: 'lower' });
  if (s === 'below' || s === 'between') L.push({ ...state.upper, which: 'upper' });
  return L;
}

// ---- fit -------------------------------------------------------------------
function alphaOption() { return state.alphas ?? state.alpha; }

function fitFunction() {
  const P = state.points, x = P.map((p) => p[0]), f = P.map((p) => p[1]);
  const opt = { form: state.form, slopes: state.slopes, shape: state.scheme, alpha: alphaOption(), margin: state.margin, lower: state.lower, upper: state.upper };
  if (state.scheme === 'none') opt.beta = state.beta;
  const s = ts.spline(x, f, opt);
  try {
    const rows = s.report();
    const n = x.length - 1, K = Math.max(4, Math.min(48, Math.ceil(6000 / n)));
    const xs = new Float64Array(n * K + 1);
    for (let i = 0; i < n; i++) for (let j = 0; j < K; j++) xs[i * K + j] = x[i] + (x[i + 1] - x[i]) * (j / K);
    xs[n * K] = x[n];
    const ys = s.evalBatch(xs);
    return { ok: true, rows, xs, ys, certified: s.certified, dims: 1 };
  } finally { s.free(); }
}

function fitCurve() {
  const b = state.box;
  const c = ts.curve(state.points, {
    closed: state.closed, param: state.param, slopes: state.slopes, alpha: alphaOption(), beta: state.beta,
    margin: state.margin, box: b.on ? { xmin: b.xmin, xmax: b.xmax, ymin: b.ymin, ymax: b.ymax } : null,
  });
  try {
    const n = c.segments, K = Math.max(4, Math.min(48, Math.ceil(6000 / n)));
    const r = c.sample(K + 1), xs = [], ys = [];
    for (let k = 0; k < r.length; k += 3) { xs.push(r[k + 1]); ys.push(r[k + 2]); }
    const cert = c.certify(b.on ? undefined : { xmin: -Infinity });
    const rows = cert.reports.map((rep, k) => ({ ...rep, seg: Math.floor(k / 2), coord: 'xy'[k % 2], ...c.params(Math.floor(k / 2)) }));
    return { ok: true, rows, xs, ys, certified: b.on ? cert.ok : null, dims: 2 };
  } finally { c.free(); }
}

function update() {
  const t0 = performance.now();
  try {
    result = state.mode === 'function' ? fitFunction() : fitCurve();
  } catch (e) {
    if (e.name !== 'TrigSplineError') throw e;
    result = { ok: false, error: e };
  }
  const t1 = performance.now();
  drawPlot();
  const t2 = performance.now();
  renderSide();
  const t3 = performance.now();
  timings.push({ fit: t1 - t0, plot: t2 - t1, side: t3 - t2, total: t3 - t0, n: state.points.length });
  if (timings.length > 2000) timings.splice(0, 1000);
  writeHash();
  scheduleOvershoot();
}

// The command's overshoot warning for the current state, next to the
// certificate: the same command line as the exports, run (after the state has
// settled) by the command itself, its "warning:" line shown as it prints it.
let ovSeq = 0, ovTimer = 0;
function scheduleOvershoot() {
  clearTimeout(ovTimer);
  const seq = ++ovSeq, box = $('overshoot');
  if (state.mode !== 'function' || !result.ok) {
    box.textContent = '';
    box.className = '';
    box.dataset.state = 'done';
    return;
  }
  // until the command has answered, the last warning is shown faded
  box.dataset.state = 'pending';
  box.className = 'stale';
  const snap = structuredClone(state);
  ovTimer = setTimeout(async () => {
    let text = '';
    try {
      const r = await runCli(createTrigsplineCli, [...cliArgs(snap), '--json', '-o', 'out.json'], { 'data.csv': dataCsv(snap) });
      const w = r.stderr.split('\n').find((l) => l.startsWith('trigspline: warning: '));
      if (w) text = w.slice('trigspline: '.length);
    } catch { /* the warning stays empty */ }
    if (seq !== ovSeq) return;
    box.textContent = text;
    box.className = '';
    box.dataset.state = 'done';
    renderStatus();
  }, dragging ? 400 : 60);
}

// ---- comparison curves (function mode) ----------------------------------------
function naturalCubic(x, f, xs) {
  const n = x.length - 1, h = [], a = new Array(n + 1).fill(0), b = new Array(n + 1).fill(1), c = new Array(n + 1).fill(0), d = new Array(n + 1).fill(0);
  for (let i = 0; i < n; i++) h.push(x[i + 1] - x[i]);
  for (let i = 1; i < n; i++) {
    a[i] = h[i - 1] / 6; b[i] = (h[i - 1] + h[i]) / 3; c[i] = h[i] / 6;
    d[i] = (f[i + 1] - f[i]) / h[i] - (f[i] - f[i - 1]) / h[i - 1];
  }
  for (let i = 1; i <= n; i++) { const w = a[i] / b[i - 1]; b[i] -= w * c[i - 1]; d[i] -= w * d[i - 1]; } // Thomas
  const m = new Array(n + 1).fill(0);
  for (let i = n - 1; i >= 1; i--) m[i] = (d[i] - c[i] * m[i + 1]) / b[i];
  m[n] = 0;
  let i = 0;
  return Array.from(xs, (v) => {
    while (i < n - 1 && v > x[i + 1]) i++;
    const A = (x[i + 1] - v) / h[i], B = (v - x[i]) / h[i];
    return A * f[i] + B * f[i + 1] + ((A ** 3 - A) * m[i] + (B ** 3 - B) * m[i + 1]) * h[i] * h[i] / 6;
  });
}
function hermite(x, f, d, xs) {
  const n = x.length - 1;
  let i = 0;
  return Array.from(xs, (v) => {
    while (i < n - 1 && v > x[i + 1]) i++;
    const h = x[i + 1] - x[i], t = (v - x[i]) / h, t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * f[i] + (t3 - 2 * t2 + t) * h * d[i] + (-2 * t3 + 3 * t2) * f[i + 1] + (t3 - t2) * h * d[i + 1];
  });
}

// ---- drawing -------------------------------------------------------------------------
const esc = (t) => String(t).replace(/[&<>"]/g, (c) => `&#${c.charCodeAt(0)};`);
const timeAxis = () => state.mode === 'function' && !!state.xTime;
const xText = (v) => (timeAxis() ? isoText(v) : fmt(v));
const fmt = (v) => (v === null || Number.isNaN(v) ? '–' : Math.abs(v) >= 1e4 || (Math.abs(v) < 1e-3 && v !== 0) ? v.toExponential(3) : +v.toPrecision(5));
function polyline(xs, ys) {
  let d = '';
  for (let k = 0; k < xs.length; k++) d += `${k ? 'L' : 'M'}${sx(xs[k]).toFixed(2)},${sy(ys[k]).toFixed(2)}`;
  return d;
}
function el(name, attrs, parent = layer) {
  const e = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  parent.appendChild(e);
  return e;
}

// The data points are a layer of their own, rebuilt only when their number,
// the mode or the view change (not on every frame of a drag).
const layer = document.createElementNS(NS, 'g'), pointLayer = document.createElementNS(NS, 'g');
let pointsKey = '', focusPoint = 0, focusKey = '';
svg.append(layer, pointLayer);
function render() {
  drawPlot();
  renderSide();
}
function renderSide() {
  renderStatus();
  renderTable();
  renderData();
  syncControls();
}
function drawPlot() {
  layer.replaceChildren();
  document.body.className = state.mode;
  const X0 = sx(view.x0), X1 = sx(view.x1);
  // forbidden regions
  if (state.mode === 'function') {
    const shade = (l, below) => {
      const ya = sy(l.m * view.x0 + l.c), yb = sy(l.m * view.x1 + l.c), edge = below ? H : 0;
      el('path', { class: 'forbidden', d: `M${X0},${ya}L${X1},${yb}L${X1},${edge}L${X0},${edge}Z` });
    };
    if (state.scheme === 'positive') shade({ m: 0, c: 0 }, true);
    if (state.scheme === 'above' || state.scheme === 'between') shade(state.lower, true);
    if (state.scheme === 'below' || state.scheme === 'between') shade(state.upper, false);
  } else if (state.box.on) {
    const b = state.box;
    el('path', { class: 'forbidden', 'fill-rule': 'evenodd', d: `M0,0H${W}V${H}H0Z M${sx(b.xmin)},${sy(b.ymin)}H${sx(b.xmax)}V${sy(b.ymax)}H${sx(b.xmin)}Z` });
  }
  // axes
  el('line', { class: 'axis', x1: M.l, y1: H - M.b, x2: W - M.r, y2: H - M.b });
  el('line', { class: 'axis', x1: M.l, y1: M.t, x2: M.l, y2: H - M.b });
  const xt = timeAxis() ? dateTicks(view.x0, view.x1, 5) : numberTicks(view.x0, view.x1, 8);
  const yt = numberTicks(view.y0, view.y1, 8);
  xt.values.forEach((v, k) => {
    el('line', { class: 'grid', x1: sx(v), y1: M.t, x2: sx(v), y2: H - M.b });
    el('line', { class: 'axis', x1: sx(v), y1: H - M.b, x2: sx(v), y2: H - M.b + 4 });
    el('text', { class: 'tick xtick', x: sx(v), y: H - M.b + 15, 'text-anchor': 'middle', 'data-v': v }).textContent = xt.labels[k];
  });
  // axis titles: the data's column names
  const names = state.mode === 'curve' ? ['x', 'y'] : state.names ?? ['x', 'f'];
  el('text', { class: 'atitle', x: (M.l + W - M.r) / 2, y: H - 6, 'text-anchor': 'middle' }).textContent = names[0];
  el('text', { class: 'atitle', x: 0, y: 0, 'text-anchor': 'middle', transform: `translate(13,${(M.t + H - M.b) / 2}) rotate(-90)` }).textContent = names[1];
  yt.values.forEach((v, k) => {
    el('line', { class: 'grid', x1: M.l, y1: sy(v), x2: W - M.r, y2: sy(v) });
    el('line', { class: 'axis', x1: M.l - 4, y1: sy(v), x2: M.l, y2: sy(v) });
    el('text', { class: 'tick ytick', x: M.l - 6, y: sy(v) + 3, 'text-anchor': 'end', 'data-v': v }).textContent = yt.labels[k];
  });
  const P = state.points;
  // selected / refused interval bands
  const band = (i, cls, why) => {
    if (state.mode !== 'function' || i === null || i < 0 || i + 1 >= P.length) return;
    const b = el('rect', { class: cls, x: sx(P[i][0]), y: M.t, width: Math.max(1, sx(P[i + 1][0]) - sx(P[i][0])), height: H - M.t - M.b, 'data-interval': i });
    if (why) el('title', {}, b).textContent = why;
  };
  band(selected, 'selint');
  if (!result.ok && result.error.where === 'interval') band(result.error.index, 'badint', result.error.message);
  if (result.ok) result.rows.forEach((r, i) => { if (state.mode === 'function' && !r.certified && state.scheme !== 'none') band(i, 'badint', 'not certified'); });
  // comparison curves
  if (state.mode === 'function' && result.ok && P.length > 2) {
    const x = P.map((p) => p[0]), f = P.map((p) => p[1]);
    if (state.overlay.cubic) el('path', { class: 'cubic', id: 'cubic', d: polyline(result.xs, naturalCubic(x, f, result.xs)) });
    if (state.overlay.pchip) {
      const d = ts.slopes('fritsch-carlson', x, f);
      el('path', { class: 'pchip', id: 'pchip', d: polyline(result.xs, hermite(x, f, d, result.xs)) });
    }
  }
  if (result.ok) el('path', { class: 'curve', id: 'curve', d: polyline(result.xs, result.ys) });
  // legend of the curves drawn
  const keys = [['curve', 'trigspline']];
  if (state.mode === 'function' && state.overlay.cubic) keys.push(['cubic', 'natural cubic']);
  if (state.mode === 'function' && state.overlay.pchip) keys.push(['pchip', 'PCHIP']);
  keys.forEach(([cls, name], k) => {
    const y = M.t + 12 + 14 * k;
    el('line', { class: cls, x1: W - M.r - 130, y1: y, x2: W - M.r - 104, y2: y });
    el('text', { class: 'tick', x: W - M.r - 98, y: y + 3 }).textContent = name;
  });
  // constraint lines with their end handles, box corners
  if (state.mode === 'function') {
    for (const l of lines()) {
      el('line', { class: 'cline', x1: X0, y1: sy(l.m * view.x0 + l.c), x2: X1, y2: sy(l.m * view.x1 + l.c) });
      [view.x0, view.x1].forEach((xe, end) => el('rect', {
        class: 'handle', x: sx(xe) - 6 + (end ? -6 : 6), y: sy(l.m * xe + l.c) - 6, width: 12, height: 12,
        fill: '#d0021b', 'data-line': l.which, 'data-end': end,
      }));
    }
  } else if (state.box.on) {
    const b = state.box;
    el('rect', { x: sx(b.xmin), y: sy(b.ymax), width: sx(b.xmax) - sx(b.xmin), height: sy(b.ymin) - sy(b.ymax), fill: 'none', stroke: '#d0021b' });
    [['min', b.xmin, b.ymin], ['max', b.xmax, b.ymax]].forEach(([k, xv, yv]) => el('rect', {
      class: 'handle', x: sx(xv) - 6, y: sy(yv) - 6, width: 12, height: 12, fill: '#d0021b', 'data-corner': k,
    }));
  }
  const badPoint = !result.ok && result.error.where === 'point' ? result.error.index : -1;
  const key = `${state.mode}:${P.length}:${view.x0}:${view.x1}:${view.y0}:${view.y1}`;
  if (key !== pointsKey) {
    pointsKey = key;
    pointLayer.replaceChildren();
    const r = P.length > 300 ? 2.5 : 5;
    // one tab stop for the points (roving tabindex, keys below)
    P.forEach((_, i) => el('circle', {
      class: 'pt', r, 'data-i': i, tabindex: -1, role: 'button', 'aria-roledescription': 'data point', 'aria-describedby': 'kbhelp',
    }, pointLayer));
    focusPoint = Math.min(focusPoint, P.length - 1);
    focusKey = '';
  }
  const circles = pointLayer.children;
  const yName = state.mode === 'curve' ? 'y' : (state.names && state.names[1]) || 'f';
  const xName = state.mode === 'curve' ? 'x' : (state.names && state.names[0]) || 'x';
  const labelled = focusKey === key;
  P.forEach(([x, y], i) => {
    const c = circles[i], cx = sx(x).toFixed(2), cy = sy(y).toFixed(2), cls = i === badPoint ? 'pt bad' : 'pt';
    if (c.getAttribute('cx') !== cx) c.setAttribute('cx', cx);
    if (c.getAttribute('cy') !== cy) c.setAttribute('cy', cy);
    if (c.getAttribute('class') !== cls) c.setAttribute('class', cls);
    const ti = i === focusPoint ? '0' : '-1';
    if (c.getAttribute('tabindex') !== ti) c.setAttribute('tabindex', ti);
    // labels: all when the points are new, else only those that moved
    if (!labelled || c.dataset.at !== `${x},${y}`) {
      c.dataset.at = `${x},${y}`;
      c.setAttribute('aria-label', `point ${i + 1} of ${P.length}: ${xName} = ${xText(x)}, ${yName} = ${fmt(y)}${i === badPoint ? ' (refused)' : ''}`);
    }
  });
  focusKey = key;
}

function renderStatus() {
  const st = $('status');
  if (!result.ok) {
    const e = result.error;
    st.className = 'bad';
    st.textContent = `Refused: ${e.message}`;
    return;
  }
  st.className = state.mode === 'function' && $('overshoot').textContent ? 'ok warn' : 'ok';
  const n = result.rows.length, cert = result.rows.filter((r) => r.certified).length;
  st.textContent = state.mode === 'function'
    ? (state.scheme === 'none' ? `${n} intervals, no region (scheme none)` : `${cert} of ${n} intervals certified inside the region`)
    : (state.box.on ? `${result.certified ? 'certified' : 'NOT certified'} inside the box (${n / 2} segments)` : `${n / 2} segments, no box`);
}

const MAXROWS = 60;
function renderTable() {
  const t = $('cert');
  if (!result.ok) { t.innerHTML = ''; return; }
  const rows = result.rows;
  let html;
  if (state.mode === 'function') {
    html = '<tr><th>i</th><th>x₀</th><th>x₁</th><th>α</th><th>β</th><th>term</th><th>gap lower</th><th>gap upper</th><th>✓</th></tr>';
    rows.slice(0, MAXROWS).forEach((r, i) => {
      html += `<tr data-interval="${i}" class="${i === selected ? 'sel' : ''}${r.certified || state.scheme === 'none' ? '' : ' fail'}"><td>${i}</td><td>${xText(r.x0)}</td><td>${xText(r.x1)}</td><td>${fmt(r.alpha)}</td><td>${fmt(r.beta)}</td><td>${r.term}</td><td>${fmt(r.gapLower)}</td><td>${fmt(r.gapUpper)}</td><td>${state.scheme === 'none' ? '' : r.certified ? '✓' : '✗'}</td></tr>`;
    });
  } else {
    html = '<tr><th>seg</th><th>coord</th><th>α</th><th>β</th><th>gap low</th><th>gap high</th><th>✓</th></tr>';
    rows.slice(0, MAXROWS).forEach((r, k) => {
      html += `<tr data-interval="${r.seg}" class="${r.certified || !state.box.on ? '' : 'fail'}"><td>${r.seg}</td><td>${r.coord}</td><td>${fmt(r.alpha)}</td><td>${fmt(r.beta)}</td><td>${fmt(r.gapLower)}</td><td>${fmt(r.gapUpper)}</td><td>${state.box.on ? (r.certified ? '✓' : '✗') : ''}</td></tr>`;
    });
  }
  if (rows.length > MAXROWS) html += `<tr><td colspan="9">… ${rows.length - MAXROWS} more rows (all in the JSON export)</td></tr>`;
  t.innerHTML = html;
}

let dataShown = '';
function renderData() {
  const P = state.points, key = `${state.mode}:${P.length}`;
  if (dragging && dataShown === key) return; // the table is rebuilt when the drag ends
  dataShown = key;
  const head = state.mode === 'curve' ? ['x', 'y'] : (state.names ?? ['x', 'f']);
  const xin = timeAxis() ? (p, i) => `<input type="text" size="22" data-row="${i}" data-col="0" value="${isoText(p[0])}" aria-label="${esc(head[0])} of point ${i + 1}">`
    : (p, i) => `<input type="number" step="any" data-row="${i}" data-col="0" value="${p[0]}" aria-label="${esc(head[0])} of point ${i + 1}">`;
  $('datatable').innerHTML = P.length > 200 ? `<tr><td>${P.length} points: edit them as CSV below</td></tr>`
    : `<tr><th>#</th><th>${esc(head[0])}</th><th>${esc(head[1])}</th></tr>${P.map((p, i) => `<tr><td>${i}</td><td>${xin(p, i)}</td><td><input type="number" step="any" data-row="${i}" data-col="1" value="${p[1]}" aria-label="${esc(head[1])} of point ${i + 1}"></td></tr>`).join('')}`;
  if (document.activeElement !== $('csv')) $('csv').value = dataCsv(state);
}

function syncControls() {
  document.querySelector(`input[name=mode][value=${state.mode}]`).checked = true;
  $('scheme').value = state.scheme; $('form').value = state.form; $('slopes').value = state.slopes;
  $('closed').checked = state.closed; $('param').value = state.param; $('boxon').checked = state.box.on;
  $('alpha').value = Math.log10(state.alpha); $('alphaout').textContent = fmt(state.alpha);
  $('ovcubic').checked = state.overlay.cubic; $('ovpchip').checked = state.overlay.pchip;
  if (document.activeElement !== $('beta')) $('beta').value = state.beta;
  if (document.activeElement !== $('margin')) $('margin').value = state.margin;
  $('betabox').style.display = state.mode === 'curve' || state.scheme === 'none' ? '' : 'none';
  $('marginbox').style.display = state.mode === 'curve' ? (state.box.on ? '' : 'none') : (state.scheme === 'none' ? 'none' : '');
  const nInt = state.mode === 'function' || !state.closed ? state.points.length - 1 : state.points.length;
  if (selected !== null && selected >= nInt) selected = null;
  $('ialphabox').style.display = selected === null ? 'none' : '';
  if (selected !== null) {
    const a = state.alphas ? state.alphas[selected] : state.alpha;
    $('isel').textContent = selected; $('ialpha').value = Math.log10(a); $('ialphaout').textContent = fmt(a);
  }
  $('cmdline').textContent = `trigspline ${cliArgs(state).join(' ')}`;
}

// ---- interaction ------------------------------------------------------------------------
let dragging = null;
svg.addEventListener('pointerdown', (ev) => {
  const t = ev.target;
  if (t.dataset.i !== undefined) {
    dragging = { kind: 'point', i: +t.dataset.i };
    focusOn(+t.dataset.i, false);
  }
  else if (t.dataset.line !== undefined) dragging = { kind: 'line', which: t.dataset.line, end: +t.dataset.end };
  else if (t.dataset.corner !== undefined) dragging = { kind: 'corner', which: t.dataset.corner };
  else if (t.dataset.interval !== undefined) { selected = +t.dataset.interval; render(); return; }
  else {
    // an interval of the function by its x
    const p = svgPoint(ev), x = ix(p.x), P = state.points;
    if (state.mode === 'function') {
      const i = P.findIndex((q, k) => k + 1 < P.length && q[0] <= x && x < P[k + 1][0]);
      selected = i >= 0 ? i : null;
      render();
    }
    return;
  }
  svg.setPointerCapture(ev.pointerId);
  ev.preventDefault();
});
let pending = null;
svg.addEventListener('pointermove', (ev) => {
  if (!dragging) return;
  pending = svgPoint(ev);
  requestAnimationFrame(applyDrag);
});
function applyDrag() {
  if (!pending || !dragging) return;
  const x = ix(pending.x), y = iy(pending.y);
  pending = null;
  moveTo(dragging, x, y);
}
// Move what is dragged to data coordinates (x, y) and refit.
function moveTo(d, x, y) {
  const P = state.points;
  if (d.kind === 'point') {
    if (state.mode === 'function') {
      // keep x strictly between the neighbours
      const lo = d.i > 0 ? P[d.i - 1][0] : -Infinity, hi = d.i + 1 < P.length ? P[d.i + 1][0] : Infinity;
      const eps = 1e-9 * (Math.abs(view.x1 - view.x0));
      x = Math.min(Math.max(x, lo + eps), hi - eps);
    }
    P[d.i] = [x, y];
  } else if (d.kind === 'line') {
    const l = state[d.which], xa = view.x0, xb = view.x1;
    const ya = d.end === 0 ? y : l.m * xa + l.c, yb = d.end === 1 ? y : l.m * xb + l.c;
    const m = (yb - ya) / (xb - xa);
    state[d.which] = { m, c: ya - m * xa };
  } else if (d.kind === 'corner') {
    if (d.which === 'min') { state.box.xmin = x; state.box.ymin = y; } else { state.box.xmax = x; state.box.ymax = y; }
  }
  update();
}
function endDrag() {
  if (!dragging) return;
  applyDrag();
  dragging = null;
  dataShown = '';
  renderData();
}
svg.addEventListener('pointerup', endDrag);
svg.addEventListener('pointercancel', endDrag);
svg.addEventListener('dblclick', (ev) => {
  const P = state.points;
  if (ev.target.dataset.i !== undefined) {
    if (P.length > 2) P.splice(+ev.target.dataset.i, 1);
  } else {
    const p = svgPoint(ev), x = ix(p.x), y = iy(p.y);
    if (state.mode === 'function') {
      const k = P.findIndex((q) => q[0] > x);
      if (P.some((q) => q[0] === x)) return;
      P.splice(k < 0 ? P.length : k, 0, [x, y]);
    } else P.push([x, y]);
  }
  state.alphas = null;
  update();
});

const on = (id, evn, fn) => $(id).addEventListener(evn, fn);
document.querySelectorAll('input[name=mode]').forEach((r) => r.addEventListener('change', () => {
  state.mode = r.value;
  if (state.mode === 'curve' && state.points.length < 3) state.points.push([0, 0]);
  if (state.mode === 'function') state.points.sort((a, b) => a[0] - b[0]);
  state.alphas = null; selected = null;
  fitView(); update();
}));
on('scheme', 'change', () => { state.scheme = $('scheme').value; fitView(); update(); });
on('form', 'change', () => { state.form = $('form').value; update(); });
on('slopes', 'change', () => { state.slopes = $('slopes').value; update(); });
on('closed', 'change', () => { state.closed = $('closed').checked; state.alphas = null; update(); });
on('param', 'change', () => { state.param = $('param').value; update(); });
on('boxon', 'change', () => { state.box.on = $('boxon').checked; fitView(); update(); });
on('alpha', 'input', () => { state.alpha = +(10 ** +$('alpha').value).toPrecision(3); state.alphas = null; update(); });
on('ialpha', 'input', () => {
  const n = state.mode === 'function' || !state.closed ? state.points.length - 1 : state.points.length;
  state.alphas ??= new Array(n).fill(state.alpha);
  state.alphas[selected] = +(10 ** +$('ialpha').value).toPrecision(3);
  update();
});
on('beta', 'change', () => { state.beta = +$('beta').value; update(); });
on('margin', 'change', () => { state.margin = +$('margin').value; update(); });
on('ovcubic', 'change', () => { state.overlay.cubic = $('ovcubic').checked; update(); });
on('ovpchip', 'change', () => { state.overlay.pchip = $('ovpchip').checked; update(); });
on('cert', 'click', (ev) => {
  const tr = ev.target.closest('tr[data-interval]');
  if (tr) { selected = +tr.dataset.interval; render(); }
});
on('datatable', 'change', (ev) => {
  const t = ev.target;
  if (t.dataset.row === undefined) return;
  // a date as the command reads it: no zone means UTC
  const v = timeAxis() && t.dataset.col === '0'
    ? Date.parse(/[zZ]|[+-]\d\d:?\d\d$/.test(t.value) || !t.value.includes('T') ? t.value : `${t.value}Z`) / 1000 : +t.value;
  if (!Number.isFinite(v) || t.value === '') return;
  state.points[+t.dataset.row][+t.dataset.col] = v;
  update();
});
// ---- keyboard: the points (WCAG 2.1.1) -----------------------------------------------------
// One tab stop (the last point focused); arrows move it by a tenth of a tick
// step (Shift: a tick step), Page Up/Down and Home/End pick another point,
// Delete removes it.
function focusOn(k, focus = true) {
  const C = pointLayer.children;
  if (!C.length) return;
  focusPoint = Math.max(0, Math.min(k, C.length - 1));
  for (let j = 0; j < C.length; j++) C[j].setAttribute('tabindex', j === focusPoint ? '0' : '-1');
  if (focus) C[focusPoint].focus();
}
pointLayer.addEventListener('focusin', (ev) => {
  if (ev.target.dataset.i !== undefined && +ev.target.dataset.i !== focusPoint) focusOn(+ev.target.dataset.i, false);
});
pointLayer.addEventListener('keydown', (ev) => {
  const t = ev.target;
  if (t.dataset.i === undefined || ev.altKey || ev.ctrlKey || ev.metaKey) return;
  const i = +t.dataset.i, P = state.points, f = ev.shiftKey ? 10 : 1;
  const dx = (f * niceStep(view.x0, view.x1, 8)) / 10, dy = (f * niceStep(view.y0, view.y1, 8)) / 10;
  const round = (v) => +v.toPrecision(12);
  const moves = { ArrowLeft: [-dx, 0], ArrowRight: [dx, 0], ArrowUp: [0, dy], ArrowDown: [0, -dy] };
  const goes = { PageUp: i - 1, PageDown: i + 1, Home: 0, End: P.length - 1 };
  if (moves[ev.key]) {
    const [mx, my] = moves[ev.key];
    moveTo({ kind: 'point', i }, round(P[i][0] + mx), round(P[i][1] + my));
    dataShown = '';
    renderData();
  } else if (goes[ev.key] !== undefined) {
    focusOn(goes[ev.key]);
  } else if (ev.key === 'Delete' || ev.key === 'Backspace') {
    if (P.length <= 2) return;
    P.splice(i, 1);
    state.alphas = null;
    update();
    focusOn(Math.min(i, P.length - 1));
  } else {
    return;
  }
  ev.preventDefault();
});

// ---- reading data: the command's own reader (reader.js) ---------------------------------------
function readOptions() {
  return {
    delimiter: $('rdelim').value, decimal: $('rdecimal').value, na: $('rna').value.trim(),
    missing: $('rmissing').value, columns: $('rcolumns').value.trim(), xTime: $('rxtime').checked,
  };
}
let source = null; // {text, name}: what was read last (read again when an option changes)
// Read text (the contents of a file called name) as `trigspline` does; when
// it accepts it, it becomes the data.  The report names the rows skipped.
let readPromise = Promise.resolve();
function readData(text, name) {
  readPromise = readInto(text, name);
  return readPromise;
}
async function readInto(text, name) {
  source = { text, name };
  const rep = $('readreport');
  rep.className = '';
  rep.textContent = `reading ${name} …`;
  let r;
  try {
    r = await readTable(createTrigsplineCli, text, name, readOptions(), state.mode);
  } catch (e) {
    r = { ok: false, message: String((e && e.message) || e), notes: [], command: '' };
  }
  const notes = r.notes.length ? `<ul>${r.notes.map((n) => `<li>${esc(n)}</li>`).join('')}</ul>` : '';
  const cmd = r.command ? `<div id="readcmd">read as: ${esc(r.command)}</div>` : '';
  if (!r.ok) {
    rep.className = 'bad';
    rep.innerHTML = `${esc(r.message)}${notes}${cmd}`;
    // a warning still being computed for the data kept must not replace this
    clearTimeout(ovTimer);
    ovSeq++;
    $('overshoot').dataset.state = 'done';
    const st = $('status');
    st.className = 'bad';
    st.textContent = `Not read: ${r.message.split('\n')[0]}`;
    return;
  }
  $('overshoot').textContent = ''; // about other data
  state.points = r.points;
  state.xTime = r.xTime;
  state.names = r.names;
  state.alphas = null;
  selected = null;
  focusPoint = 0;
  if (state.mode === 'curve' && state.box.on) {
    // a box around the new points (10 % of their extent beyond them), which the user then drags
    const X = r.points.map((q) => q[0]), Y = r.points.map((q) => q[1]);
    const [x0, x1, y0, y1] = [Math.min(...X), Math.max(...X), Math.min(...Y), Math.max(...Y)];
    const dx = 0.1 * (x1 - x0 || 1), dy = 0.1 * (y1 - y0 || 1);
    state.box = { on: true, xmin: x0 - dx, xmax: x1 + dx, ymin: y0 - dy, ymax: y1 + dy };
  }
  const cols = r.names ? ` (columns ${r.names.map((n) => esc(JSON.stringify(n))).join(' and ')}${r.xTime ? '; x as dates' : ''})` : '';
  const skipped = r.skipped ? `; ${r.skipped} row${r.skipped === 1 ? '' : 's'} with a missing value skipped` : '';
  const lines = r.report.length ? `<ul>${r.report.map((l) => `<li>${esc(l)}</li>`).join('')}</ul>` : '';
  rep.innerHTML = `Read ${r.points.length} points from ${esc(name)}${cols}${skipped}.${lines}${notes}${cmd}`;
  fitView();
  update();
}
on('apply', 'click', () => readData($('csv').value, 'pasted.csv'));
function pasted(ev) {
  const t = ev.clipboardData && ev.clipboardData.getData('text/plain');
  if (!t) return;
  ev.preventDefault();
  $('csv').value = t;
  readData(t, 'pasted.csv');
}
on('csv', 'paste', pasted);
document.addEventListener('paste', (ev) => {
  if (ev.target !== $('csv') && !(ev.target.closest && ev.target.closest('input, textarea, select'))) pasted(ev);
});
on('file', 'change', async () => {
  const f = $('file').files[0];
  if (!f) return;
  const t = await f.text();
  $('csv').value = t;
  readData(t, f.name);
});
const carries = (ev) => ev.dataTransfer && [...ev.dataTransfer.types].some((k) => k === 'Files' || k === 'text/plain');
document.addEventListener('dragover', (ev) => {
  if (!carries(ev)) return;
  ev.preventDefault();
  document.body.classList.add('dragover');
});
document.addEventListener('dragleave', (ev) => { if (!ev.relatedTarget) document.body.classList.remove('dragover'); });
document.addEventListener('drop', (ev) => {
  document.body.classList.remove('dragover');
  if (!carries(ev)) return;
  ev.preventDefault();
  const f = ev.dataTransfer.files[0];
  if (f) {
    f.text().then((t) => { $('csv').value = t; readData(t, f.name); });
  } else {
    const t = ev.dataTransfer.getData('text/plain');
    $('csv').value = t;
    readData(t, 'dropped.csv');
  }
});
for (const id of ['rdelim', 'rdecimal', 'rmissing', 'rna', 'rcolumns', 'rxtime']) on(id, 'change', () => { if (source) readData(source.text, source.name); });
document.querySelectorAll('button[data-export]').forEach((b) => b.addEventListener('click', async () => {
  try {
    const r = await exportState(createTrigsplineCli, state, b.dataset.export);
    const a = document.createElement('a');
    a.href = URL.createObjectURL(new Blob([r.text], { type: r.type }));
    a.download = r.name;
    document.body.appendChild(a);
    a.click();
    a.remove();
  } catch (e) {
    $('status').className = 'bad';
    $('status').textContent = e.message;
  }
}));

// For tests and the console: the state, a way to set it, the timings.
window.explorer = {
  ts,
  get state() { return state; },
  set(s) { state = { ...structuredClone(DEFAULT), ...s }; selected = null; $('overshoot').textContent = ''; fitView(); update(); },
  get result() { return result; },
  get reading() { return readPromise; }, // the last read of pasted or dropped data
  timings,
  toScreen: (x, y) => { const r = svg.getBoundingClientRect(); return [r.left + sx(x) * r.width / W, r.top + sy(y) * r.height / H]; },
  moveTo,
};
fitView();
update();
document.body.dataset.ready = '1';
