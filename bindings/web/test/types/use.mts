// A use of every declaration of trigspline.d.mts, compiled with tsc --strict
// (types.test.mjs against out/web; tools/dist/npm.sh against the installed
// package).  Never run: only type-checked.
import {
  load, simdSupported, getDefaultModule, NAMES, TrigSplineError, Spline, Curve, curveTrig, curveTrigPositive,
  curveTrigMonotone, curveTrigAbove, curveTrigBelow, curveTrigBetween, stackTrig, areaTrig,
  fitThicknesses, stackPixels, chartjsTrigspline, installEChartsTrigspline, dataCsv, cliArgs, isoText,
  EXPORTS, runCli, exportState,
} from 'trigspline';
import type { SplineOptions, StackLayers, TrigSpline, Certificate } from 'trigspline';

export async function use(): Promise<number> {
  const ts: TrigSpline = await load({ maxMemoryMB: 64, simd: simdSupported() });
  if (ts.simd !== (await load({ simd: false })).simd) getDefaultModule();
  const opts: SplineOptions = { shape: 'positive', form: 'c1', lower: { m: 0, c: 0 }, certify: true };
  const s: Spline = ts.spline([0, 1, 2, 3], new Float64Array([1, 0, 0, 2]), opts);
  let y = s.eval(1.5) + s.evalDeriv(0.5).dy + s.evalBatch([0.5, 1])[0] + s.derivative(2)(1, 'clamp');
  y += s.integral(0, 3) + s.a(0) + s.control(0).B[0] + s.findInterval(1.2) + s.solve(0.5).length;
  const c: Certificate = s.certify({ lower: 0 });
  y += c.reports[0].gapLower + s.report(0).a + s.report().length + s.errorBound(1).bound;
  if (s.certified && s.shape === NAMES.shape[1]) y += s.x[0] + s.intervals;
  s.free();
  const k = ts.spline([0, 1, 2, 3], [0, 1, 4, 9], { constraints: ['convex', { kind: 'lower', value: 0 }] });
  const rep = k.constraintReport()[0][0];
  if (rep) y += rep.gap + rep.at + (rep.active ? 1 : 0) + (rep.certified ? 1 : 0);
  k.free();
  y += ts.disaggregate([0, 1, 2], [3, 0], [0, 0.5, 1, 1.5, 2], { kind: 'totals', lo: 0 })[0];
  const cv: Curve = ts.curve([[0, 0], [1, 1], [2, 0]], { param: 'centripetal', box: { ymin: 0 } });
  y += cv.sample(4)[1] + cv.length() + cv.eval(0.5).p[0] + cv.params(0).alpha + cv.control(0)[0][0];
  cv.free();
  try { ts.spline([0, 1], [1, -1], { shape: 'positive' }); } catch (e) {
    if (e instanceof TrigSplineError) y += (e.index ?? 0) + e.code + e.status.length;
  }
  const ctx = { moveTo(x: number, yy: number) { y += x + yy; }, lineTo() {}, closePath() {} };
  for (const f of [curveTrig, curveTrigPositive, curveTrigMonotone, curveTrigAbove(0), curveTrigBelow({ c: 3 }),
    curveTrigBetween(0, 1)]) f.samples(8).form('paper').module(ts)(ctx).lineStart();
  const series = [Object.assign([[0, 1], [0, 2]], { key: 'a', index: 0 })];
  const layers: StackLayers = stackTrig().x((_d, i) => i).offset('auto').samples(4).options({ form: 'c1' }).module(ts)(series);
  const d: string | undefined = areaTrig().x((v) => v).y((v) => v).digits(2)(layers[0]);
  y += (d ?? '').length + (areaTrig().line(layers[0]) ?? '').length + layers.clamped;
  y += fitThicknesses(ts, [0, 1], [[1, 2]], new Float64Array([0, 0.5, 1])).sums[0][1];
  y += stackPixels(ts, [0, 10], [[5, 4]], 10, -1)?.ys[0][0] ?? 0;
  y += chartjsTrigspline.defaults.samples;
  installEChartsTrigspline({ registerPostUpdate() {} }, { module: ts });
  const state = { mode: 'function' as const, points: [[0, 1], [1, 2]] };
  y += dataCsv(state).length + cliArgs(state).length + EXPORTS.csv.args.length + isoText(0).length;
  const factory = async () => ({});
  y += (await runCli(factory, ['--help'], {})).status + (await exportState(factory, state, 'csv')).text.length;
  return y + (getDefaultModule() === ts ? 1 : 0) + ts.version.length;
}
