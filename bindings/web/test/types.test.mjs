// trigspline.d.mts against the module: every runtime export of
// trigspline.mjs is declared (and nothing else), and a use of each
// declaration (types/use.mts) compiles with tsc --strict.  TS_WEB_OUT as for
// node.test.mjs; tsc from bindings/web/node_modules (typescript, a dev
// dependency).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync, mkdtempSync, rmSync, copyFileSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { tmpdir } from 'node:os';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const OUT = process.env.TS_WEB_OUT;
if (!OUT) throw new Error('TS_WEB_OUT not set (run through bindings/web/test/run.sh)');
const dts = readFileSync(join(OUT, 'trigspline.d.mts'), 'utf8');

test('every export of trigspline.mjs is declared in trigspline.d.mts, and only those', async () => {
  const lib = await import(join(OUT, 'trigspline.mjs'));
  const declared = new Set([...dts.matchAll(/^export declare (?:const|function|class) (\w+)/gm)].map((m) => m[1]));
  assert.deepEqual([...declared].sort(), Object.keys(lib).sort());
});

test('a use of every declaration compiles with tsc --strict', () => {
  const dir = mkdtempSync(join(tmpdir(), 'ts-types-'));
  try {
    copyFileSync(join(here, 'types', 'use.mts'), join(dir, 'use.mts'));
    writeFileSync(join(dir, 'tsconfig.json'), JSON.stringify({
      compilerOptions: {
        strict: true, noEmit: true, target: 'es2022', module: 'nodenext', moduleResolution: 'nodenext',
        lib: ['es2022', 'dom', 'esnext.disposable'], types: [], skipLibCheck: false,
        paths: { trigspline: [join(OUT, 'trigspline.d.mts')] },
      },
      files: ['use.mts'],
    }));
    const tsc = join(here, '..', 'node_modules', 'typescript', 'bin', 'tsc');
    const r = spawnSync(process.execPath, [tsc, '-p', dir], { encoding: 'utf8' });
    assert.equal(r.status, 0, `tsc:\n${r.stdout}${r.stderr}`);
  } finally { rmSync(dir, { recursive: true, force: true }); }
});
