// ts.disaggregate in the WebAssembly module (docs/method.md §12): bin totals
// kept by the cells of a finer grid, no negative value, dry bins dry, the
// same numbers as the native command (TS_WEB_CLI_SHIPPED disaggregate, its
// shortest round-trip output), every refusal a TrigSplineError.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { join } from 'node:path';

const OUT = process.env.TS_WEB_OUT;
if (!OUT) throw new Error('TS_WEB_OUT not set (run through bindings/web/test/run.sh)');
const lib = await import(join(OUT, 'trigspline.mjs'));
const ts = await lib.load();

const edges = [0, 1, 2, 3, 4, 5, 6];
const totals = [0, 12.5, 0, 3, 0.4, 0];
const grid = Array.from({ length: 6 * 24 + 1 }, (_, k) => k / 24);

test('disaggregate: totals kept, none negative, dry bins dry', () => {
  const cells = ts.disaggregate(edges, totals, grid);
  assert.equal(cells.length, 6 * 24);
  for (let j = 0; j < 6; j++) {
    let s = 0;
    for (let k = 0; k < 24; k++) {
      const c = cells[24 * j + k];
      assert.ok(c >= 0, `cell ${24 * j + k}: ${c}`);
      s += c;
    }
    if (totals[j] === 0) assert.equal(s, 0);
    // 24 rounded sums: well within 1e-13 of the total
    else assert.ok(Math.abs(s - totals[j]) <= 1e-13 * totals[j], `bin ${j}: ${s}`);
  }
  const r = ts.disaggregate(edges, totals, grid, { kind: 'rate' });
  assert.equal(r.length, grid.length);
  assert.ok(r.every((v) => v >= 0));
  assert.equal(r[24], 0); // the edge of a dry bin
  const d = ts.disaggregate(edges, totals, [1, 2], { kind: 'derivative' });
  assert.deepEqual(Array.from(d), [0, 0]); // r' = 0 at a dry bin's edges
  const b = ts.disaggregate([0, 1, 2], [1, 2], [0, 0.5, 1, 1.5, 2], { kind: 'rate', lo: 0.5, hi: 2.5 });
  assert.ok(b.every((v) => v >= 0.5 && v <= 2.5));
});

test('disaggregate: the native command gives the same numbers', () => {
  const cli = process.env.TS_WEB_CLI_SHIPPED;
  if (!cli) return;
  const csv = edges.slice(0, -1).map((e, j) => `${e},${e + 1},${totals[j]}`).join('\n') + '\n';
  const p = spawnSync(cli, ['disaggregate', '--step', '0.25'], { input: csv, encoding: 'utf8' });
  assert.equal(p.status, 0, p.stderr);
  const want = p.stdout.trim().split('\n').slice(1).map((l) => Number(l.split(',')[2]));
  const got = ts.disaggregate(edges, totals, Array.from({ length: 25 }, (_, k) => k / 4));
  assert.deepEqual(Array.from(got), want);
});

test('disaggregate: refusals', () => {
  const err = (fn, status) => assert.throws(fn, (e) => e instanceof lib.TrigSplineError && e.status === status);
  err(() => ts.disaggregate([0, 1, 2], [1, -1], [0, 2]), 'TS_ERR_NEGATIVE');
  err(() => ts.disaggregate([0, 1, 2], [1], [0, 2]), 'TS_ERR_LENGTH');
  err(() => ts.disaggregate([0, 1, 2], [1, 1], [0, 3]), 'TS_ERR_DOMAIN');
  err(() => ts.disaggregate([0, 1, 2], [1, 1], [0, 2], { kind: 'mode' }), 'TS_ERR_OPTION');
  err(() => ts.disaggregate([0, 1, 2], [1, 5], [0, 2], { hi: 3 }), 'TS_ERR_INFEASIBLE');
  err(() => ts.disaggregate([0, 1, 2], [1, 'x'], [0, 2]), 'TS_ERR_NONFINITE');
  // the library's sentence names the bin or edge with its values
  const msg = (fn) => { try { fn(); } catch (e) { return e.message; } return ''; };
  assert.match(msg(() => ts.disaggregate([0, 1, 2], [1, -1], [0, 2])),
    /bin 1 \[1, 2\]: total -1 is negative; totals must be >= 0/);
  assert.match(msg(() => ts.disaggregate([0, 1, 2], [1, 5], [0, 2], { hi: 3 })),
    /bin 1 \[1, 2\]: total 5 gives the mean 5, outside the rate bounds \[0, 3\]/);
  assert.match(msg(() => ts.disaggregate([0, 1, 1], [1, 1], [0, 1])),
    /edge 2 \(x = 1\) is not greater than the previous edge 1/);
  // a refusal after a good call: no stale sentence
  assert.doesNotMatch(msg(() => ts.disaggregate([0, 1, 2], [1, 1], [0, 3])), /bin/);
  const top = ts.heapTop();
  for (let i = 0; i < 200; i++) ts.disaggregate(edges, totals, grid);
  assert.equal(ts.heapTop(), top); // no leak
});
