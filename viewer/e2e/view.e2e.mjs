// End-to-end test of the viewer: the datomsim binary writes the pages of the paper's runs, and
// headless Chromium opens them from disk (file://, no server, no network).
//
//   node e2e/view.e2e.mjs --datomsim PATH [--shots DIR]     (or DATOMSIM=PATH, DATOMSIM_SHOTS=DIR)
//
// For each page: no console error, no request leaves the file, the canvas is drawn (the
// screenshot is not blank), stepping changes the picture, seeking is deterministic, a click on a
// module shows its panel, and playing at speed reaches the end of the run with the mobile at the
// goal. Screenshots go to DIR (default /tmp/viewer-shots). Ends with "N passed, M failed".
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readdirSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { launchBrowser } from './browser.mjs';

const repository = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');
const GOAL = [6, 5, 2];
const START = [0, 0, 2];

function option(name, fallback) {
  const k = process.argv.indexOf(name);
  return k >= 0 && k + 1 < process.argv.length ? process.argv[k + 1] : fallback;
}

const datomsim = option('--datomsim', process.env.DATOMSIM);
const shots = resolve(option('--shots', process.env.DATOMSIM_SHOTS || '/tmp/viewer-shots'));
if (!datomsim || !existsSync(datomsim)) {
  console.error('view.e2e: give the datomsim binary: --datomsim PATH or DATOMSIM=PATH');
  process.exit(2);
}
mkdirSync(shots, { recursive: true });

let passed = 0;
let failed = 0;
async function check(name, body) {
  try {
    await body();
    ++passed;
    console.log(`ok - ${name}`);
  } catch (error) {
    ++failed;
    console.log(`not ok - ${name}\n  ${String(error.stack || error).split('\n').join('\n  ')}`);
  }
}
function assert(condition, message) {
  if (!condition) throw new Error(message);
}

function run(...args) {
  return execFileSync(datomsim, args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}

// The pages: the demo's, when it writes viewers; else written with `datomsim view` from the
// demo's traces and `datomsim reach` maps. Plus a scene shown at rest.
function makePages(scratch) {
  const demo = join(scratch, 'demo');
  run('demo', '-o', demo);
  const pages = [];
  for (const hole of [2, 1]) {
    const name = `arch-hole${hole}`;
    const demoPage = readdirSync(demo).find((f) => f.startsWith(name) && f.endsWith('.html'));
    if (demoPage) {
      pages.push({ name, file: join(demo, demoPage), run: true, overlay: true });
      continue;
    }
    const scene = join(repository, 'scenes', `paper-${name}.json`);
    const reach = join(scratch, `${name}-reach.json`);
    run('reach', scene, '--goal', GOAL.join(','), '--start', START.join(','), '--out', reach);
    const file = join(scratch, `${name}.html`);
    run('view', join(demo, `${name}-trace.jsonl`), '--reach', reach, '-o', file);
    pages.push({ name, file, run: true, overlay: true });
  }
  const sceneFile = join(scratch, 'scene-hole1.html');
  run('view', join(repository, 'scenes', 'paper-arch-hole1.json'), '-o', sceneFile);
  pages.push({ name: 'scene-hole1', file: sceneFile, run: false, overlay: false });
  return pages;
}

// Statistics of a PNG screenshot, decoded by the browser: luminance variance and distinct colours
// of the 3D view (the control bar left out).
async function pictureStats(page, png) {
  return page.evaluate(async (b64) => {
    const image = new Image();
    image.src = `data:image/png;base64,${b64}`;
    await image.decode();
    const canvas = document.createElement('canvas');
    canvas.width = image.width;
    canvas.height = image.height;
    const context = canvas.getContext('2d');
    context.drawImage(image, 0, 0);
    const height = image.height - 60;
    const { data } = context.getImageData(0, 0, image.width, height);
    let sum = 0;
    let sum2 = 0;
    const colours = new Set();
    const n = data.length / 4;
    for (let k = 0; k < data.length; k += 4) {
      const y = 0.2126 * data[k] + 0.7152 * data[k + 1] + 0.0722 * data[k + 2];
      sum += y;
      sum2 += y * y;
      colours.add((data[k] << 16) | (data[k + 1] << 8) | data[k + 2]);
    }
    const mean = sum / n;
    return { variance: sum2 / n - mean * mean, colours: colours.size, width: image.width, height };
  }, png.toString('base64'));
}

// Fraction of pixels that differ between two PNG screenshots of the same size.
async function difference(page, a, b) {
  return page.evaluate(
    async ([pa, pb]) => {
      const load = async (b64) => {
        const image = new Image();
        image.src = `data:image/png;base64,${b64}`;
        await image.decode();
        const canvas = document.createElement('canvas');
        canvas.width = image.width;
        canvas.height = image.height;
        const context = canvas.getContext('2d');
        context.drawImage(image, 0, 0);
        return context.getImageData(0, 0, image.width, image.height - 60).data;
      };
      const [x, y] = [await load(pa), await load(pb)];
      let differ = 0;
      for (let k = 0; k < x.length; k += 4) {
        if (Math.abs(x[k] - y[k]) + Math.abs(x[k + 1] - y[k + 1]) + Math.abs(x[k + 2] - y[k + 2]) > 24) ++differ;
      }
      return differ / (x.length / 4);
    },
    [a.toString('base64'), b.toString('base64')],
  );
}

async function settle(page) {
  // Two animation frames: the picture of the last seek is on screen.
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
}

async function shoot(page, name) {
  await settle(page);
  return page.screenshot({ path: join(shots, `${name}.png`) });
}

function cellToWorld([x, y, z], s) {
  return [(x + 0.5 + z / 2) * s, (y + 0.5 + z / 2) * s, (Math.SQRT2 / 2) * (z + 0.5) * s];
}

async function testPage(context, spec) {
  const page = await context.newPage();
  const errors = [];
  const requests = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(error.message));
  page.on('request', (request) => {
    const url = request.url();
    if (!url.startsWith('file:') && !url.startsWith('data:') && !url.startsWith('blob:')) requests.push(url);
  });
  const name = spec.name;

  await check(`${name}: opens from disk and starts`, async () => {
    await page.goto(pathToFileURL(spec.file).href);
    await page.waitForFunction(() => window.datomsimViewer && window.datomsimViewer.ready, null, { timeout: 30000 });
  });
  if (!(await page.evaluate(() => Boolean(window.datomsimViewer)))) {
    await page.screenshot({ path: join(shots, `${name}-failed.png`) });
    console.log(`  console errors: ${errors.join(' | ')}`);
    await page.close();
    return;
  }

  let rest;
  await check(`${name}: the canvas is drawn (not blank)`, async () => {
    rest = await shoot(page, `${name}-rest`);
    const stats = await pictureStats(page, rest);
    assert(stats.variance > 100, `luminance variance ${stats.variance.toFixed(1)} is too low: blank picture`);
    assert(stats.colours > 500, `only ${stats.colours} colours: blank picture`);
  });

  if (spec.run) {
    const api = 'window.datomsimViewer';
    const duration = await page.evaluate(`${api}.duration`);

    await check(`${name}: stepping changes the picture`, async () => {
      const firstTurn = await page.evaluate(`${api}.changeTimes.find((t, k, all) => k > 0 && all[k - 1] > 0 && t - all[k - 1] >= 0.9)`);
      let steps = 0;
      let time = 0;
      while (time < firstTurn && steps < 60) {
        await page.keyboard.press('ArrowRight');
        time = await page.evaluate(`${api}.time()`);
        ++steps;
      }
      assert(time > 0, 'the right arrow did not step');
      const stepped = await shoot(page, `${name}-step`);
      const changed = await difference(page, rest, stepped);
      assert(changed > 0.002, `only ${(100 * changed).toFixed(3)} % of the pixels changed after ${steps} steps`);
      await page.keyboard.press('ArrowLeft');
      assert((await page.evaluate(`${api}.time()`)) < time, 'the left arrow did not step back');
    });

    await check(`${name}: seeking is deterministic`, async () => {
      const t = duration * 0.37;
      await page.evaluate(`${api}.seek(${t})`);
      const a = await shoot(page, `${name}-seek-a`);
      await page.evaluate(`${api}.seek(${duration * 0.9}); ${api}.seek(0.01); ${api}.seek(${t})`);
      const b = await shoot(page, `${name}-seek-b`);
      assert((await difference(page, a, b)) === 0, 'the same time shows two different pictures');
      rmSync(join(shots, `${name}-seek-a.png`));
      rmSync(join(shots, `${name}-seek-b.png`));
    });

    await check(`${name}: a motion at its middle, mobile on top of its pivot`, async () => {
      const middle = await page.evaluate(() => {
        const v = window.datomsimViewer;
        // The end of the first quarter turn: the first change time after a gap of a second.
        const times = v.changeTimes;
        for (let k = 1; k < times.length; ++k) if (times[k] - times[k - 1] >= 0.9 && times[k - 1] > 0) return times[k];
        return times[1];
      });
      await page.evaluate(`${api}.seek(${middle})`);
      const mobile = await page.evaluate(`${api}.modulePose(1)`);
      assert(mobile.piston >= 0 && mobile.fraction > 0.99, 'the mobile is not compressed at the middle');
      const [x, y, z] = mobile.position;
      // Close, from the side, the others faded (focus on the mobile), without the distance map.
      await page.evaluate(`${api}.setOverlay(false); ${api}.selectId(1); ${api}.setFocus(true)`);
      await page.evaluate(`${api}.camera([${x - 5.6}, ${y - 3.4}, ${z + 0.6}], [${x}, ${y}, ${z - 0.7}])`);
      await shoot(page, `${name}-motion-middle`);
      await page.evaluate(`${api}.setFocus(false); ${api}.selectId(-1); ${api}.setOverlay(true); ${api}.fit()`);
    });

    await check(`${name}: clicking a module shows its panel`, async () => {
      await page.evaluate(`${api}.seek(0)`);
      await settle(page);
      const point = await page.evaluate(`${api}.screenPositionOf(1)`);
      await page.mouse.click(point.x, point.y);
      const info = await page.evaluate(`${api}.selectedInfo()`);
      assert(info && /Datom 1/.test(info), `no panel for module 1 (got ${info})`);
      assert(/cell\s+0, 0, 2/.test(info), `the panel does not give the cell: ${info}`);
      assert(/latches/.test(info) && /orientation/.test(info) && /piston/.test(info), info);
      await page.keyboard.press('l');
      const labels = await page.evaluate(() => [...document.querySelectorAll('.dv-label')].filter((l) => l.style.display !== 'none').length);
      assert(labels >= 100, `only ${labels} labels shown`);
      await shoot(page, `${name}-panel-labels`);
      await page.keyboard.press('l');
      await page.keyboard.press('Escape');
    });

    if (spec.overlay) {
      await check(`${name}: the distance map and its path`, async () => {
        await page.evaluate(`${api}.seek(0); ${api}.fit('top')`);
        const top = await shoot(page, `${name}-distances-top`);
        const stats = await pictureStats(page, top);
        assert(stats.colours > 500, 'blank distance map');
        await page.evaluate(`${api}.fit()`);
        await shoot(page, `${name}-distances-3d`);
      });
    }

    await check(`${name}: plays the whole run to the goal`, async () => {
      await page.evaluate(`${api}.seek(0); ${api}.setSpeed(32); ${api}.play()`);
      await page.waitForFunction((d) => window.datomsimViewer.time() >= d, duration, { timeout: 120000, polling: 200 });
      const mobile = await page.evaluate(`${api}.modulePose(1)`);
      const goal = cellToWorld(GOAL, 2);
      const distance = Math.hypot(...mobile.position.map((p, k) => p - goal[k]));
      assert(distance < 1e-3, `the mobile ends ${distance} away from the goal`);
      await shoot(page, `${name}-end`);
    });
  }

  await check(`${name}: no console error and no request leaves the file`, async () => {
    assert(errors.length === 0, `console errors: ${errors.join(' | ')}`);
    assert(requests.length === 0, `requests: ${requests.join(' ')}`);
  });
  await page.close();
}

const scratch = mkdtempSync(join(tmpdir(), 'datomsim-e2e-'));
const { context, close } = await launchBrowser();
try {
  let pages = [];
  await check('datomsim writes the pages', async () => {
    pages = makePages(scratch);
  });
  for (const spec of pages) await testPage(context, spec);
} finally {
  await close();
  rmSync(scratch, { recursive: true, force: true });
}
console.log(`screenshots in ${shots}`);
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
