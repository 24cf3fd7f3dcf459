// The charts gallery (make demo -> out/charts/index.html): d3, Chart.js and
// ECharts before (their own smoothing) and after (trigspline) on d3-shape#81's
// data and on real series, with what each crossing costs.  One static page:
// the three libraries, the module (wasm inlined) and the data inlined, so it
// works from a file:// URL with no network.
//   node build.mjs OUT_WEB OUT_DIR
// The costs in the captions are measured here, in Node, on the same drawing
// code (test/stackcheck.mjs): the deepest crossing in data units and the
// share of the x range where a layer's top is below the top of the layer
// under it (or below 0).
import { readFileSync, writeFileSync, mkdirSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import * as sc from '../test/stackcheck.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const root = resolve(here, '../../..');
const [outWeb, outDir] = process.argv.slice(2);
if (!outWeb || !outDir) { console.error('usage: node build.mjs OUT_WEB OUT_DIR'); process.exit(2); }
// the packages' own UMD builds (read from node_modules: their `exports` do
// not list them), without their source-map comments (nothing to fetch)
const vendor = (p) => readFileSync(join(here, '..', 'node_modules', p), 'utf8').replace(/^\/\/# sourceMappingURL=.*$/gm, '');

// ---- data -------------------------------------------------------------------
function csv(path) {
  const lines = readFileSync(join(root, path), 'utf8').split('\n').filter((l) => l && !l.startsWith('#'));
  const head = lines[0].split(',');
  return { head, rows: lines.slice(1).map((l) => Object.fromEntries(l.split(',').map((v, i) => [head[i], +v]))) };
}
const uk = csv('data/realworld/uk_electricity_mix.csv');
const rain = csv('data/examples/rainfall_daily.csv');
const data = {
  issue81: { keys: ['a', 'b'], labels: ['lower layer', 'upper layer'],
    rows: [0, 186, 2294, 2812.11].map((a, i) => ({ x: i, a, b: [0, 0, 0, 18500][i] })) },
  uk: { keys: uk.head.slice(1), labels: uk.head.slice(1), rows: uk.rows.map((r) => ({ ...r, x: r.year })) },
  rain: { keys: ['rain_mm'], labels: ['rain (mm)'], rows: rain.rows.map((r) => ({ x: r.day, rain_mm: r.rain_mm })) },
};
// shares of generation (d3.stackOffsetExpand's input, in %)
data.ukShare = { keys: data.uk.keys, labels: data.uk.keys, rows: data.uk.rows.map((r) => {
  const t = data.uk.keys.reduce((s, k) => s + r[k], 0);
  return Object.fromEntries([['x', r.x], ...data.uk.keys.map((k) => [k, (100 * r[k]) / t])]);
}) };

// ---- costs ------------------------------------------------------------------
const lib = await import(join(resolve(outWeb), 'trigspline.mjs'));
const ts = await lib.load();
const M = sc.methods({ ...lib, module: ts });
function cost(ds, method) {
  const { series, X } = sc.scales(ds);
  let top = 0;
  for (const s of series) for (const d of s) top = Math.max(top, d[1]);
  const px = ds.rows.map((r) => X(r.x));
  const m = sc.measure(M[method](ds), px);
  const unit = (top > 0 ? top : 1) / sc.H;
  return { cross: m.cross * unit, below: m.below * unit, fraction: m.crossFraction };
}
const costs = {};
for (const [name, ds] of Object.entries(data)) {
  costs[name] = {};
  for (const method of Object.keys(M)) costs[name][method] = cost(ds, method);
}

// ---- page -------------------------------------------------------------------
const wasm = readFileSync(join(outWeb, 'trigspline.wasm')).toString('base64');
const module = readFileSync(join(outWeb, 'trigspline.mjs'), 'utf8').replace(/^export (default )?/gm, '');
const inline = (code) => code.replace(/<\/script/gi, '<\\/script');
const page = readFileSync(join(here, 'index.html'), 'utf8')
  .replace('<!--VENDOR-->', () => ['d3/dist/d3.min.js', 'chart.js/dist/chart.umd.min.js', 'echarts/dist/echarts.min.js']
    .map((p) => `<script>\n${inline(vendor(p))}\n</script>`).join('\n'))
  .replace('<!--SCRIPT-->', () => `<script type="module">\nconst WASM_BASE64 = ${JSON.stringify(wasm)};\n${inline(module)}\n`
    + `const DATA = ${JSON.stringify(data)};\nconst COSTS = ${JSON.stringify(costs)};\n`
    + `${inline(readFileSync(join(here, 'gallery.js'), 'utf8'))}\n</script>`);
mkdirSync(outDir, { recursive: true });
writeFileSync(join(outDir, 'index.html'), page);
// the methods that cross or dip, per data set
const fmt = (c) => `${c.cross.toPrecision(3)} deep over ${(100 * c.fraction).toFixed(0)} %, dip ${c.below.toPrecision(3)}`;
for (const [name, byMethod] of Object.entries(costs)) {
  const bad = Object.entries(byMethod).filter(([, c]) => c.cross > 1e-9 || c.below > 1e-9);
  console.log(`${name}: ${bad.length ? bad.map(([k, c]) => `${k}: ${fmt(c)}`).join('; ') : 'no crossing'}`);
}
console.log(`wrote ${join(outDir, 'index.html')} (${(page.length / 1024).toFixed(0)} KB)`);
