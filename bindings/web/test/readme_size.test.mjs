// README's size of the module: the figures it states for out/web/trigspline.mjs
// with trigspline-simd.wasm ("SIMD128 module ... N KB gzipped together") and
// with trigspline.wasm ("scalar one ... N KB gzipped together"), a client
// fetching one of the two, are the measured ones, gzip -9 of each file as a
// server would send them, 1 KB = 1024 bytes, within 1 KB (the rounding of the
// stated whole number plus compressor differences).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { join } from 'node:path';

const OUT = process.env.TS_WEB_OUT;
const ROOT = join(import.meta.dirname ?? new URL('.', import.meta.url).pathname, '..', '..', '..');

test('README states the gzipped size of trigspline.mjs with each module as measured', () => {
  assert.ok(OUT, 'TS_WEB_OUT not set (run through bindings/web/test/run.sh)');
  const gz = (f) => gzipSync(readFileSync(join(OUT, f)), { level: 9 }).length;
  const readme = readFileSync(join(ROOT, 'README.md'), 'utf8');
  const m = readme.match(/out\/web\/trigspline\.mjs`[^]*?SIMD128 module[^]*?(\d+(?:\.\d+)?) KB gzipped together[^]*?scalar one[^]*?(\d+(?:\.\d+)?) KB gzipped together/);
  assert.ok(m, 'README: "... out/web/trigspline.mjs ... SIMD128 module ... N KB gzipped together ... scalar one ... M KB gzipped together" not found');
  for (const [wasm, stated] of [['trigspline-simd.wasm', m[1]], ['trigspline.wasm', m[2]]]) {
    const kb = (gz('trigspline.mjs') + gz(wasm)) / 1024;
    console.log(`# trigspline.mjs + ${wasm}: ${kb.toFixed(1)} KB gzipped; README says ${stated} KB`);
    assert.ok(Math.abs(+stated - kb) <= 1, `README says ${stated} KB gzipped with ${wasm}, measured ${kb.toFixed(1)} KB: update README.md`);
  }
});
