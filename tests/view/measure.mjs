// Load time and frame rate of a page written by `tailor view`, in headless Chromium
// (software WebGL: SwiftShader on the CPU, so the figures are far below a laptop GPU's).
//
//   node tests/view/measure.mjs DIR/view/index.html [--renders 20] [--seconds 5]
//                               [--frame K] [--hide candidates,collisions,...] [--antialias 0|1]
//
// Prints: the size of the folder; the time from navigation to the scene data decoded and
// to the first frame on screen; the time to show another, not yet loaded frame; the mean
// time of one render over back-to-back renders while orbiting (finished by a pixel
// read-back); the frames per second of an orbit paced by requestAnimationFrame.

import { readdirSync, statSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { findChromium, launchChromium, loadPuppeteer, openViewer } from './viewer_browser.mjs';

const argv = process.argv.slice(2);
const option = (name, fallback) => {
  const i = argv.indexOf(name);
  return i >= 0 && i + 1 < argv.length ? argv[i + 1] : fallback;
};
const page = resolve(argv[0] || '');
const folderBytes = (dir) => readdirSync(dir).reduce((sum, name) => {
  const path = join(dir, name);
  const stat = statSync(path);
  return sum + (stat.isDirectory() ? folderBytes(path) : stat.size);
}, 0);

const { browser, close } = await launchChromium(await loadPuppeteer(), findChromium());
try {
  const { page: tab, errors } = await openViewer(browser, pathToFileURL(page).href + (option('--antialias', null) ? `?antialias=${option('--antialias')}` : ''), 600_000);
  const info = await tab.evaluate(() => ({ ...window.tailorViewer.timing, ...window.tailorViewer.scene,
    renderer: window.tailorViewer.renderer }));
  const other = Number(option('--frame', Math.max(1, Math.floor(info.frames / 2))));
  await tab.evaluate((k) => window.tailorViewer.setFrame(k), other);
  const frameMs = await tab.evaluate(() => window.tailorViewer.timing.lastFrameMs);
  const hidden = option('--hide', '').split(',').filter((name) => name);
  for (const name of hidden) await tab.evaluate((n) => window.tailorViewer.setVisible(n, false), name);
  const bench = await tab.evaluate((n, s) => window.tailorViewer.benchmark(n, s),
    Number(option('--renders', '20')), Number(option('--seconds', '5')));
  console.log(JSON.stringify({
    page,
    folder_mb: +(folderBytes(dirname(page)) / 1e6).toFixed(1),
    frames: info.frames,
    cloth_faces: info.clothFaces,
    scene_loaded_ms: Math.round(info.sceneLoadedMs),
    first_frame_ms: Math.round(info.firstFrameMs),
    show_frame_ms: Math.round(frameMs),
    shown_frame: other,
    hidden,
    renderer: info.renderer,
    render_ms_mean: +bench.renderMs.toFixed(1),
    raf_fps: +bench.rafFps.toFixed(1),
    errors,
  }, null, 1));
} finally {
  await close();
}
