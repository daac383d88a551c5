// Loads a brdfkit report in headless Chromium (Debian's /usr/bin/chromium through playwright-core,
// no browser download, no network) and fails (exit 1, one line per problem) unless every page
// opens with no console error, no failed request, every image decoded, every chart drawn and every
// local link resolving. Saves full-page screenshots of the index and of the first material page.
// Usage: node check_report.mjs SITE_DIR SCREENSHOT_DIR
import { chromium } from 'playwright-core';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const [site, shots] = process.argv.slice(2);
if (!site || !shots) {
  console.error('usage: node check_report.mjs SITE_DIR SCREENSHOT_DIR');
  process.exit(2);
}
fs.mkdirSync(shots, { recursive: true });
const problems = [];
const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'brdfkit-chromium-'));
// A new empty profile (playwright passes it as --user-data-dir).
const browser = await chromium.launchPersistentContext(profile, {
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  headless: true,
  viewport: { width: 1280, height: 900 },
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
         '--disable-component-update', '--disable-sync'],
});

async function check(file, shot) {
  const page = await browser.newPage();
  const where = path.relative(site, file);
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`${where}: console error: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`${where}: script error: ${e.message}`));
  page.on('requestfailed', (r) => problems.push(`${where}: request failed: ${r.url()}`));
  page.on('request', (r) => { if (!r.url().startsWith('file:')) problems.push(`${where}: network request: ${r.url()}`); });
  await page.goto(pathToFileURL(file).href, { waitUntil: 'load' });
  await page.waitForTimeout(300);
  const report = await page.evaluate(() => {
    const out = { images: [], charts: [], links: [] };
    for (const img of document.images) out.images.push({ src: img.getAttribute('src'), ok: img.complete && img.naturalWidth > 0 });
    for (const div of document.querySelectorAll('.chart')) {
      const inst = window.echarts && echarts.getInstanceByDom(div);
      const series = inst ? inst.getOption().series || [] : [];
      const points = series.reduce((n, s) => n + (s.data ? s.data.filter((d) => d !== null).length : 0), 0);
      const canvas = div.querySelector('canvas');
      out.charts.push({ id: div.dataset.chart || div.id, ok: !!inst && points > 0 && !!canvas && canvas.width > 0, points });
    }
    for (const a of document.querySelectorAll('a[href]')) out.links.push(a.getAttribute('href'));
    return out;
  });
  for (const i of report.images) if (!i.ok) problems.push(`${where}: image missing or undecodable: ${i.src}`);
  for (const c of report.charts) if (!c.ok) problems.push(`${where}: chart not drawn: ${c.id}`);
  const targets = [];
  for (const href of report.links) {
    if (/^[a-z]+:/i.test(href)) { problems.push(`${where}: link leaves the report: ${href}`); continue; }
    const target = path.resolve(path.dirname(file), decodeURIComponent(href.split('#')[0]));
    if (!fs.existsSync(target)) problems.push(`${where}: broken link: ${href}`);
    else targets.push(target);
  }
  if (shot) await page.screenshot({ path: path.join(shots, shot), fullPage: true });
  console.log(`${where}: ${report.images.length} images, ${report.charts.length} charts, ${report.links.length} links`);
  await page.close();
  return targets;
}

const index = path.join(site, 'index.html');
const linked = await check(index, 'index.png');
const pages = linked.filter((t) => t.endsWith('.html'));
if (pages.length === 0) problems.push('index.html: links to no material page');
for (const [k, p] of pages.entries()) await check(p, k === 0 ? 'material.png' : null);
await browser.close();
fs.rmSync(profile, { recursive: true, force: true });
for (const p of problems) console.log('PROBLEM ' + p);
console.log(problems.length ? `${problems.length} problem(s)` : `report OK: ${pages.length + 1} pages`);
process.exit(problems.length ? 1 : 0);
