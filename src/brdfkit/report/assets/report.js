// brdfkit report: builds the tables and the Apache ECharts charts of the index and the material
// pages from the data the page's data script defines (window.BRDFKIT_INDEX / BRDFKIT_MATERIAL).
// Everything it needs is in the report folder, so the pages open offline.
'use strict';

function el(tag, attrs, text) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

function fmt(v) {
  if (v === null || v === undefined) return 'n/a';
  return Math.abs(v) >= 1e-3 && Math.abs(v) < 1e4 ? v.toPrecision(4) : v.toExponential(3);
}

// One colour per curve across all charts of a page: measured in black, fits in the order listed.
const PALETTE = ['#d62728', '#1f77b4', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2', '#17becf', '#bcbd22', '#7f7f7f'];
let colourOrder = [];
function colourOf(name) {
  if (name.startsWith('measured')) return '#111111';
  let k = colourOrder.indexOf(name);
  if (k < 0) k = colourOrder.push(name) - 1;
  return PALETTE[k % PALETTE.length];
}
const LEGEND = { top: 22, textStyle: { fontSize: 10 }, itemWidth: 14, itemHeight: 8 };

function chart(container, option) {
  for (const s of option.series || []) if (s.name) s.color = colourOf(s.name);
  const c = echarts.init(container, null, { renderer: 'canvas' });
  c.setOption(Object.assign({ animation: false, tooltip: { trigger: 'item' } }, option));
  window.addEventListener('resize', () => c.resize());
  return c;
}

// ---- index ----

function errorTable(index, metric) {
  const table = document.getElementById('error-table');
  table.innerHTML = '';
  const head = el('tr');
  head.appendChild(el('th', { class: 'name', 'data-col': 'material' }, 'material'));
  for (const m of index.models) head.appendChild(el('th', { 'data-col': m }, m));
  table.appendChild(head);
  for (const mat of index.materials) {
    const row = el('tr');
    const name = el('td', { class: 'name' });
    const link = el('a', { href: mat.page }, mat.name);
    name.appendChild(link);
    row.appendChild(name);
    const values = index.models.map((m) => (mat.errors[m] || {})[metric]);
    const finite = values.filter((v) => typeof v === 'number');
    const best = finite.length ? Math.min(...finite) : null;
    values.forEach((v, k) => {
      const cell = el('td', {}, typeof v === 'number' ? fmt(v) : mat.errors[index.models[k]] ? 'n/a' : '');
      cell.dataset.value = typeof v === 'number' ? v : '';
      if (v === best && best !== null) cell.classList.add('best');
      row.appendChild(cell);
    });
    table.appendChild(row);
  }
  head.querySelectorAll('th').forEach((th, col) => th.addEventListener('click', () => sortTable(table, col)));
}

function sortTable(table, col) {
  const rows = Array.from(table.querySelectorAll('tr')).slice(1);
  const asc = table.dataset.sortCol == col ? table.dataset.sortDir !== 'asc' : true;
  const key = (r) => {
    const cell = r.children[col];
    if (col === 0) return cell.textContent;
    return cell.dataset.value === '' ? Infinity : Number(cell.dataset.value);
  };
  rows.sort((a, b) => (key(a) < key(b) ? -1 : key(a) > key(b) ? 1 : 0) * (asc ? 1 : -1));
  rows.forEach((r) => table.appendChild(r));
  table.dataset.sortCol = col;
  table.dataset.sortDir = asc ? 'asc' : 'desc';
}

// Seed 002 Fig. 14: materials on x sorted by one model's error, every model's error on a log axis.
function errorChart(index, metric, sortModel) {
  const mats = index.materials.slice();
  const err = (mat, m) => (mat.errors[m] || {})[metric];
  mats.sort((a, b) => (err(a, sortModel) ?? Infinity) - (err(b, sortModel) ?? Infinity));
  chart(document.getElementById('error-chart'), {
    tooltip: { trigger: 'axis' },
    legend: { type: 'scroll', top: 0 },
    grid: { top: 60, bottom: 90, left: 70, right: 20 },
    xAxis: { type: 'category', data: mats.map((m) => m.name), axisLabel: { rotate: 30 } },
    yAxis: { type: 'log', name: metric + ' error (log)', nameLocation: 'middle', nameGap: 50 },
    series: index.models.map((m) => ({
      name: m, type: 'line', symbolSize: 6,
      data: mats.map((mat) => (typeof err(mat, m) === 'number' && err(mat, m) > 0 ? err(mat, m) : null)),
      lineStyle: { width: m === sortModel ? 3 : 1 },
    })),
  });
}

function buildIndex(index) {
  colourOrder = index.models.slice();
  const metricSel = document.getElementById('metric');
  const sortSel = document.getElementById('sort-model');
  for (const m of index.metrics) metricSel.appendChild(el('option', { value: m }, m));
  for (const m of index.models) sortSel.appendChild(el('option', { value: m }, m));
  metricSel.value = index.fit_metric;
  const redraw = () => {
    errorTable(index, metricSel.value);
    const old = echarts.getInstanceByDom(document.getElementById('error-chart'));
    if (old) old.dispose();
    errorChart(index, metricSel.value, sortSel.value);
  };
  metricSel.addEventListener('change', redraw);
  sortSel.addEventListener('change', redraw);
  redraw();
}

// ---- material page ----

function lineSeries(name, points, kind) {
  return kind === 'samples'
    ? { name, type: 'scatter', symbolSize: 4, data: points }
    : { name, type: 'line', showSymbol: false, data: points };
}

function sliceCharts(mat, grid) {
  for (const s of mat.plots.slices.slices) {
    const series = [];
    if (s.data.length) series.push(lineSeries('measured', s.data, s.data_kind));
    for (const [name, pts] of Object.entries(s.fits)) series.push(lineSeries(name, pts, 'curve'));
    for (const cube of [false, true]) {
      const div = el('div', { class: 'chart small', 'data-chart': `slice-${s.theta_i_deg}${cube ? '-cbrt' : ''}` });
      grid.appendChild(div);
      const map = (pts) => pts.map(([t, y]) => [t, cube ? Math.cbrt(y) : y]);
      chart(div, {
        title: { text: `θi = ${s.theta_i_deg}°: ρ cos θo${cube ? ' (cube root)' : ''}`, textStyle: { fontSize: 13 } },
        tooltip: { trigger: 'axis' }, legend: LEGEND,
        grid: { top: 70, bottom: 40, left: 55, right: 15 },
        xAxis: { type: 'value', min: -90, max: 90, name: 'θo (°, + mirror side)', nameLocation: 'middle', nameGap: 25 },
        yAxis: { type: 'value' },
        series: series.map((x) => Object.assign({}, x, { data: map(x.data) })),
      });
    }
  }
}

// Seed 002 Fig. 4: the incidence plane as a polar plot of (ρ cos θo)^(1/3), θo = 0 up.
function polarCharts(mat, grid) {
  for (const s of mat.plots.slices.slices) {
    const series = [];
    const polar = (pts) => pts.map(([t, y]) => [Math.cbrt(Math.max(y, 0)), t + 180]);
    if (s.data.length) series.push(Object.assign(lineSeries('measured', polar(s.data), s.data_kind), { coordinateSystem: 'polar' }));
    for (const [name, pts] of Object.entries(s.fits))
      series.push({ name, type: 'line', showSymbol: false, coordinateSystem: 'polar', data: polar(pts) });
    const div = el('div', { class: 'chart small', 'data-chart': `polar-${s.theta_i_deg}` });
    grid.appendChild(div);
    chart(div, {
      title: { text: `θi = ${s.theta_i_deg}°: (ρ cos θo)^1/3`, textStyle: { fontSize: 13 } },
      legend: LEGEND,
      polar: { radius: '62%', center: ['50%', '62%'] },
      angleAxis: { type: 'value', min: 0, max: 360, startAngle: 270, clockwise: true, interval: 30,
                   axisLabel: { formatter: (v) => (v >= 90 && v <= 270 ? `${v - 180}°` : '') } },
      radiusAxis: { type: 'value' },
      series,
    });
  }
}

function heatmap(div, title, cells, bins, range, label) {
  chart(div, {
    title: { text: title, textStyle: { fontSize: 13 } },
    grid: { top: 40, bottom: 60, left: 55, right: 70 },
    xAxis: { type: 'category', data: Array.from({ length: bins }, (_, k) => 2 * k), name: 'θd (°)', nameLocation: 'middle', nameGap: 25 },
    yAxis: { type: 'category', data: Array.from({ length: bins }, (_, k) => 2 * k), name: 'θh (°)' },
    visualMap: { min: range[0], max: range[1], calculable: true, orient: 'vertical', right: 0, top: 40, text: [label, ''],
                 inRange: { color: ['#313695', '#4575b4', '#abd9e9', '#ffffbf', '#fdae61', '#d73027', '#a50026'] } },
    series: [{ type: 'heatmap', data: cells }],
  });
}

function mapCharts(mat, grid) {
  const m = mat.plots.maps;
  if (!m) return;
  const all = m.data.concat(m.fit_map).map((c) => c[2]);
  const range = [Math.min(...all), Math.max(...all)];
  const specs = [['measured', m.data, range, 'log10 Y'], [m.fit, m.fit_map, range, 'log10 Y'],
                 [`measured / ${m.fit}`, m.log2_ratio, [-2, 2], 'log2']];
  for (const [title, cells, r, label] of specs) {
    const div = el('div', { class: 'chart', 'data-chart': `map-${title}` });
    grid.appendChild(div);
    heatmap(div, `(θh, θd): ${title}`, cells, m.bins, r, label);
  }
}

function albedoChart(mat, div) {
  const a = mat.plots.albedo;
  const series = [];
  const measured = a.theta_i_deg.map((t, k) => [t, a.data[k]]).filter((p) => p[1] !== null);
  if (measured.length) series.push(lineSeries('measured', measured, 'curve'));
  if (a.data_samples) series.push(lineSeries('measured (its samples)', a.data_samples, 'samples'));
  for (const [name, ys] of Object.entries(a.fits)) series.push(lineSeries(name, a.theta_i_deg.map((t, k) => [t, ys[k]]), 'curve'));
  chart(div, {
    tooltip: { trigger: 'axis' }, legend: Object.assign({}, LEGEND, { top: 0 }),
    grid: { top: 40, bottom: 40, left: 55, right: 15 },
    xAxis: { type: 'value', min: 0, max: 90, name: 'θi (°)', nameLocation: 'middle', nameGap: 25 },
    yAxis: { type: 'value', name: 'albedo (Y)' },
    series,
  });
}

function paramTables(mat, host) {
  for (const f of mat.fits) {
    host.appendChild(el('h3', {}, f.model));
    const p = el('p', { class: 'note' });
    p.appendChild(document.createTextNode(`fitting metric ${f.fit_metric}; `));
    p.appendChild(el('a', { href: f.json }, 'fit JSON'));
    host.appendChild(p);
    const t = el('table');
    const head = el('tr');
    for (const h of ['parameter', 'R', 'G', 'B']) head.appendChild(el('th', { class: h === 'parameter' ? 'name' : '' }, h));
    t.appendChild(head);
    for (const q of f.params) {
      const r = el('tr');
      r.appendChild(el('td', { class: 'name' }, q.name));
      for (const v of q.values) r.appendChild(el('td', {}, fmt(v)));
      t.appendChild(r);
    }
    for (const [id, v] of Object.entries(f.metrics)) {
      const r = el('tr');
      r.appendChild(el('td', { class: 'name' }, `error ${id}`));
      r.appendChild(el('td', { colspan: 3 }, fmt(v)));
      t.appendChild(r);
    }
    host.appendChild(t);
  }
}

function buildMaterial(mat) {
  colourOrder = mat.fits.map((f) => f.model);
  sliceCharts(mat, document.getElementById('slices'));
  polarCharts(mat, document.getElementById('polar'));
  mapCharts(mat, document.getElementById('maps'));
  albedoChart(mat, document.getElementById('albedo'));
  paramTables(mat, document.getElementById('params'));
}

window.addEventListener('DOMContentLoaded', () => {
  if (window.BRDFKIT_INDEX) buildIndex(window.BRDFKIT_INDEX);
  if (window.BRDFKIT_MATERIAL) buildMaterial(window.BRDFKIT_MATERIAL);
});
