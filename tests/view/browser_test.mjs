// The browser test of `tailor view` (issue 16), run by ctest as `view.browser`:
//  1. a short `tailor simulate` run (plus the contact fixture when the run wrote no
//     contacts_NNNN.json), written out by `tailor view`, opened from file:// in headless
//     Chromium: no console errors; cloth and arm on screen; red candidate triangles,
//     colliding primitives, observers where the data has them, gone when toggled off;
//     moving the slider changes the picture; served over HTTP it loads as well;
//  2. one detected step (`tailor generate` + `tailor detect --json` + `tailor view
//     --detect`): the cloth and its red candidate triangles on screen.
// Exit 0: all passed; 1: a check failed; 77: skipped (no Chromium or node packages).
//
// node tests/view/browser_test.mjs --tailor build/release/tailor --work DIR
//   [--sim DIR]           use this `tailor simulate` output instead of running one
//   [--frames N]          frames to simulate (default 8; 4 with TAILOR_SANITIZED=1)
//   [--no-fixture]        never write the contact fixture (test the run's own contact files)
//   [--expect-red]        fail unless some frame shows red candidate triangles (on by
//                         default when the output has contact files)
//   [--screenshot FILE]   save a screenshot of the simulation page
//   [--keep]              keep DIR afterwards

import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, rmSync } from 'node:fs';
import { createServer } from 'node:http';
import { extname, join, resolve } from 'node:path';
import { writeContactsFixture } from './contacts_fixture.mjs';
import { findChromium, launchChromium, loadPuppeteer, openViewer } from './viewer_browser.mjs';

const argv = process.argv.slice(2);
const flag = (name) => argv.includes(name);
const option = (name, fallback) => {
  const i = argv.indexOf(name);
  return i >= 0 && i + 1 < argv.length ? argv[i + 1] : fallback;
};
const tailor = resolve(option('--tailor', 'build/release/tailor'));
const work = resolve(option('--work', 'build/view-browser-test'));
const started = Date.now();
// Under the sanitizers (TAILOR_SANITIZED=1) tailor runs several times slower: smaller runs.
const sanitized = process.env.TAILOR_SANITIZED === '1';

const chromium = findChromium();
const puppeteer = await loadPuppeteer();
if (!chromium || !puppeteer) {
  console.log(`view.browser skipped: ${!chromium ? 'Chromium is not installed (apt-get install chromium)'
    : 'puppeteer-core is missing (npm ci in web/)'}; scripts/install-deps.sh installs both`);
  process.exit(77);
}

let passed = 0, failed = 0;
function check(ok, what, detail = '') {
  if (ok) ++passed;
  else ++failed;
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}${detail ? `: ${detail}` : ''}`);
  return ok;
}
function run(args) {
  return execFileSync(tailor, args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}
const pageUrl = (output) => {
  const match = output.match(/^open (file:\/\/\S+)$/m);
  if (!match) throw new Error(`tailor view printed no page to open:\n${output}`);
  return match[1];
};

// Pixels that differ between two pictures (RGB distance above 24).
function changedPixels(a, b) {
  let changed = 0;
  for (let i = 0; i < a.length; i += 4) {
    const d = Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]);
    if (d > 24) ++changed;
  }
  return changed;
}
const picture = (page) => page.evaluate(() => Array.from(window.tailorViewer.picture().pixels));
const counts = (page) => page.evaluate(() => window.tailorViewer.pixelCounts());
const show = (page, name, on) =>
  page.evaluate((n, o) => window.tailorViewer.setVisible(n, o), name, on);
const setFrame = (page, k) => page.evaluate((f) => window.tailorViewer.setFrame(f), k);

// A static file server on the loopback interface, for the http:// check.
function serve(root) {
  const types = { '.html': 'text/html', '.js': 'text/javascript' };
  const server = createServer((request, response) => {
    const path = join(root, decodeURIComponent(new URL(request.url, 'http://x').pathname));
    if (!path.startsWith(root) || !existsSync(path)) {
      response.writeHead(404).end();
      return;
    }
    const file = path.endsWith('/') ? join(path, 'index.html') : path;
    response.writeHead(200, { 'content-type': types[extname(file)] || 'application/octet-stream' });
    response.end(readFileSync(file));
  });
  return new Promise((ready) => server.listen(0, '127.0.0.1', () => ready(server)));
}

async function simulationChecks(browser) {
  let sim = option('--sim', null);
  if (!sim) {
    sim = join(work, 'sim');
    // Tang's preset (no radial view): candidate triangles from the first frames on; the
    // paper preset culls every candidate until the elbow bends (frame ~22).
    run(['simulate', '--frames', option('--frames', sanitized ? '4' : '8'), '--method', 'tang',
      '--out', sim]);
  }
  sim = resolve(sim);
  // The fixture puts collisions and an observer in every frame; a real run may have none.
  let fixture = false;
  if (!flag('--no-fixture') && !existsSync(join(sim, 'contacts_0001.json'))) {
    fixture = true;
    const frames = writeContactsFixture(sim);
    console.log(`     (no contacts_NNNN.json in ${sim}: wrote the test fixture for ${frames} frames)`);
  }
  const expectContacts = existsSync(join(sim, 'contacts_0001.json'));
  const expectRed = flag('--expect-red') || expectContacts;
  const output = run(['view', sim]);
  const { page, errors } = await openViewer(browser, pageUrl(output));
  const scene = await page.evaluate(() => window.tailorViewer.scene);
  check(scene.frames >= 2 && scene.hasArm, 'simulation page loaded from file://',
    `${scene.frames} frames`);

  await show(page, 'candidates', false);
  await show(page, 'collisions', false);
  await show(page, 'observers', false);
  const first = await counts(page);
  check(first.cloth > 5000, 'cloth on screen (blue pixels)', `${first.cloth}`);
  check(first.arm > 200, 'arm on screen (skin pixels)', `${first.arm}`);
  check(first.background > 0.3 * first.total, 'background around them', `${first.background}`);

  // The slider: keyboard on the range input, as a person would move it.
  const before = await picture(page);
  await page.focus('#frame');
  await page.keyboard.press('End');
  const last = scene.frames - 1;
  await page.evaluate((k) => window.tailorViewer.whenShown(k), last);
  check(await page.evaluate(() => window.tailorViewer.frame()) === last,
    'the slider moved to the last frame', `frame ${last}`);
  const moved = changedPixels(before, await picture(page));
  check(moved > 500, 'moving the slider changes the picture (overlays off)', `${moved} pixels changed`);

  // Play for a moment, then pause: frames keep coming while playing, and stop after.
  const shownCount = () => page.evaluate(() => window.tailorViewer.framesShown);
  const beforePlay = await shownCount();
  await page.click('#play');
  await page.waitForFunction((n) => window.tailorViewer.framesShown >= n + 3, { polling: 50, timeout: 30_000 },
    beforePlay).catch((error) => console.log(`     (waiting for playback: ${error.message})`));
  await page.click('#play');
  const played = (await shownCount()) - beforePlay;
  check(played >= 3, 'play advances the frames', `${played} frames shown`);
  await new Promise((done) => setTimeout(done, 400));
  const afterPause = (await shownCount()) - beforePlay;
  check(afterPause <= played + 1, 'pause stops it', `${played} frames, 400 ms later ${afterPause}`);

  if (expectRed) {
    await show(page, 'candidates', true);
    let best = { frame: -1, red: 0 };
    for (let k = 1; k < scene.frames; ++k) {
      await setFrame(page, k);
      const red = (await counts(page)).red;
      if (red > best.red) best = { frame: k, red };
    }
    check(best.red > 200, 'red candidate triangles on screen', `${best.red} pixels at frame ${best.frame}`);
    await setFrame(page, Math.max(best.frame, 1));
    await show(page, 'candidates', false);
    check((await counts(page)).red === 0, 'no red with the candidate toggle off');
    await setFrame(page, 0);
    await show(page, 'candidates', true);
    check((await counts(page)).red === 0, 'no red at frame 0 (no step ends there)');
  }
  if (fixture) {
    await setFrame(page, 1);
    await show(page, 'collisions', true);
    await show(page, 'observers', true);
    const on = await counts(page);
    check(on.yellow > 20 && on.magenta > 10, 'colliding faces and contact points drawn',
      `${on.yellow} yellow, ${on.magenta} magenta pixels`);
    check(on.cyan > 20, 'observers drawn', `${on.cyan} cyan pixels`);
    await show(page, 'collisions', false);
    await show(page, 'observers', false);
    const off = await counts(page);
    check(off.yellow === 0 && off.magenta === 0 && off.cyan === 0,
      'no collision or observer marks with their toggles off');
  }
  if (await page.evaluate(() => window.tailorViewer.scene.hasClusters)) {
    await show(page, 'candidates', false);
    const plain = await counts(page);
    await show(page, 'clusters', true);
    const coloured = await counts(page);
    check(coloured.cloth < 0.8 * plain.cloth, 'clusters recolour the cloth',
      `blue pixels ${plain.cloth} -> ${coloured.cloth}`);
    await show(page, 'clusters', false);
  }
  const screenshot = option('--screenshot', null);
  if (screenshot) {
    await setFrame(page, last);
    await show(page, 'candidates', true);
    await page.screenshot({ path: screenshot });
  }
  check(errors.length === 0, 'no console errors (file://)', errors.join(' | '));
  await page.close();

  const root = resolve(sim, 'view');
  const server = await serve(root);
  const url = `http://127.0.0.1:${server.address().port}/index.html`;
  const served = await openViewer(browser, url);
  const httpCounts = await counts(served.page);
  check(httpCounts.cloth > 5000 && served.errors.length === 0, 'the page works over HTTP too',
    served.errors.join(' | ') || `${httpCounts.cloth} cloth pixels`);
  await served.page.close();
  server.close();
}

async function detectionChecks(browser) {
  const step = join(work, 'step');
  run(['generate', 'folded-cloth', '--triangles', sanitized ? '2000' : '4000', '--out', step]);
  const t0 = join(step, 't0.ply'), t1 = join(step, 't1.ply'), json = join(step, 'detect.json');
  run(['detect', t0, t1, '--json', json]);
  const { page, errors } = await openViewer(browser, pageUrl(run(['view', '--detect', json, t0, t1])));
  await setFrame(page, 1);
  const summary = await page.evaluate(() => document.getElementById('contacts-summary').textContent);
  const candidates = Number((summary.match(/^(\d+) candidate/) || [0, -1])[1]);
  check(candidates > 0, 'detected step: the culling found candidate triangles', summary);
  const red = (await counts(page)).red;
  await show(page, 'candidates', false);
  await show(page, 'collisions', false);
  const plain = await counts(page);
  check(plain.cloth > 5000 && red > 100 && plain.red === 0,
    'detected step: cloth, and red triangles when toggled on',
    `${plain.cloth} blue pixels; ${red} red on, ${plain.red} off`);
  check(errors.length === 0, 'detected step: no console errors', errors.join(' | '));
  await page.close();
}

rmSync(work, { recursive: true, force: true });
mkdirSync(work, { recursive: true });
const { browser, close } = await launchChromium(puppeteer, chromium);
try {
  await simulationChecks(browser);
  await detectionChecks(browser);
} catch (error) {
  check(false, 'the test ran to the end', error.stack || String(error));
} finally {
  await close();
}
if (!flag('--keep') && failed === 0) rmSync(work, { recursive: true, force: true });
console.log(`view.browser: ${((Date.now() - started) / 1000).toFixed(1)} s`);
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
