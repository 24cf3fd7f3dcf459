// Assembles the web package from the emcc outputs (make web):
//   node build.mjs BUILD_DIR OUT_DIR
// BUILD_DIR holds trigspline.wasm and trigspline-simd.wasm (the library +
// glue.c, scalar and SIMD128) and trigspline-cli.js (the command-line tool,
// wasm embedded).  Writes to OUT_DIR:
//   trigspline.mjs      ES module: the wrapper (trigspline.js), the curve
//                       factories (curve.js), stacked areas (stack.js), the
//                       chart plugins (charts.js), the exports (export.js); loads
//   trigspline-simd.wasm  where the engine has SIMD128, else
//   trigspline.wasm     from next to itself (fetch, or the file in Node)
//   trigspline.d.mts    its types (kept by hand beside the sources)
//   trigspline-cli.mjs  the CLI as an ES module (default export: the factory)
//   index.html          the explorer: one page, everything inlined (both
//                       modules: the page loads one, as trigspline.mjs does)
//   example.html        the curve factory on a canvas
//   sizes.txt           raw and gzipped sizes
import { readFileSync, writeFileSync, mkdirSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const [buildDir, outDir] = process.argv.slice(2);
if (!buildDir || !outDir) {
  console.error('usage: node build.mjs BUILD_DIR OUT_DIR');
  process.exit(2);
}
mkdirSync(outDir, { recursive: true });
const src = (f) => readFileSync(join(here, f), 'utf8');
const wasm = readFileSync(join(buildDir, 'trigspline.wasm'));
const wasmSimd = readFileSync(join(buildDir, 'trigspline-simd.wasm'));
const cliJs = readFileSync(join(buildDir, 'trigspline-cli.js'), 'utf8');

// Module sources without their relative imports (they become one scope).
const body = (f) => src(f).replace(/^import [^;]*from '\.\.?\/[^']*';\n/gm, '');
const unexport = (s) => s.replace(/^export (default )?/gm, '');

const lib = body('trigspline.js') + body('curve.js') + body('stack.js') + body('charts.js') + body('export.js');
const embedded = `const WASM_BASE64 = ${JSON.stringify(wasm.toString('base64'))};\n`
  + `const WASM_SIMD_BASE64 = ${JSON.stringify(wasmSimd.toString('base64'))};\n${lib}`;
writeFileSync(join(outDir, 'trigspline.mjs'), lib);
writeFileSync(join(outDir, 'trigspline.wasm'), wasm);
writeFileSync(join(outDir, 'trigspline-simd.wasm'), wasmSimd);
writeFileSync(join(outDir, 'trigspline.d.mts'), src('trigspline.d.mts'));
writeFileSync(join(outDir, 'trigspline-cli.mjs'), `${cliJs}\nexport default createTrigsplineCli;\n`);

// Pages: <!--SCRIPT--> in the template becomes one inline module script, the
// wasm inlined as base64 (WASM_BASE64), so a page works from a file:// URL.
const inline = (code) => code.replace(/<\/script/gi, '<\\/script');
function page(template, parts) {
  const code = parts.join('\n');
  return src(template).replace('<!--SCRIPT-->', () => `<script type="module">\n${inline(code)}\n</script>`);
}
writeFileSync(join(outDir, 'index.html'),
  page('explorer/index.html', [cliJs, unexport(embedded), unexport(body('explorer/ticks.js')),
    unexport(body('explorer/reader.js')), unexport(body('explorer/explorer.js'))]));
writeFileSync(join(outDir, 'example.html'),
  page('explorer/example.html', [unexport(embedded), unexport(body('explorer/example.js'))]));

// Sizes (the goal: wasm + JS <= 60 KB gzipped; a client fetches one of the
// two modules).
const gz = (b) => gzipSync(b, { level: 9 }).length;
const js = Buffer.from(body('trigspline.js') + body('curve.js'));
const rows = [
  ['trigspline.wasm', wasm.length, gz(wasm)],
  ['trigspline-simd.wasm', wasmSimd.length, gz(wasmSimd)],
  ['wrapper + curve factories (JS)', js.length, gz(js)],
  ['wasm + JS as separate files', wasm.length + js.length, gz(wasm) + gz(js)],
  ['trigspline.mjs (with export.js) + trigspline.wasm', Buffer.byteLength(lib) + wasm.length, gz(Buffer.from(lib)) + gz(wasm)],
  ['trigspline.mjs (with export.js) + trigspline-simd.wasm', Buffer.byteLength(lib) + wasmSimd.length,
    gz(Buffer.from(lib)) + gz(wasmSimd)],
  ['the same with both modules inlined as base64 (the pages)', Buffer.byteLength(embedded), gz(Buffer.from(embedded))],
  ['trigspline-cli.mjs (exports only)', Buffer.byteLength(cliJs), gz(Buffer.from(cliJs))],
];
const text = rows.map(([n, raw, z]) => `${n}: ${raw} bytes, ${z} gzipped`).join('\n');
writeFileSync(join(outDir, 'sizes.txt'), `${text}\n`);
console.log(text);
