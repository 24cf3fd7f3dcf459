// The npm package imported in a page in Chromium: DIR (where the tarball was
// installed) is served on the loopback, a page imports
// /node_modules/trigspline/trigspline.mjs (which fetches trigspline-simd.wasm,
// Chromium having SIMD128, next to itself) and runs the smoke test; every request off the loopback is
// refused and counted.  Prints "smoke: page ..." lines; exit 0 when it passed.
//   node npm_page.mjs DIR PLAYWRIGHT_PACKAGE_JSON
import { createServer } from 'node:http';
import { readFileSync, mkdtempSync, rmSync } from 'node:fs';
import { join, extname } from 'node:path';
import { tmpdir } from 'node:os';
import { createRequire } from 'node:module';

const [dir, pw] = process.argv.slice(2);
const { chromium } = createRequire(pw)('playwright-core');
const page = `<!DOCTYPE html><meta charset="utf-8"><title>trigspline npm smoke</title>
<script type="module">
import { load } from '/node_modules/trigspline/trigspline.mjs';
const ts = await load();
const x = [0, 2, 3, 5, 15, 25, 27, 28, 30], f = [2, 1.58, 1.55, 1.54, 1.8, 1.54, 1.55, 1.58, 2];
const s = ts.spline(x, f, { shape: 'positive', alpha: 0.15 });
const r = { y: s.eval(4.2), certified: s.certified, version: ts.version, simd: ts.simd };
s.free();
try { ts.spline(x, f.map((v, i) => (i === 3 ? -1 : v)), { shape: 'positive' }); } catch (e) { r.error = [e.status, e.index]; }
window.result = r;
</script>`;
const types = { '.mjs': 'text/javascript', '.wasm': 'application/wasm', '.html': 'text/html' };
const server = createServer((req, res) => {
  const p = decodeURIComponent(new URL(req.url, 'http://x').pathname);
  if (p === '/' || p === '/index.html') { res.writeHead(200, { 'content-type': 'text/html' }).end(page); return; }
  if (p.includes('..')) { res.writeHead(403).end(); return; }
  try {
    res.writeHead(200, { 'content-type': types[extname(p)] ?? 'application/octet-stream' }).end(readFileSync(join(dir, p)));
  } catch { res.writeHead(404).end(); }
});
await new Promise((r) => server.listen(0, '127.0.0.1', r));
const base = `http://127.0.0.1:${server.address().port}`;
const profile = mkdtempSync(join(tmpdir(), 'npm-smoke-chromium-'));
const external = [];
let ok = false;
const context = await chromium.launchPersistentContext(profile, {
  executablePath: '/usr/bin/chromium', headless: true,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--no-first-run'],
});
try {
  await context.route('**/*', (route) => {
    const u = route.request().url();
    if (u.startsWith(base)) return route.continue();
    external.push(u);
    return route.abort();
  });
  const p = await context.newPage();
  const errors = [];
  p.on('pageerror', (e) => errors.push(String(e)));
  await p.goto(`${base}/`);
  await p.waitForFunction(() => window.result, null, { timeout: 30000 });
  const r = await p.evaluate(() => window.result);
  console.log(`smoke: page y(4.2) = ${r.y} certified ${r.certified ? 1 : 0}, error ${r.error}, version ${r.version}, module ${r.simd ? 'SIMD128' : 'scalar'}`);
  console.log(`smoke: page requests off the loopback: ${external.length}, page errors: ${errors.length}`);
  ok = r.simd && r.certified && r.y > 0 && r.error && r.error[0] === 'TS_ERR_NEGATIVE' && r.error[1] === 3
    && external.length === 0 && errors.length === 0;
} finally {
  await context.close();
  server.close();
  rmSync(profile, { recursive: true, force: true });
}
process.exit(ok ? 0 : 1);
