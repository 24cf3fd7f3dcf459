// README's size of the module: the figure it states for out/web/trigspline.mjs
// with trigspline.wasm ("N KB gzipped together") is the measured one, gzip -9 of
// each file as a server would send them, 1 KB = 1024 bytes, within 1 KB (the
// rounding of the stated whole number plus compressor differences).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { join } from 'node:path';

const OUT = process.env.TS_WEB_OUT;
const ROOT = join(import.meta.dirname ?? new URL('.', import.meta.url).pathname, '..', '..', '..');

test('README states the gzipped size of trigspline.mjs + trigspline.wasm as measured', () => {
  assert.ok(OUT, 'TS_WEB_OUT not set (run through bindings/web/test/run.sh)');
  const gz = (f) => gzipSync(readFileSync(join(OUT, f)), { level: 9 }).length;
  const kb = (gz('trigspline.mjs') + gz('trigspline.wasm')) / 1024;
  const readme = readFileSync(join(ROOT, 'README.md'), 'utf8');
  const m = readme.match(/out\/web\/trigspline\.mjs`[^]*?(\d+(?:\.\d+)?) KB gzipped together/);
  assert.ok(m, 'README: "... out/web/trigspline.mjs ... N KB gzipped together" not found');
  console.log(`# trigspline.mjs + trigspline.wasm: ${kb.toFixed(1)} KB gzipped; README says ${m[1]} KB`);
  assert.ok(Math.abs(+m[1] - kb) <= 1, `README says ${m[1]} KB gzipped, measured ${kb.toFixed(1)} KB: update README.md`);
});
