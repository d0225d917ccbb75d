// Headless Chromium for the viewer's browser test and measurements: finds Debian's
// chromium, loads puppeteer-core from web/node_modules (pinned by web/package-lock.json),
// opens a page written by `tailor view` and records every console error.

import { existsSync, mkdtempSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

export const repoRoot = join(dirname(fileURLToPath(import.meta.url)), '..', '..');

/** Path of a Chromium executable, or null: $CHROMIUM, then the Debian package's. */
export function findChromium() {
  for (const candidate of [process.env.CHROMIUM, '/usr/bin/chromium', '/usr/bin/chromium-browser']) {
    if (candidate && existsSync(candidate)) return candidate;
  }
  return null;
}

/** puppeteer-core from web/node_modules, or null if `npm ci` has not run there. */
export async function loadPuppeteer() {
  const require = createRequire(join(repoRoot, 'web', 'package.json'));
  let entry;
  try {
    entry = require.resolve('puppeteer-core');
  } catch {
    return null;
  }
  const module = await import(pathToFileURL(entry).href);
  return module.default ?? module;
}

/**
 * Launches headless Chromium with a fresh profile. As root the sandbox must be off; the
 * background-networking switches keep it from stalling on refused connections (there is
 * no network); SwiftShader draws WebGL on the CPU (--disable-gpu, no GPU here).
 */
export async function launchChromium(puppeteer, executablePath) {
  const profile = mkdtempSync(join(tmpdir(), 'tailor-view-chromium-'));
  const browser = await puppeteer.launch({
    executablePath,
    headless: true,
    userDataDir: profile,
    args: [
      '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--enable-unsafe-swiftshader', '--use-angle=swiftshader',
    ],
    defaultViewport: { width: 1280, height: 800 },
    protocolTimeout: 180_000,
  });
  const close = async () => {
    await browser.close();
    rmSync(profile, { recursive: true, force: true });
  };
  return { browser, close };
}

/**
 * Opens `url` in a new tab and waits until the viewer says it is ready (or failed).
 * Returns the page and the list that collects console errors, page errors and failed
 * requests from then on.
 */
export async function openViewer(browser, url, timeoutMs = 90_000) {
  const page = await browser.newPage();
  const errors = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(`console: ${message.text()}`);
  });
  page.on('pageerror', (error) => errors.push(`page error: ${error.message}`));
  page.on('requestfailed', (request) =>
    errors.push(`request failed: ${request.url()} (${request.failure()?.errorText})`));
  await page.goto(url, { waitUntil: 'load', timeout: timeoutMs });
  await page.waitForFunction(
    () => window.tailorViewer && (window.tailorViewer.ready || window.tailorViewer.error),
    { timeout: timeoutMs, polling: 100 });
  const error = await page.evaluate(() => window.tailorViewer.error);
  if (error) errors.push(`viewer error: ${error}`);
  return { page, errors };
}
