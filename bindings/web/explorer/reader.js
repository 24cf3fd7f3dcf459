// Reading pasted or dropped data with the command-line tool's own reader
// (tools/cli compiled to WebAssembly, the module of the exports): the text
// becomes a file of its in-memory file system and `trigspline fit FILE --json`
// (or `curve` for a parametric curve) reads it with the command's options,
// so the explorer accepts exactly what the command accepts (delimiters,
// decimal comma, missing-value words, quoted fields, headers, ISO 8601
// dates) and refuses the rest with the command's message (FILE:LINE:COLUMN).
import { runCli } from '../export.js';

// The command's reading options for o = {delimiter: 'auto'|','|';'|'tab'|
// 'space', decimal: 'auto'|'point'|'comma', na: 'WORDS' or '', missing:
// 'skip'|'error', columns: 'X,Y' or '', xTime: bool}; '' and 'auto' leave the
// command's own default.  'auto' decimal: see readTable.
export function readArgs(o, mode) {
  const a = [];
  if (o.delimiter && o.delimiter !== 'auto') a.push('--delimiter', o.delimiter);
  if (o.decimal === 'comma') a.push('--decimal-comma');
  if (o.na) a.push('--na', o.na);
  if (o.missing) a.push('--missing', o.missing);
  if (mode === 'function' && o.columns) a.push('--columns', o.columns);
  if (mode === 'function' && o.xTime) a.push('--x-time');
  return a;
}

// The first line that is not blank or a comment starts with an empty field
// (R's write.csv writes "" there above its row names, pandas' to_csv an empty
// cell above its index).
function rowNamesFirst(text) {
  for (const line of text.split(/\r?\n/, 200)) {
    const t = line.trim();
    if (!t || t.startsWith('#')) continue;
    return /^(""|'')?\s*[,;\t]/.test(line);
  }
  return false;
}

// A file name the command takes as a file (not an option), without folders.
function fileName(name) {
  const base = String(name || 'pasted.csv').split(/[\\/]/).pop() || 'pasted.csv';
  return base.startsWith('-') ? `./${base}` : base;
}

// Points from the command's JSON report: fit (x from the intervals' x0/x1,
// which are numbers also when the knots print x as dates) or curve (the
// segments' end points, which are the data).
function pointsOf(js) {
  if (js.command === 'curve') {
    const S = js.segments;
    return [...S.map((s) => s.P[0]), S[S.length - 1].P[3]].map((p) => [p[0], p[1]]);
  }
  const I = js.intervals;
  return js.knots.map((k, i) => [i < I.length ? I[i].x0 : I[I.length - 1].x1, k.f]);
}

async function readOnce(factory, text, name, o, mode) {
  const cmd = mode === 'curve' ? 'curve' : 'fit';
  const opts = readArgs(o, mode);
  const args = [cmd, name, ...opts, '-v', '--json', '-o', 'read.json'];
  const r = await runCli(factory, args, { [name]: text });
  const lines = r.stderr.split('\n').map((l) => l.replace(/^trigspline: /, '')).filter(Boolean);
  const command = `trigspline ${[cmd, name, ...opts].join(' ')}`;
  const out = r.status === 0 ? r.read('read.json') : null;
  if (out === null) {
    // the command's message; its advice names its own options (shown with the form's)
    return { ok: false, status: r.status, message: lines.filter((l) => !l.startsWith('warning: ')).join('\n') || `exit ${r.status}`, command };
  }
  const js = JSON.parse(out);
  if (js.command === 'curve' && js.dim !== 2) {
    return { ok: false, status: 2, message: `${name}: ${js.dim} coordinates per point; the explorer draws plane curves (x, y)`, command };
  }
  return {
    ok: true,
    command,
    points: pointsOf(js),
    xTime: js.command === 'fit' ? !!js.columns.x_time : false,
    names: js.command === 'fit' ? [js.columns.x, js.columns.y] : null,
    skipped: js.rows ? js.rows.skipped_missing : 0,
    // what the command reports about the rows (-v): the skipped ones, by line
    report: lines.filter((l) => l.startsWith(`${name}:`)),
  };
}

// Read text (the contents of a file called name) as the command does for the
// explorer's mode ('function' or 'curve') with the options o (readArgs).
// Returns {ok, points, xTime, names, skipped, report, notes, command} or
// {ok: false, message, command}.  Two choices the command leaves to its user
// are made here, each stated in notes: with decimal 'auto', data that the
// command refuses for want of --decimal-comma are read again with it; a
// first column without a name (row names) is passed over (--columns 2,3)
// unless columns are given.
export async function readTable(factory, text, name, o, mode = 'function') {
  const file = fileName(name);
  const opt = { ...o };
  const notes = [];
  if (mode === 'function' && !opt.columns && rowNamesFirst(text)) {
    opt.columns = '2,3';
    notes.push('the first column has no name (row names, as R\'s write.csv writes them): columns 2 and 3 read (--columns 2,3)');
  }
  let r = await readOnce(factory, text, file, opt, mode);
  if (!r.ok && (opt.decimal ?? 'auto') === 'auto' && /--decimal-comma/.test(r.message)) {
    // the decimal comma was what the command missed unless it still is
    const again = await readOnce(factory, text, file, { ...opt, decimal: 'comma' }, mode);
    if (again.ok || !/decimal/.test(again.message)) {
      r = again;
      notes.push('numbers with a decimal comma: read with --decimal-comma');
    }
  }
  return { ...r, notes };
}
