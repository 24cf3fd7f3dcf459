// The full crossing measurement (make test-web-stack-full): 1e5 random
// stacked data sets (stackcheck.mjs), the table on stdout and in
// ARTIFACTS/stack-crossings-full.md; exits 1 when a trigspline drawing
// crosses or dips below the baseline.
//   node stack_full.mjs OUT_WEB ARTIFACTS [COUNT]
import { writeFileSync, mkdirSync } from 'node:fs';
import { join, resolve } from 'node:path';
import * as sc from './stackcheck.mjs';

const [out, art, count = '100000'] = process.argv.slice(2);
if (!out || !art) { console.error('usage: node stack_full.mjs OUT_WEB ARTIFACTS [COUNT]'); process.exit(2); }
const lib = await import(join(resolve(out), 'trigspline.mjs'));
const ts = await lib.load();
const t0 = performance.now();
const res = sc.run({ ...lib, module: ts }, +count, 1);
const text = `${sc.table(res)}\n\n(${((performance.now() - t0) / 1000).toFixed(0)} s)`;
mkdirSync(art, { recursive: true });
writeFileSync(join(art, 'stack-crossings-full.md'), `${text}\n`);
console.log(text);
const bad = Object.entries(res.stats).filter(([k, s]) => k.startsWith('trigspline') && (s.cross || s.below));
process.exit(bad.length ? 1 : 0);
