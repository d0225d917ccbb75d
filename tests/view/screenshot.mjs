// A screenshot of a page written by `tailor view` (e.g. docs/viewer.png), in headless Chromium.
//
//   node tests/view/screenshot.mjs DIR/view/index.html OUT.png [--frame K] [--size 960x600]

import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { findChromium, launchChromium, loadPuppeteer, openViewer } from './viewer_browser.mjs';

const argv = process.argv.slice(2);
const option = (name, fallback) => {
  const i = argv.indexOf(name);
  return i >= 0 && i + 1 < argv.length ? argv[i + 1] : fallback;
};
const [width, height] = option('--size', '960x600').split('x').map(Number);
const { browser, close } = await launchChromium(await loadPuppeteer(), findChromium());
try {
  // Multisampled even in software: a picture, not a frame rate.
  const url = `${pathToFileURL(resolve(argv[0])).href}?antialias=1`;
  const { page, errors } = await openViewer(browser, url);
  await page.setViewport({ width, height });
  await page.evaluate((k) => window.tailorViewer.setFrame(k), Number(option('--frame', '0')));
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  await page.screenshot({ path: argv[1] });
  if (errors.length > 0) throw new Error(errors.join('\n'));
} finally {
  await close();
}
