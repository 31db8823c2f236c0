// Opens pages written by `rt export-web` in headless Chromium (SwiftShader's WebGL2) and writes
// each page's first frame, as the page read it back with readPixels (window.__rtPixels), to
// OUT/NAME.png; the comparison with the CPU render is rt compare's (cmake/check_web_export.cmake).
//   node render_pages.js [--http] OUT PAGE.html[@ACTION,...]...
// With --http the pages are opened from a plain static web server on 127.0.0.1 (serveFiles), as
// a lecturer's course web site would serve them, rather than from file://.
// With @ACTION,...: after the first frame, each switch of the page's panel named (its checkbox
// #toggle-ACTION: specular, shadows, ...) is clicked, the frame it draws written to
// OUT/NAME.ACTION.png (cmake/check_web_toggles.cmake compares it with rt render's), and clicked
// again, which must draw the first frame exactly; `moves` and `ortho` move the camera with the
// mouse (and P) and write the frame and the camera W shows; `mode-NAME` chooses that mode in the
// panel's menu; `reference` checks the CPU render button's difference and the frame time
// (runActions).
// A console error, an uncaught exception, a WebGL error or any request beyond the page's own
// file fails the page (exit 1). A browser
// without WebGL2 prints one "SKIPPED: ..." line naming its renderer and exits 0.
'use strict';
const fs = require('fs');
const path = require('path');
const http = require('http');
const puppeteer = require('puppeteer-core');

const kChromium = process.env.RT_CHROMIUM || '/usr/bin/chromium';
const kTimeoutMs = 100000;  // the slowest page compiles and draws in a few seconds

function writePng(file, url) {
  fs.writeFileSync(file, Buffer.from(url.replace(/^data:image\/png;base64,/, ''), 'base64'));
}

// The camera moved as a lecturer would (drag to orbit, right drag to pan, the wheel to zoom, P
// for `ortho`), then W: writes the frame and the camera the page shows for the scene file, and
// R must bring the first frame back.
async function moveCamera(page, name, action, out) {
  await page.$eval('#live', (e) => e.scrollIntoView());
  const box = await (await page.$('#live')).boundingBox();
  const x = box.x + box.width / 2, y = box.y + box.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + 40, y + 10, { steps: 4 });
  await page.mouse.up();
  await page.mouse.down({ button: 'right' });
  await page.mouse.move(x + 60, y - 20, { steps: 4 });
  await page.mouse.up({ button: 'right' });
  await page.mouse.wheel({ deltaY: -100 });
  await page.mouse.wheel({ deltaY: -100 });
  if (action === 'ortho') await page.keyboard.press('p');
  await page.keyboard.press('w');
  await new Promise((r) => setTimeout(r, 300));  // the moves' frames are drawn at the next paint
  writePng(path.join(out, name + '.' + action + '.png'), await page.evaluate(() => window.__rtFrame()));
  fs.writeFileSync(path.join(out, name + '.' + action + '.camera.json'),
    await page.$eval('#camera-json', (e) => e.textContent));
  await page.keyboard.press('r');
  return await page.evaluate(() => window.__rtFrame() === window.__rtPixels)
    ? [] : ['R after the moves does not draw the first frame again'];
}

// The CPU render button: the difference of the unmoved first frame from it must be near black,
// and the frame time must show.
async function checkReference(page) {
  await page.click('#compare');
  await page.waitForFunction(() => document.getElementById('reference').complete, { timeout: 10000 });
  await new Promise((r) => setTimeout(r, 200));
  const r = await page.evaluate(() => {
    const c = document.getElementById('difference');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let sum = 0, n = 0;
    for (let i = 0; i < d.length; i += 4) { sum += d[i] + d[i + 1] + d[i + 2]; n += 3; }
    return { mean: sum / n, shown: !document.getElementById('difference-figure').hidden,
      time: document.getElementById('frame-time').textContent };
  });
  console.log(`  CPU render shown: ${r.shown}, mean |difference| x 8 ${r.mean.toFixed(3)}; ${r.time}`);
  const problems = [];
  if (!r.shown || !(r.mean < 1)) problems.push('the CPU render\'s difference is not near black');
  if (!/frame \d+: [\d.]+ ms/.test(r.time)) problems.push('no frame time shown');
  return problems;
}

// `mode-NAME`: the panel's mode menu set to NAME, the frame written, and the first mode chosen
// again, which must draw the first frame exactly.
async function switchMode(page, name, action, out, first) {
  const initial = await page.$eval('#mode', (e) => e.value);
  const chosen = await page.select('#mode', action.slice('mode-'.length));
  if (chosen.length === 0) return ['the page has no mode "' + action.slice(5) + '" to choose'];
  writePng(path.join(out, name + '.' + action + '.png'), await page.evaluate(() => window.__rtFrame()));
  await page.select('#mode', initial);
  if (await page.evaluate(() => window.__rtFrame()) !== first)
    return ['choosing the mode ' + initial + ' again does not draw the first frame again'];
  return [];
}

// Each action: a switch is clicked, its frame written, and clicked back, which must draw the
// first frame exactly; `moves` and `ortho` move the camera; `reference` checks the CPU render.
async function runActions(page, name, actions, out) {
  const problems = [];
  const first = await page.evaluate(() => window.__rtPixels);
  for (const s of actions) {
    if (s === 'moves' || s === 'ortho') { problems.push(...await moveCamera(page, name, s, out)); continue; }
    if (s === 'reference') { problems.push(...await checkReference(page)); continue; }
    if (s.startsWith('mode-')) { problems.push(...await switchMode(page, name, s, out, first)); continue; }
    const box = await page.$('#toggle-' + s);
    if (!box || await page.evaluate((b) => b.disabled, box)) {
      problems.push('the page has no switch "' + s + '" to click');
      continue;
    }
    await box.click();
    writePng(path.join(out, name + '.' + s + '.png'), await page.evaluate(() => window.__rtFrame()));
    await box.click();
    if (await page.evaluate(() => window.__rtFrame()) !== first)
      problems.push('switching ' + s + ' back does not draw the first frame again');
  }
  return problems;
}

// A static web server of the given files (GET by name, text/html, nothing else: 404), on a free
// port of 127.0.0.1; resolves to the server and its base URL.
function serveFiles(files) {
  const byName = new Map(files.map((f) => [encodeURIComponent(path.basename(f)), f]));
  const server = http.createServer((request, response) => {
    const file = byName.get(request.url.slice(1));
    if (request.method !== 'GET' || !file) {
      response.writeHead(404);
      return response.end();
    }
    response.writeHead(200, { 'Content-Type': 'text/html; charset=utf-8' });
    response.end(fs.readFileSync(file));
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1',
    () => resolve({ server: server, base: 'http://127.0.0.1:' + server.address().port + '/' })));
}

async function renderPage(browser, argument, out, base) {
  const [file, switchList] = argument.split('@');
  const switches = switchList ? switchList.split(',') : [];
  const problems = [];
  const page = await browser.newPage();
  await page.setViewport({ width: 1600, height: 1200 });  // the canvas and the panel in view
  page.on('console', (m) => { if (m.type() === 'error') problems.push('console: ' + m.text()); });
  page.on('pageerror', (e) => problems.push('uncaught: ' + e.message));
  // Self-contained: the page's own file and data: URLs only.
  const own = base ? base + encodeURIComponent(path.basename(file)) : 'file://' + path.resolve(file);
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
      problems.push(...await runActions(page, name, switches, out));
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
  const args = process.argv.slice(2);
  const overHttp = args[0] === '--http';
  const [out, ...files] = overHttp ? args.slice(1) : args;
  if (!out || files.length === 0)
    throw new Error('usage: node render_pages.js [--http] OUT PAGE.html...');
  const served = overHttp ? await serveFiles(files.map((f) => f.split('@')[0])) : null;
  fs.mkdirSync(out, { recursive: true });
  const browser = await puppeteer.launch({
    executablePath: kChromium,
    headless: 'new',
    args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox'],
  });
  let failed = 0;
  try {
    for (const file of files) {
      const r = await renderPage(browser, file, out, served && served.base);
      if (r.skip) { console.log(r.skip); return 0; }
      const verdict = r.problems.length ? 'FAILED' : 'drawn';
      console.log(`${r.name}: ${verdict} in ${r.seconds} s on ${r.renderer}`);
      for (const p of r.problems) console.log('  ' + p);
      if (r.problems.length) ++failed;
    }
  } finally {
    await browser.close();
    if (served) served.server.close();
  }
  return failed ? 1 : 0;
}

main().then((code) => process.exit(code), (e) => {
  console.log('render_pages: ' + e.message);
  process.exit(1);
});
