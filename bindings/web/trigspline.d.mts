// Types of trigspline.mjs (the WebAssembly module's wrapper, the curve
// factories, stacked areas and chart plugins).  Kept by hand beside the
// sources (trigspline.js, curve.js, stack.js, charts.js, export.js); the web
// tests check that every runtime export is declared here and compile a use of
// each with tsc --strict.

export type FormName = 'paper' | 'c1' | 'geometric';
export type ShapeName = 'none' | 'positive' | 'above' | 'below' | 'between' | 'monotone';
export type ExtrapolateName = 'error' | 'clamp' | 'extend' | 'linear';
export type ParamName = 'centripetal' | 'chord' | 'uniform';
/** A line y = m x + c, or a constant c. */
export type Line = { m?: number; c?: number } | number;
export type Numbers = ArrayLike<number>;

/** The library's vocabulary, read from the module when it loads. */
export declare const NAMES: {
  readonly form: readonly string[];
  readonly slopes: readonly string[];
  readonly shape: readonly string[];
  readonly extrapolate: readonly string[];
  readonly term: readonly string[];
  readonly param: readonly string[];
};

export declare class TrigSplineError extends Error {
  name: 'TrigSplineError';
  /** the status name, e.g. "TS_ERR_NEGATIVE" */
  status: string;
  code: number;
  /** the point, interval or query the error names; null when none */
  index: number | null;
  where: 'point' | 'interval' | 'query' | null;
}

export interface SplineOptions {
  form?: FormName | number;
  /** a method name, or one user slope per point */
  slopes?: string | number | Numbers;
  alpha?: number | Numbers;
  beta?: number | Numbers;
  margin?: number | Numbers;
  shape?: ShapeName | number;
  lower?: Line;
  upper?: Line;
  line?: Line;
  certify?: boolean;
  extrapolate?: ExtrapolateName | number;
  /** constraint records (docs/method.md §13, geometric form, no shape): the
   * command line's --constraint SPEC strings ('convex', 'lower=0',
   * 'slope<=5@0-3', ...) or records */
  constraints?: (string | ConstraintRecord)[];
}

/** One constraint record: kind from NAMES.constraint; value for bounds and
 * slopes; points for a polyline bound; spline for a bound given by another
 * Spline of the same module (lower, upper; docs/method.md §13.7: the fitted
 * spline keeps its own copy); intervals first .. first + count - 1 (count 0:
 * to the end). */
export interface ConstraintRecord {
  kind: string;
  value?: number;
  points?: number[][] | null;
  spline?: Spline | null;
  first?: number;
  count?: number;
}

/** Per interval of a constraint record: null outside its scope. */
export type ConstraintReportEntry = { active: boolean; gap: number; at: number; certified: boolean } | null;

export interface DisaggregateOptions {
  /** what is returned: totals over the grid's cells (default), or the rate r or r' at its points */
  kind?: 'totals' | 'rate' | 'derivative';
  /** bounds of the rate (defaults 0 and Infinity) */
  lo?: number;
  hi?: number;
  /** tension (default the library's) */
  alpha?: number;
}

export interface CurveOptions {
  param?: ParamName | number;
  closed?: boolean;
  slopes?: string | number;
  alpha?: number | Numbers;
  beta?: number | Numbers;
  box?: { xmin?: number; xmax?: number; ymin?: number; ymax?: number; zmin?: number; zmax?: number };
  margin?: number;
  /** coordinates per point when points is a flat array */
  dim?: number;
}

export interface IntervalReport {
  x0: number; x1: number; alpha: number; beta: number; a: number;
  B: [number, number, number, number];
  term: string; hasLower: boolean; hasUpper: boolean;
  gapLower: number; atLower: number; gapUpper: number; atUpper: number;
  certified: boolean;
}

export interface Certificate {
  ok: boolean;
  /** the first violating interval when !ok */
  index: number | null;
  reports: IntervalReport[];
}

export declare class Spline {
  readonly intervals: number;
  readonly form: string;
  readonly shape: string;
  readonly extrapolate: string;
  readonly certified: boolean;
  readonly x: Float64Array;
  readonly f: Float64Array;
  readonly slopes: Float64Array;
  readonly alpha: Float64Array;
  readonly beta: Float64Array;
  eval(x: number): number;
  evalDeriv(x: number): { y: number; dy: number; d2y: number };
  evalBatch(xs: Numbers, deriv?: number, out?: Float64Array | null, partial?: boolean,
    extrapolate?: ExtrapolateName | null): Float64Array;
  derivative(nu?: number): (x: number, extrapolate?: ExtrapolateName | null) => number;
  solve(y?: number): Float64Array;
  findInterval(x: number): number;
  integral(a: number, b: number): number;
  a(i: number): number;
  control(i: number): { B: number[]; X: number[] };
  report(): IntervalReport[];
  report(i: number): IntervalReport;
  certify(lines?: { lower?: Line | null; upper?: Line | null }): Certificate;
  /** per record, per interval (docs/method.md §13) */
  constraintReport(): ConstraintReportEntry[][];
  errorBound(fprimeMax: number, fsecondMax?: number, exactSlopes?: boolean): { bound: number; perInterval: Float64Array };
  free(): void;
  [Symbol.dispose](): void;
}

export declare class Curve {
  readonly segments: number;
  readonly dim: number;
  readonly closed: boolean;
  readonly knots: Float64Array;
  eval(t: number): { p: number[]; dp: number[]; d2p: number[] };
  /** m samples per segment: rows (t, x, y[, z]) */
  sample(m?: number): Float64Array;
  params(i: number): { alpha: number; beta: number };
  control(i: number): number[][];
  length(tol?: number): number;
  certify(box?: CurveOptions['box']): Certificate;
  free(): void;
  [Symbol.dispose](): void;
}

/** A loaded module (load()). */
export interface TrigSpline {
  readonly version: string;
  /** true: the SIMD128 module (trigspline-simd.wasm) was loaded; false: the scalar one */
  readonly simd: boolean;
  readonly NAMES: typeof NAMES;
  readonly STATUS_NAMES: readonly string[];
  readonly TrigSplineError: typeof TrigSplineError;
  readonly defaults: Required<Pick<SplineOptions, 'alpha' | 'beta' | 'margin' | 'certify'>> &
    { form: string; slopes: string; shape: string; extrapolate: string };
  readonly curveDefaults: { param: string; closed: boolean; slopes: string; alpha: number; beta: number; margin: number };
  spline(x: Numbers, f: Numbers, options?: SplineOptions): Spline;
  curve(points: number[][] | Numbers, options?: CurveOptions): Curve;
  slopes(method: string | number, x: Numbers, f: Numbers): Float64Array;
  /** bin totals (edges.length = totals.length + 1) to totals over the grid's
   * cells, or the rate (docs/method.md §12: totals kept, lo <= r <= hi, C¹) */
  disaggregate(edges: Numbers, totals: Numbers, grid: Numbers, options?: DisaggregateOptions): Float64Array;
  errorConstants(form: FormName | number, a: number): { first: number; line: number; second: number };
  strerror(code: number): string;
  heapTop(): number;
}

export interface LoadOptions {
  /** the wasm bytes or a compiled module (default: trigspline-simd.wasm where the engine
   * has WebAssembly SIMD128, else trigspline.wasm, next to trigspline.mjs) */
  wasm?: BufferSource | WebAssembly.Module;
  /** false: the scalar module even where SIMD128 exists (default: SIMD128 where
   * supported; in Node the environment TRIGSPLINE_SIMD=0 means false); both give the same bits */
  simd?: boolean;
  /** cap of the module's heap in MB (default 2048) */
  maxMemoryMB?: number;
}
export declare function load(options?: LoadOptions): Promise<TrigSpline>;
/** Whether this engine validates WebAssembly SIMD128 (what load() chooses by). */
export declare function simdSupported(): boolean;
/** The first module load() made (what the curve factories and plugins use by default). */
export declare function getDefaultModule(): TrigSpline | null;

// ---- d3-shape style curve factories (curve.js) ---------------------------

export interface PathContext {
  moveTo(x: number, y: number): void;
  lineTo(x: number, y: number): void;
  closePath(): void;
}
export interface CurveObject {
  areaStart(): void; areaEnd(): void; lineStart(): void; lineEnd(): void; point(x: number, y: number): void;
}
export interface Scale { (v: number): number; invert(p: number): number }
export interface CurveFactory {
  (context: PathContext): CurveObject;
  alpha(a: number): CurveFactory;
  form(f: FormName): CurveFactory;
  slopes(s: string): CurveFactory;
  samples(n: number): CurveFactory;
  scales(x: Scale, y: Scale): CurveFactory;
  module(ts: TrigSpline): CurveFactory;
}
export declare const curveTrig: CurveFactory;
export declare const curveTrigPositive: CurveFactory;
export declare const curveTrigMonotone: CurveFactory;
export declare function curveTrigAbove(lower: Line): CurveFactory;
export declare function curveTrigBelow(upper: Line): CurveFactory;
export declare function curveTrigBetween(lower: Line, upper: Line): CurveFactory;

// ---- stacked areas (stack.js) ----------------------------------------------

/** One series of d3.stack()'s result: [lower, upper] per point, .key, .index. */
export interface StackSeries<D = unknown> extends ArrayLike<ArrayLike<number> & { data?: D }> {
  key?: string;
  index?: number;
}
export type StackOffset = 'auto' | 'none' | 'expand' | 'silhouette' | 'baseline';
export interface StackLayer {
  key: string | undefined;
  /** the place in the stack, 0 at the bottom */
  index: number;
  x: Float64Array;
  y0: Float64Array;
  y1: Float64Array;
}
export interface StackLayers extends Array<StackLayer> {
  x: Float64Array;
  offset: StackOffset;
  /** layers drawn with straight pieces (the scheme refused their data) */
  linear: number;
  /** evaluated values below 0 set to 0 (0 when every certificate holds) */
  clamped: number;
  certified: boolean;
}
export interface StackTrig {
  (series: ArrayLike<StackSeries>): StackLayers;
  x(accessor: ((point: ArrayLike<number> & { data?: any }, i: number) => number) | number): StackTrig;
  offset(name: StackOffset): StackTrig;
  samples(perInterval: number): StackTrig;
  options(o: Omit<SplineOptions, 'shape'>): StackTrig;
  module(ts: TrigSpline): StackTrig;
}
export declare function stackTrig(): StackTrig;
export interface AreaTrig {
  /** the band between y0 and y1: an SVG path string, or undefined when drawing into a context */
  (layer: Pick<StackLayer, 'x' | 'y0' | 'y1'>): string | undefined;
  line(layer: Pick<StackLayer, 'x' | 'y1'>): string | undefined;
  x(scale: (v: number) => number): AreaTrig;
  y(scale: (v: number) => number): AreaTrig;
  context(ctx: PathContext | null): AreaTrig;
  digits(d: number): AreaTrig;
}
export declare function areaTrig(): AreaTrig;
export declare function fitThicknesses(ts: TrigSpline, x: Numbers, thick: Numbers[], xs: Float64Array,
  options?: Omit<SplineOptions, 'shape'>): { sums: Float64Array[]; linear: number; clamped: number; certified: boolean };

// ---- chart plugins (charts.js) ------------------------------------------------

export declare function stackPixels(ts: TrigSpline, px: Numbers, layers: Numbers[], base: number | Numbers,
  dir: 1 | -1, samples?: number): { xs: Float64Array; ys: Float64Array[]; base: Float64Array; positive: boolean } | null;
/** Chart.js plugin: Chart.register(chartjsTrigspline); options.plugins.trigspline.enabled = true. */
export declare const chartjsTrigspline: {
  id: 'trigspline';
  defaults: { enabled: boolean; samples: number; module: TrigSpline | null };
  beforeDatasetsDraw(chart: any, args: unknown, options: { enabled?: boolean; samples?: number; module?: TrigSpline | null }): void;
};
/** ECharts: once per echarts namespace; then smooth: 'trigspline' on line series. */
export declare function installEChartsTrigspline(echarts: { registerPostUpdate(f: (ecModel: any, api: any) => void): void },
  options?: { module?: TrigSpline; samples?: number }): void;

// ---- the explorer's exports through the CLI module (export.js) --------------

export interface ExplorerState {
  mode: 'function' | 'curve';
  points: number[][];
  [option: string]: unknown;
}
/** x in seconds since 1970 (UTC) as ISO 8601: a date for a whole day, else a
 * date-time in UTC with the fraction of a second to 1 ns. */
export declare function isoText(t: number): string;
export declare function dataCsv(state: ExplorerState): string;
export declare function cliArgs(state: ExplorerState, dataPath?: string): string[];
export declare const EXPORTS: Record<'csv' | 'json' | 'svg', { args: string[]; file: string; type: string }>;
export declare function runCli(factory: (options: object) => Promise<any>, args: string[],
  files: Record<string, string>): Promise<{ status: number; stderr: string; read(name: string): string | null }>;
export declare function exportState(factory: (options: object) => Promise<any>, state: ExplorerState,
  kind: 'csv' | 'json' | 'svg'): Promise<{ text: string; type: string; name: string }>;
