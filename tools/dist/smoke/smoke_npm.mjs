// The distribution smoke test of the npm package (as smoke.c): the paper's
// Table 1, positive, alpha 0.15, at x = 4.2 and certified, and one refusal (a
// negative value: TS_ERR_NEGATIVE naming point 3).  Run where `trigspline`
// is installed: node smoke_npm.mjs.  Prints the "smoke:" lines; exit 0 when
// both behave as documented.
import { load, TrigSplineError } from 'trigspline';

let ok = true;
const ts = await load();
// both modules are installed: Node has SIMD128, so load() takes that one
const scalar = await load({ simd: false });
console.log(`smoke: modules simd ${ts.simd ? 1 : 0} scalar ${scalar.simd ? 1 : 0}`);
if (!ts.simd || scalar.simd) ok = false;
const x = [0, 2, 3, 5, 15, 25, 27, 28, 30];
const f = [2, 1.58, 1.55, 1.54, 1.8, 1.54, 1.55, 1.58, 2];
console.log(`smoke: version ${ts.version}`);
const s = ts.spline(x, f, { shape: 'positive', alpha: 0.15 });
const y = s.eval(4.2), c = s.certified && s.certify({ lower: 0 }).ok ? 1 : 0;
s.free();
console.log(`smoke: y(4.2) = ${y} certified ${c}`);
if (c !== 1 || !(y > 0)) ok = false;
try {
  ts.spline(x, f.map((v, i) => (i === 3 ? -1 : v)), { shape: 'positive', alpha: 0.15 });
  console.log('smoke: error: negative data accepted');
  ok = false;
} catch (e) {
  console.log(`smoke: error ${e.status} index ${e.index}: ${e.message}`);
  if (!(e instanceof TrigSplineError && e.status === 'TS_ERR_NEGATIVE' && e.index === 3)) ok = false;
}
process.exit(ok ? 0 : 1);
