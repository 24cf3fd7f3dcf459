// Exports of the explorer: CSV samples, the JSON report and the SVG plot,
// written by the command-line tool itself (tools/cli compiled to WebAssembly:
// trigspline-cli.mjs), so they are the CLI's bytes.  This file is the one
// place where an explorer state becomes a command line.

// x (seconds since 1970, UTC) as ISO 8601: a date when it is a whole day,
// else a date-time in UTC with the fraction of a second to 1 ns.
export function isoText(t) {
  let s = Math.floor(t), ns = Math.round((t - s) * 1e9);
  if (ns === 1e9) { s += 1; ns = 0; }
  const iso = new Date(s * 1000).toISOString();
  if (ns === 0 && s % 86400 === 0) return iso.slice(0, 10);
  const frac = ns ? `.${String(ns).padStart(9, '0').replace(/0+$/, '')}` : '';
  return `${iso.slice(0, 19)}${frac}Z`;
}

// One CSV field (RFC 4180 quoting when needed).
const field = (v) => (/[",;\t\r\n ]/.test(v) ? `"${v.replace(/"/g, '""')}"` : v);

// The data file as the CLI reads it (numbers in JavaScript's shortest
// round-trip form, which the CLI's reader parses back to the same doubles;
// x as ISO 8601 when state.xTime; the header from state.names, the column
// names the data were read with, when they are text).
export function dataCsv(state) {
  let head = state.mode === 'curve' ? 'x,y' : 'x,f';
  const names = state.mode === 'function' ? state.names : null;
  if (Array.isArray(names) && names.length === 2 && names.every((n) => typeof n === 'string' && n.trim() !== '' && !Number.isFinite(Number(n)))) {
    head = names.map(field).join(',');
  }
  const xt = state.mode === 'function' && state.xTime ? isoText : String;
  return `${head}\n${state.points.map((p) => `${xt(p[0])},${p[1]}`).join('\n')}\n`;
}

const line = (l) => `${l.m},${l.c}`;

// The command line (without the output options) for a state:
//   state.mode 'function': fit DATA --shape S [--lower M,C] [--upper M,C] --form F
//     --slopes D (--alpha A | --alphas A0,...) [--beta B | --margin T]
//   state.mode 'curve': curve DATA [--closed] --param P --slopes D
//     (--alpha A | --alphas ...) --beta B [--box X0,X1,Y0,Y1 --margin T]
export function cliArgs(state, dataPath = 'data.csv') {
  const alpha = state.alphas ? ['--alphas', state.alphas.join(',')] : ['--alpha', `${state.alpha}`];
  if (state.mode === 'curve') {
    const a = ['curve', dataPath];
    if (state.closed) a.push('--closed');
    a.push('--param', state.param, '--slopes', state.slopes, ...alpha, '--beta', `${state.beta}`);
    if (state.box && state.box.on) {
      const b = state.box;
      a.push('--box', [b.xmin, b.xmax, b.ymin, b.ymax].join(','), '--margin', `${state.margin}`);
    }
    return a;
  }
  const a = ['fit', dataPath, '--shape', state.scheme];
  if (state.scheme === 'above' || state.scheme === 'between') a.push('--lower', line(state.lower));
  if (state.scheme === 'below' || state.scheme === 'between') a.push('--upper', line(state.upper));
  a.push('--form', state.form, '--slopes', state.slopes, ...alpha);
  if (state.scheme === 'none') a.push('--beta', `${state.beta}`);
  else a.push('--margin', `${state.margin}`);
  return a;
}

// The output options of each export, and the file it is read from.
export const EXPORTS = {
  csv: { args: ['-o', 'out.csv'], file: 'out.csv', type: 'text/csv' },
  json: { args: ['--json', '-o', 'out.json'], file: 'out.json', type: 'application/json' },
  svg: { args: ['--svg', 'out.svg', '-o', 'samples.csv'], file: 'out.svg', type: 'image/svg+xml' },
};

// Run the CLI module (factory = the default export of trigspline-cli.mjs) on
// args with the given files in its in-memory file system.  Returns
// {status, stderr, read(name)}.  A fresh instance per run: the CLI's state
// starts clean every time.
export async function runCli(factory, args, files) {
  let stderr = '';
  const mod = await factory({
    noInitialRun: true,
    print: () => {},
    printErr: (s) => { stderr += `${s}\n`; },
  });
  for (const [name, text] of Object.entries(files)) mod.FS.writeFile(name, text);
  let status;
  try {
    status = mod.callMain(args);
  } catch (e) {
    if (e && typeof e.status === 'number') status = e.status; // exit() called
    else throw e;
  }
  return {
    status,
    stderr,
    read(name) {
      try {
        // emscripten's umask() stub leaves the CLI's renamed outputs at mode 000
        mod.FS.chmod(name, 0o644);
        return mod.FS.readFile(name, { encoding: 'utf8' });
      } catch { return null; }
    },
  };
}

// One export of a state: {text, type, name} or an Error with the CLI's message.
export async function exportState(factory, state, kind) {
  const e = EXPORTS[kind];
  const r = await runCli(factory, [...cliArgs(state), ...e.args], { 'data.csv': dataCsv(state) });
  const text = r.read(e.file);
  if (r.status !== 0 || text === null) {
    throw new Error(`trigspline ${cliArgs(state).join(' ')}: exit ${r.status}: ${r.stderr.trim()}`);
  }
  return { text, type: e.type, name: `trigspline.${kind}` };
}
