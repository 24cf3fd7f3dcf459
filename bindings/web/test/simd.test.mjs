// The choice of module at load (trigspline.js, load and simdSupported): the
// SIMD128 module (trigspline-simd.wasm) where WebAssembly.validate accepts the
// SIMD probe, the scalar one (trigspline.wasm) where it does not, with
// load({ simd: false }) or TRIGSPLINE_SIMD=0; the pages' inlined copies
// likewise.  The two modules' bits: node.test.mjs (both against the native
// library) and the last test here (against each other, every form).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

const OUT = process.env.TS_WEB_OUT;
if (!OUT) throw new Error('TS_WEB_OUT not set (run through bindings/web/test/run.sh)');
const lib = await import(join(OUT, 'trigspline.mjs'));

// WebAssembly.validate answering false for every module with a SIMD opcode
// (prefix 0xfd), as an engine without SIMD128 does
async function withoutSimd(fn) {
  const validate = WebAssembly.validate;
  WebAssembly.validate = (bytes) => !new Uint8Array(bytes.buffer ?? bytes).includes(0xfd) && validate(bytes);
  try { return await fn(); } finally { WebAssembly.validate = validate; }
}

test('load() takes the SIMD128 module where the engine validates the probe, else the scalar one', async () => {
  assert.equal(lib.simdSupported(), true, 'Node >= 18 runs SIMD128');
  assert.equal((await lib.load()).simd, true);
  assert.equal((await lib.load({ simd: false })).simd, false);
  assert.equal((await lib.load({ simd: true })).simd, true);
  await withoutSimd(async () => {
    assert.equal(lib.simdSupported(), false);
    assert.equal((await lib.load()).simd, false);
    assert.equal((await lib.load({ simd: true })).simd, false, 'no SIMD128: the scalar module whatever asked');
  });
  const saved = process.env.TRIGSPLINE_SIMD;
  process.env.TRIGSPLINE_SIMD = '0';
  try {
    assert.equal((await lib.load()).simd, false);
    assert.equal((await lib.load({ simd: true })).simd, true, 'the option wins over the environment');
  } finally {
    if (saved === undefined) delete process.env.TRIGSPLINE_SIMD; else process.env.TRIGSPLINE_SIMD = saved;
  }
  // given bytes are taken as they are
  assert.equal((await lib.load({ wasm: readFileSync(join(OUT, 'trigspline-simd.wasm')) })).simd, true);
  assert.equal((await lib.load({ wasm: readFileSync(join(OUT, 'trigspline.wasm')) })).simd, false);
});

test('a page with both modules inlined loads one by the same rule', async () => {
  // the module text of example.html (build.mjs: WASM_BASE64, WASM_SIMD_BASE64, the wrapper)
  const html = readFileSync(join(OUT, 'example.html'), 'utf8');
  const b64 = (name) => html.match(new RegExp(`const ${name} = "([^"]*)"`))[1];
  const scalar = Buffer.from(b64('WASM_BASE64'), 'base64'), simd = Buffer.from(b64('WASM_SIMD_BASE64'), 'base64');
  assert.deepEqual(scalar, readFileSync(join(OUT, 'trigspline.wasm')));
  assert.deepEqual(simd, readFileSync(join(OUT, 'trigspline-simd.wasm')));
  assert.ok(simd.includes(0xfd) && WebAssembly.validate(simd));
});

test('SIMD128 and scalar modules give the same bits on 3e5 sorted and 1e5 random queries per form and order', async () => {
  const [a, b] = [await lib.load({ simd: true }), await lib.load({ simd: false })];
  const n = 3000, x = new Float64Array(n), f = new Float64Array(n);
  let s = 7;
  const u = () => { s = (Math.imul(s, 1664525) + 1013904223) >>> 0; return s * 2 ** -32; };
  for (let i = 0; i < n; i++) { x[i] = i + 0.9 * u(); f[i] = i % 5 === 2 ? 0 : Math.exp(3 * u() - 2); }
  const m = 300000, sorted = new Float64Array(m), random = new Float64Array(100000);
  for (let j = 0; j < m; j++) sorted[j] = x[0] + (x[n - 1] - x[0]) * ((j + 0.5) / m) ** 2;
  for (let j = 0; j < random.length; j++) random[j] = x[0] + (x[n - 1] - x[0]) * u();
  let compared = 0;
  for (const form of lib.NAMES.form) {
    const [sa, sb] = [a.spline(x, f, { form, shape: 'positive' }), b.spline(x, f, { form, shape: 'positive' })];
    for (const q of [sorted, random]) {
      for (let d = 0; d < 3; d++) {
        const ya = new BigUint64Array(sa.evalBatch(q, d).buffer), yb = new BigUint64Array(sb.evalBatch(q, d).buffer);
        let differ = 0;
        for (let j = 0; j < ya.length; j++) differ += ya[j] !== yb[j];
        assert.equal(differ, 0, `${form} form, order ${d}: ${differ} of ${ya.length} differ`);
        compared += ya.length;
      }
    }
    sa.free();
    sb.free();
  }
  console.log(`# SIMD128 and scalar modules: ${compared} values compared, all bit-identical`);
});
