// A screenshot of a page written by `rt export-web`, for docs/viewer.md: the page opened in
// headless Chromium (SwiftShader's WebGL2, as render_pages.js), each ELEMENT clicked in turn
// (a CSS selector: #compare shows the CPU render, #toggle-specular switches specular off ...),
// then the whole page written as a PNG.
//   node screenshot_page.js PAGE.html OUT.png [ELEMENT...]
'use strict';
const path = require('path');
const puppeteer = require('puppeteer-core');

async function main() {
  const [file, out, ...clicks] = process.argv.slice(2);
  if (!file || !out) throw new Error('usage: node screenshot_page.js PAGE.html OUT.png [ELEMENT...]');
  const browser = await puppeteer.launch({
    executablePath: process.env.RT_CHROMIUM || '/usr/bin/chromium',
    headless: 'new',
    args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox'],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({ width: 1040, height: 600 });
    await page.goto('file://' + path.resolve(file));
    await page.waitForFunction(() => window.__rtDone !== undefined, { timeout: 100000 });
    const done = await page.evaluate(() => window.__rtDone);
    if (!done.ok) throw new Error('the page did not draw: ' + JSON.stringify(done));
    for (const selector of clicks) await page.click(selector);
    await new Promise((r) => setTimeout(r, 500));  // the CPU render's image loads
    await page.screenshot({ path: out, fullPage: true });
  } finally {
    await browser.close();
  }
}

main().catch((e) => {
  console.log('screenshot_page: ' + e.message);
  process.exit(1);
});
