// The gallery's page script (build.mjs inlines it after the module, DATA and
// COSTS).  d3, Chart and echarts are the inlined UMD globals.
/* global d3, Chart, echarts, DATA, COSTS, load, stackTrig, areaTrig, chartjsTrigspline,
   installEChartsTrigspline, stackPixels */
const ts = await load();
Chart.register(chartjsTrigspline);
installEChartsTrigspline(echarts);
const W = 460, H = 260, M = { l: 44, r: 8, t: 8, b: 22 };
const colors = d3.schemeTableau10;
const OURS_D3 = 'trigspline stackTrig + areaTrig (d3)';
const OURS_PLUGIN = 'trigspline plugins (Chart.js, ECharts: stackPixels)';
const gallery = document.getElementById('gallery');
const drawn = [];

function costText(c, unit) {
  if (c.cross <= 1e-9 && c.below <= 1e-9) return '<span class="good">0 crossings, nothing below 0</span>';
  const parts = [];
  if (c.cross > 1e-9) {
    parts.push(`<span class="bad">a layer goes ${c.cross.toPrecision(3)} ${unit} under the layer below it, `
      + `over ${(100 * c.fraction).toFixed(0)} % of the x range</span>`);
  }
  if (c.below > 1e-9) parts.push(`<span class="bad">dips to −${c.below.toPrecision(3)} ${unit}</span>`);
  return parts.join('; ');
}

function section(title, text) {
  const h = document.createElement('h2');
  h.textContent = title;
  gallery.append(h);
  if (text) {
    const p = document.createElement('p');
    p.innerHTML = text;
    gallery.append(p);
  }
}

// A before/after pair: make(plotElement) draws each panel.
function pair(id, left, right) {
  const div = document.createElement('div');
  div.className = 'pair';
  div.id = id;
  for (const [side, spec] of [['before', left], ['after', right]]) {
    const panel = document.createElement('div');
    panel.className = `panel ${side}`;
    panel.innerHTML = `<h3>${spec.title}</h3>`;
    const plot = spec.tag === 'svg' ? document.createElementNS('http://www.w3.org/2000/svg', 'svg')
      : document.createElement(spec.tag);
    plot.setAttribute('class', 'plot');
    if (spec.tag === 'canvas') { plot.width = W; plot.height = H; }
    panel.append(plot);
    const cost = document.createElement('p');
    cost.className = 'cost';
    cost.innerHTML = spec.cost;
    panel.append(cost);
    div.append(panel);
    drawn.push({ id, side, plot, spec });
  }
  gallery.append(div);
}

// ---- d3 ---------------------------------------------------------------------
function d3Stack(ds, offset) {
  return d3.stack().keys(ds.keys).offset(offset)(ds.rows);
}
function d3Axes(svg, x, y, fmt) {
  const span = x.domain()[1] - x.domain()[0];
  svg.append('g').attr('transform', `translate(0,${H - M.b})`).call(d3.axisBottom(x).ticks(Math.min(6, span)).tickFormat(fmt));
  svg.append('g').attr('transform', `translate(${M.l},0)`).call(d3.axisLeft(y).ticks(5));
}
function d3Panel(plot, ds, offset, mode, fmt, curve = d3.curveMonotoneX) {
  const series = d3Stack(ds, offset);
  const x = d3.scaleLinear(d3.extent(ds.rows, (r) => r.x), [M.l, W - M.r]);
  const y = d3.scaleLinear([Math.min(0, d3.min(series, (s) => d3.min(s, (d) => d[0]))),
    d3.max(series, (s) => d3.max(s, (d) => d[1]))], [H - M.b, M.t]).nice();
  const svg = d3.select(plot).attr('viewBox', `0 0 ${W} ${H}`).attr('width', W).attr('height', H);
  if (mode === 'before') {
    const area = d3.area().x((d) => x(d.data.x)).y0((d) => y(d[0])).y1((d) => y(d[1])).curve(curve);
    svg.selectAll('path.layer').data(series).join('path').attr('class', 'layer')
      .attr('fill', (s, k) => colors[k % 10]).attr('fill-opacity', 0.8).attr('d', area);
  } else {
    const layers = stackTrig().x((d) => d.data.x).module(ts)(series);
    const area = areaTrig().x(x).y(y);
    svg.selectAll('path.layer').data(layers).join('path').attr('class', 'layer')
      .attr('fill', (l, k) => colors[k % 10]).attr('fill-opacity', 0.8).attr('d', area);
  }
  d3Axes(svg, x, y, fmt);
}

// ---- Chart.js -----------------------------------------------------------------
function chartjsPanel(plot, ds, mode, stacked) {
  return new Chart(plot, {
    type: 'line',
    data: {
      labels: ds.rows.map((r) => r.x),
      datasets: ds.keys.map((k, i) => ({
        label: ds.labels[i], data: ds.rows.map((r) => r[k]), borderColor: colors[i % 10],
        backgroundColor: `${colors[i % 10]}cc`, fill: stacked ? (i ? '-1' : 'origin') : 'origin',
        tension: 0.4, pointRadius: 0, borderWidth: 1,
      })),
    },
    options: {
      animation: false, responsive: false, plugins: { legend: { display: false },
        trigspline: { enabled: mode === 'after' } },
      scales: { y: { stacked, beginAtZero: true }, x: { ticks: { maxTicksLimit: 8 } } },
    },
  });
}

// ---- ECharts ------------------------------------------------------------------
function echartsPanel(plot, ds, mode, stacked) {
  const chart = echarts.init(plot, null, { renderer: 'canvas', width: W, height: H });
  chart.setOption({
    animation: false, color: colors,
    grid: { left: 44, right: 8, top: 8, bottom: 24 },
    xAxis: { type: 'category', boundaryGap: false, data: ds.rows.map((r) => r.x) },
    yAxis: { type: 'value' },
    series: ds.keys.map((k) => ({
      type: 'line', name: k, data: ds.rows.map((r) => r[k]), stack: stacked ? 'total' : undefined,
      areaStyle: { opacity: 0.8 }, showSymbol: false, lineStyle: { width: 1 },
      smooth: mode === 'after' ? 'trigspline' : true,
    })),
  });
  return chart;
}

// ---- the page -----------------------------------------------------------------
const c = (name, method, unit) => costText(COSTS[name][method], unit);
const year = d3.format('d');
section('d3 — d3-shape#81', 'The issue\'s own data (open since 2016): with <code>curveMonotoneX</code> the top '
  + 'line of the upper layer runs under the top of the lower one. <code>stackTrig()</code> + <code>areaTrig()</code> '
  + 'on the same <code>d3.stack()</code> result cannot.');
pair('d3-81', { title: 'd3.area().curve(d3.curveMonotoneX)', tag: 'svg', cost: c('issue81', 'd3 curveMonotoneX', ''),
  draw: (p) => d3Panel(p, DATA.issue81, d3.stackOffsetNone, 'before', d3.format('d')) },
{ title: 'stackTrig() + areaTrig()', tag: 'svg', cost: c('issue81', OURS_D3, ''),
  draw: (p) => d3Panel(p, DATA.issue81, d3.stackOffsetNone, 'after', d3.format('d')) });
section('d3 — UK electricity mix (TWh)', 'Eight sources, coal falling to almost nothing, solar 0 until 2004.');
pair('d3-uk', { title: 'curveMonotoneX', tag: 'svg', cost: c('uk', 'd3 curveMonotoneX', 'TWh'),
  draw: (p) => d3Panel(p, DATA.uk, d3.stackOffsetNone, 'before', year) },
{ title: 'stackTrig()', tag: 'svg', cost: c('uk', OURS_D3, 'TWh'),
  draw: (p) => d3Panel(p, DATA.uk, d3.stackOffsetNone, 'after', year) });
section('d3 — the same as shares of generation (a percentage, stackOffsetExpand)',
  'With <code>stackOffsetExpand</code> the fitted layers are divided by their sum at every drawn x: the top stays at exactly 100 %.');
pair('d3-share', { title: 'curveMonotoneX, stackOffsetExpand', tag: 'svg', cost: c('ukShare', 'd3 curveMonotoneX', '%'),
  draw: (p) => d3Panel(p, DATA.uk, d3.stackOffsetExpand, 'before', year) },
{ title: 'stackTrig(), stackOffsetExpand', tag: 'svg', cost: c('ukShare', OURS_D3, '%'),
  draw: (p) => d3Panel(p, DATA.uk, d3.stackOffsetExpand, 'after', year) });
section('d3 — daily rain (mm), one layer', '<code>curveCardinal</code> (britecharts#172: \"Area chart was dipping below 0\") '
  + 'against <code>stackTrig()</code> on a one-layer stack.');
pair('d3-rain', { title: 'curveCardinal', tag: 'svg', cost: c('rain', 'd3 curveCardinal', 'mm'),
  draw: (p) => d3Panel(p, DATA.rain, d3.stackOffsetNone, 'before', d3.format('d'), d3.curveCardinal) },
{ title: 'stackTrig()', tag: 'svg', cost: c('rain', OURS_D3, 'mm'),
  draw: (p) => d3Panel(p, DATA.rain, d3.stackOffsetNone, 'after', d3.format('d')) });
section('Chart.js — stacked area and a line', 'After: <code>Chart.register(chartjsTrigspline)</code> and '
  + '<code>plugins: { trigspline: { enabled: true } }</code>.');
pair('chartjs-uk', { title: 'UK mix, tension: 0.4', tag: 'canvas', cost: c('uk', 'Chart.js tension 0.4', 'TWh'),
  draw: (p) => chartjsPanel(p, DATA.uk, 'before', true) },
{ title: 'UK mix, trigspline plugin', tag: 'canvas', cost: c('uk', OURS_PLUGIN, 'TWh'),
  draw: (p) => chartjsPanel(p, DATA.uk, 'after', true) });
pair('chartjs-rain', { title: 'daily rain (mm), tension: 0.4', tag: 'canvas', cost: c('rain', 'Chart.js tension 0.4', 'mm'),
  draw: (p) => chartjsPanel(p, DATA.rain, 'before', false) },
{ title: 'daily rain (mm), trigspline plugin', tag: 'canvas', cost: c('rain', OURS_PLUGIN, 'mm'),
  draw: (p) => chartjsPanel(p, DATA.rain, 'after', false) });
section('ECharts — stacked area and a line', 'After: <code>installEChartsTrigspline(echarts)</code> and '
  + '<code>smooth: \'trigspline\'</code> on the series.');
pair('echarts-uk', { title: 'UK mix, smooth: true', tag: 'div', cost: c('uk', 'ECharts smooth: true', 'TWh'),
  draw: (p) => echartsPanel(p, DATA.uk, 'before', true) },
{ title: 'UK mix, smooth: \'trigspline\'', tag: 'div', cost: c('uk', OURS_PLUGIN, 'TWh'),
  draw: (p) => echartsPanel(p, DATA.uk, 'after', true) });
pair('echarts-rain', { title: 'daily rain (mm), smooth: true', tag: 'div', cost: c('rain', 'ECharts smooth: true', 'mm'),
  draw: (p) => echartsPanel(p, DATA.rain, 'before', false) },
{ title: 'daily rain (mm), smooth: \'trigspline\'', tag: 'div', cost: c('rain', OURS_PLUGIN, 'mm'),
  draw: (p) => echartsPanel(p, DATA.rain, 'after', false) });

const charts = [];
for (const d of drawn) charts.push(d.spec.draw(d.plot));
// for the browser test: the panels and what the module exports
window.gallery = { panels: drawn.length, charts, drawn, ts, stackTrig, areaTrig, stackPixels };
document.body.dataset.ready = '1';
