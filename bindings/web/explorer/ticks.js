// Axis ticks of the explorer's plot: round numbers (steps 1, 2 or 5 times a
// power of ten, as matplotlib's MaxNLocator with steps [1, 2, 5, 10]) and,
// for an x of dates (seconds since 1970, UTC, as the command reads ISO 8601),
// calendar steps (seconds, minutes, hours, days, months, years) labelled as
// dates.

// The smallest step 1, 2 or 5 times a power of ten that puts at most `most`
// intervals on [lo, hi].
export function niceStep(lo, hi, most = 8) {
  const raw = (hi - lo) / most;
  if (!(raw > 0) || !Number.isFinite(raw)) return 1;
  const p = 10 ** Math.floor(Math.log10(raw));
  for (const m of [1, 2, 5, 10]) if (m * p >= raw * (1 - 1e-12)) return m * p;
  return 10 * p;
}

// Ticks on [lo, hi]: {values, labels, step}.  Values are k * step (computed
// as integer k times step, then rounded to the step's decimals so that 0.3
// is 0.3), labels with exactly the decimals the step needs.
export function numberTicks(lo, hi, most = 8) {
  const step = niceStep(lo, hi, most);
  const dec = Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
  const values = [], labels = [];
  const k0 = Math.ceil(lo / step - 1e-9), k1 = Math.floor(hi / step + 1e-9);
  for (let k = k0; k <= k1 && values.length < 100; k++) {
    const v = +(k * step).toFixed(Math.min(dec, 20));
    values.push(v);
    labels.push(numberLabel(v, step, dec));
  }
  return { values, labels, step };
}

// v with the step's decimals; very large or small steps in exponent form with
// as many mantissa digits as the step has below v's exponent.
function numberLabel(v, step, dec) {
  if (v === 0 || !(step >= 1e9 || step < 1e-6)) return (v < 0 ? '-' : '') + Math.abs(v).toFixed(dec);
  const e = Math.floor(Math.log10(Math.abs(v)) + 1e-12), d = Math.max(0, e - Math.floor(Math.log10(step) + 1e-9));
  return v.toExponential(Math.min(d, 20)).replace('e+', 'e');
}

const MIN = 60, HOUR = 3600, DAY = 86400;
// calendar steps: [unit, count]; units 's' (seconds), 'M' (months), 'Y' (years)
const DATE_STEPS = [
  ['s', 1], ['s', 2], ['s', 5], ['s', 10], ['s', 15], ['s', 30],
  ['s', MIN], ['s', 2 * MIN], ['s', 5 * MIN], ['s', 10 * MIN], ['s', 15 * MIN], ['s', 30 * MIN],
  ['s', HOUR], ['s', 2 * HOUR], ['s', 3 * HOUR], ['s', 6 * HOUR], ['s', 12 * HOUR],
  ['s', DAY], ['s', 2 * DAY], ['s', 7 * DAY], ['s', 14 * DAY],
  ['M', 1], ['M', 2], ['M', 3], ['M', 6], ['Y', 1], ['Y', 2], ['Y', 5], ['Y', 10], ['Y', 20], ['Y', 50], ['Y', 100],
];
const approx = ([u, c]) => (u === 's' ? c : u === 'M' ? c * 30.44 * DAY : c * 365.25 * DAY);
const pad = (v, n = 2) => String(v).padStart(n, '0');

// Date ticks on [lo, hi] (seconds since 1970): {values, labels, unit}.  Weeks
// start on Mondays, months on the 1st, years on 1 January; a label says as
// much as the step needs (2024, 2024-03, 2024-03-05, 2024-03-05 12:00, 12:00:30).
export function dateTicks(lo, hi, most = 6) {
  const span = hi - lo;
  let st = DATE_STEPS[DATE_STEPS.length - 1];
  for (const s of DATE_STEPS) if (approx(s) * most >= span) { st = s; break; }
  const [unit, c] = st;
  const values = [];
  if (unit === 's') {
    // weeks from a Monday (1970-01-05), shorter steps from midnight
    const origin = c >= 7 * DAY ? 4 * DAY : 0;
    for (let k = Math.ceil((lo - origin) / c); origin + k * c <= hi && values.length < 100; k++) values.push(origin + k * c);
  } else if (unit === 'Y' && approx(st) > 5000 * 365.25 * DAY) {
    // beyond calendars: plain years of 365.25 days
    return { ...numberTicks(lo, hi, most), unit: 'number' };
  } else {
    const d = new Date(lo * 1000);
    let y = d.getUTCFullYear(), m = unit === 'M' ? d.getUTCMonth() : 0;
    if (unit === 'Y') y = Math.floor(y / c) * c; else m = Math.floor(m / c) * c;
    for (let guard = 0; guard < 2000 && values.length < 100; guard++) {
      const t = Date.UTC(y, m, 1) / 1000;
      if (t > hi) break;
      if (t >= lo) values.push(t);
      if (unit === 'Y') y += c; else { m += c; if (m >= 12) { y += Math.floor(m / 12); m %= 12; } }
    }
  }
  const fmt = (t) => {
    const d = new Date(t * 1000);
    const day = `${pad(d.getUTCFullYear(), 4)}-${pad(d.getUTCMonth() + 1)}-${pad(d.getUTCDate())}`;
    if (unit === 'Y') return String(d.getUTCFullYear());
    if (unit === 'M') return day.slice(0, 7);
    if (c >= DAY) return day;
    const hm = `${pad(d.getUTCHours())}:${pad(d.getUTCMinutes())}`;
    if (c < MIN) return `${hm}:${pad(d.getUTCSeconds())}`;
    return `${day} ${hm}`;
  };
  return { values, labels: values.map(fmt), unit: unit === 's' && c < DAY ? 'time' : 'date' };
}
