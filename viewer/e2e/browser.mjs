// Starting Debian's Chromium headless through playwright-core (no browser download: the
// executable is the system's), in a fresh profile directory that is removed on close.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { chromium } from 'playwright-core';

export const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';

// The pages' size: Chromium draws WebGL on the CPU here (SwiftShader), and the time of every
// frame follows its pixels: at 960 x 600 the three end-to-end scripts took 4 min instead of
// 5.5 at 1280 x 800, and every layout the checks look at (panels, captions, the strip) fits.
export const VIEWPORT = { width: 960, height: 600 };

// Returns {context, close}: a browser context of a headless Chromium with a fresh profile.
export async function launchBrowser({ viewport = VIEWPORT } = {}) {
  const profile = mkdtempSync(join(tmpdir(), 'datomsim-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    viewport,
    args: [
      '--headless',
      '--no-sandbox',
      '--disable-gpu',
      '--disable-quic',
      '--no-first-run',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
      // WebGL without a GPU: SwiftShader, which Chromium only allows when asked.
      '--enable-unsafe-swiftshader',
      '--use-angle=swiftshader',
    ],
  });
  const close = async () => {
    await context.close();
    rmSync(profile, { recursive: true, force: true });
  };
  return { context, close };
}
