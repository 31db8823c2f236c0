// Opens pages written by `rt export-web` in headless Chromium (SwiftShader's WebGL2) and writes
// each page's first frame, as the page read it back with readPixels (window.__rtPixels), to
// OUT/NAME.png; the comparison with the CPU render is rt compare's (cmake/check_web_export.cmake).
//   node render_pages.js OUT PAGE.html[@SWITCH,...]...
// With @SWITCH,...: after the first frame each switch of the page's panel (its checkbox
// #toggle-SWITCH: specular, shadows, ...) is clicked, the frame it draws written to
// OUT/NAME.SWITCH.png (cmake/check_web_toggles.cmake compares it with rt render's), and clicked
// again, which must draw the first frame exactly.
// A console error, an uncaught exception, a WebGL error or any request beyond the page's own
// file fails the page (exit 1). A browser
// without WebGL2 prints one "SKIPPED: ..." line naming its renderer and exits 0.
'use strict';
const fs = require('fs');
const path = require('path');
const puppeteer = require('puppeteer-core');

const kChromium = process.env.RT_CHROMIUM || '/usr/bin/chromium';
const kTimeoutMs = 100000;  // the slowest page compiles and draws in a few seconds

// Clicks each switch, writes the frame it draws, clicks it back; returns the problems.
async function flipSwitches(page, name, switches, out) {
  const problems = [];
  const first = await page.evaluate(() => window.__rtPixels);
  for (const s of switches) {
    const box = await page.$('#toggle-' + s);
    if (!box || await page.evaluate((b) => b.disabled, box)) {
      problems.push('the page has no switch "' + s + '" to click');
      continue;
    }
    await box.click();
    const url = await page.evaluate(() => window.__rtFrame());
    fs.writeFileSync(path.join(out, name + '.' + s + '.png'),
      Buffer.from(url.replace(/^data:image\/png;base64,/, ''), 'base64'));
    await box.click();
    if (await page.evaluate(() => window.__rtFrame()) !== first)
      problems.push('switching ' + s + ' back does not draw the first frame again');
  }
  return problems;
}

async function renderPage(browser, argument, out) {
  const [file, switchList] = argument.split('@');
  const switches = switchList ? switchList.split(',') : [];
  const problems = [];
  const page = await browser.newPage();
  page.on('console', (m) => { if (m.type() === 'error') problems.push('console: ' + m.text()); });
  page.on('pageerror', (e) => problems.push('uncaught: ' + e.message));
  // Self-contained: the page's own file and data: URLs only.
  const own = 'file://' + path.resolve(file);
  page.on('request', (r) => {
    if (r.url() !== own && !r.url().startsWith('data:')) problems.push('fetches ' + r.url());
  });
  const t0 = Date.now();
  await page.goto(own);
  await page.waitForFunction(() => window.__rtDone !== undefined, { timeout: kTimeoutMs });
  const done = await page.evaluate(() => window.__rtDone);
  if (done.noWebgl2) return { skip: 'SKIPPED: this Chromium offers no WebGL2 (' + done.renderer + ')' };
  const name = path.basename(file, '.html');
  if (done.ok) {
    const url = await page.evaluate(() => window.__rtPixels);
    fs.writeFileSync(path.join(out, name + '.png'),
      Buffer.from(url.replace(/^data:image\/png;base64,/, ''), 'base64'));
    try {
      problems.push(...await flipSwitches(page, name, switches, out));
    } catch (e) {
      problems.push('switching: ' + e.message);
    }
  } else {
    problems.push('the page failed: ' + done.error);
  }
  const seconds = ((Date.now() - t0) / 1000).toFixed(1);
  await page.close();
  return { name: name, seconds: seconds, renderer: done.renderer, problems: problems };
}

async function main() {
  const [out, ...files] = process.argv.slice(2);
  if (!out || files.length === 0) throw new Error('usage: node render_pages.js OUT PAGE.html...');
  fs.mkdirSync(out, { recursive: true });
  const browser = await puppeteer.launch({
    executablePath: kChromium,
    headless: 'new',
    args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox'],
  });
  let failed = 0;
  try {
    for (const file of files) {
      const r = await renderPage(browser, file, out);
      if (r.skip) { console.log(r.skip); return 0; }
      const verdict = r.problems.length ? 'FAILED' : 'drawn';
      console.log(`${r.name}: ${verdict} in ${r.seconds} s on ${r.renderer}`);
      for (const p of r.problems) console.log('  ' + p);
      if (r.problems.length) ++failed;
    }
  } finally {
    await browser.close();
  }
  return failed ? 1 : 0;
}

main().then((code) => process.exit(code), (e) => {
  console.log('render_pages: ' + e.message);
  process.exit(1);
});
