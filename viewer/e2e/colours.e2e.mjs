// End-to-end checks of the viewer's colourings (docs/viewer.md, "Colourings"): pages written with
// `datomsim view --loads` and of a run with --actuators, opened from disk in headless Chromium.
//
//   node viewer/e2e/colours.e2e.mjs --datomsim build/release/bin/datomsim [--shots DIR] [--viewer-js FILE]
//
// Prints one line per check and `N passed, M failed`; exits non-zero on a failure.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { launchBrowser } from './browser.mjs';
import { assert, check, commonOptions, finish, repository } from './harness.mjs';

const { datomsim, shots, givenBundle } = commonOptions();
if (!datomsim) {
  console.error('usage: node viewer/e2e/colours.e2e.mjs --datomsim PATH [--shots DIR] [--viewer-js FILE]');
  process.exit(2);
}

// Run in the repository with paths relative to it, so that a trace's description (and the page's
// title, in the pictures docs/ shows) names the scene as a user would.
function run(...args) {
  return execFileSync(resolve(datomsim), args, {
    cwd: repository,
    encoding: 'utf8',
    stdio: ['ignore', 'pipe', 'pipe'],
  });
}

const scratch = mkdtempSync(join(tmpdir(), 'datomsim-colours-'));
const scene = join('scenes', 'paper-arch-hole2.json');

// The pages: the scene at rest with weak latches (some overloaded), the paper's run with the
// scene's default loads, and the paper's run with actuators.
function makePages() {
  let bundle = givenBundle && resolve(givenBundle);
  if (!bundle) {
    bundle = join(scratch, 'viewer.bundle.js');
    execFileSync(process.execPath, [join(repository, 'viewer', 'build.mjs'), '--outfile', bundle], { stdio: 'ignore' });
  }
  const view = (...args) => run('view', ...args, '--viewer-js', bundle);
  const file = (name) => join(scratch, name);
  run('loads', scene, '--latch-moment', '2e-5', '--latch-force', '0.05', '--out', file('weak.json'));
  run('loads', scene, '--out', file('loads.json'));
  view(scene, '--loads', file('weak.json'), '-o', file('weak.html'));
  // The walkers' run starts from its scene as the file has it (follow-gradient moves a module to
  // its start first: the loads of the scene file are not those of its trace's start).
  const walkers = join('scenes', 'walkers.json');
  run('loads', walkers, '--out', file('walkers-loads.json'));
  run('run', walkers, '--program', 'walkers', '--trace', file('run.jsonl'));
  view(file('run.jsonl'), '--loads', file('walkers-loads.json'), '-o', file('run.html'));
  const runArgs = ['--program', 'follow-gradient', '--goal', '6,5,2', '--start', '0,0,2'];
  const actuators = ['--actuators', 'sma-spring+electrostatic', '--size', '1cm'];
  run('run', scene, ...runArgs, ...actuators, '--trace', file('act.jsonl'), '--out', file('act.json'));
  view(file('act.jsonl'), '-o', file('act.html'));
  const json = (name) => JSON.parse(readFileSync(file(name), 'utf8'));
  return { weak: json('weak.json'), loads: json('loads.json'), act: json('act.json'), file };
}

async function open(context, path, errors) {
  const page = await context.newPage();
  page.on('console', (message) => message.type() === 'error' && errors.push(message.text()));
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto(pathToFileURL(path).href, { timeout: 120000 });
  await page.waitForFunction(() => window.datomsimViewer && window.datomsimViewer.ready, null, { timeout: 30000 });
  return page;
}

async function shoot(page, name) {
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  return page.screenshot({ path: join(shots, `${name}.png`) });
}

// Pixels of a screenshot within `tolerance` of an sRGB colour, as a share of the picture.
async function shareNear(page, png, rgb, tolerance = 40) {
  return page.evaluate(
    async ([b64, target, tol]) => {
      const image = new Image();
      image.src = `data:image/png;base64,${b64}`;
      await image.decode();
      const canvas = document.createElement('canvas');
      [canvas.width, canvas.height] = [image.width, image.height];
      const context = canvas.getContext('2d');
      context.drawImage(image, 0, 0);
      const { data } = context.getImageData(0, 0, image.width, image.height - 100);
      let near = 0;
      for (let k = 0; k < data.length; k += 4) {
        const d = Math.abs(data[k] - target[0]) + Math.abs(data[k + 1] - target[1]) + Math.abs(data[k + 2] - target[2]);
        if (d <= tol) ++near;
      }
      return near / (data.length / 4);
    },
    [png.toString('base64'), rgb, tolerance],
  );
}

let pages;
await check('datomsim writes the pages (loads of the scene, a run, a run with actuators)', async () => {
  pages = makePages();
});

await check('view --loads refuses the loads of another scene, naming the file, and writes nothing', async () => {
  let message = '';
  try {
    // The paper's run starts with the goal's module moved to the start: another scene.
    run('view', pages.file('act.jsonl'), '--loads', pages.file('loads.json'), '-o', pages.file('refused.html'));
  } catch (error) {
    message = String(error.stderr);
  }
  assert(message.includes(`${pages.file('loads.json')}: the loads of another scene: its centre of mass`), `message: ${message}`);
  let written = true;
  try {
    readFileSync(pages.file('refused.html'));
  } catch {
    written = false;
  }
  assert(!written, 'a page was left behind');
});

const { context, close } = await launchBrowser();
const errors = [];
try {
  if (pages) {
    const weak = await open(context, pages.file('weak.html'), errors);
    await check('loads page: latches coloured by safety factor, the overloaded ones counted in the legend', async () => {
      let state = await weak.evaluate(() => window.datomsimViewer.colouring());
      assert(state.modes.join() === 'own,loads', `modes ${state.modes}`);
      await weak.evaluate(() => window.datomsimViewer.fit('top'));
      const own = await shoot(weak, 'colours-own-top');
      await weak.evaluate(() => window.datomsimViewer.setColouring('loads'));
      state = await weak.evaluate(() => window.datomsimViewer.colouring());
      const fragment = await weak.evaluate(() => window.datomsimViewer.fragment());
      assert(fragment.includes('colours=loads'), `the address ${fragment} names the colouring`);
      const counted = state.latches.byBand.reduce((a, b) => a + b, 0) + state.latches.stale;
      assert(counted === pages.weak.latches, `${counted} latches coloured, the scene has ${pages.weak.latches}`);
      assert(state.latches.stale === 0, 'nothing moved in a scene at rest');
      assert(state.latches.overloaded.length === pages.weak.overloaded && pages.weak.overloaded > 0,
        `${state.latches.overloaded.length} overloaded shown, loads says ${pages.weak.overloaded}`);
      assert(state.legend.includes('latch safety factor') && state.legend.includes(`${pages.weak.overloaded} overloaded`),
        `legend: ${state.legend}`);
      const loads = await shoot(weak, 'colours-loads-top');
      // The overloaded band's red is on the latches; the bodies are grey, so more of it than
      // the red connectors of the modules' own colours would not show in loads mode without it.
      const [redOwn, redLoads] = [await shareNear(weak, own, [200, 0, 0]), await shareNear(weak, loads, [200, 0, 0])];
      assert(redLoads > 0.0005, `overloaded red covers ${redLoads} of the picture`);
      const grey = await shareNear(weak, loads, [188, 192, 200], 60);
      assert(grey > 0.02, `the grey bodies cover ${grey}`);
      console.log(`  red share: own colours ${redOwn.toFixed(4)}, loads ${redLoads.toFixed(4)}`);
      await weak.evaluate(() => window.datomsimViewer.fit('3d'));
      await shoot(weak, 'colours-loads-3d');
    });
    await check('loads page: a click on a module gives its latches\' loads in the panel', async () => {
      const worst = pages.weak.loads[pages.weak.most_loaded[0]];
      await weak.evaluate((id) => window.datomsimViewer.selectId(id), worst.a);
      const text = await weak.evaluate(() => window.datomsimViewer.selectedInfo());
      assert(text.includes(`\u2192 ${worst.b}: F`) && text.includes(`safety ${Number(worst.safety.toPrecision(3))}`), `panel: ${text}`);
      await weak.evaluate(() => window.datomsimViewer.selectId(-1));
    });
    await weak.close();

    const runPage = await open(context, pages.file('run.html'), errors);
    await check('run page with loads: the start\'s loads hold at the start, go stale where modules moved', async () => {
      await runPage.evaluate(() => window.datomsimViewer.setColouring('loads'));
      const start = await runPage.evaluate(() => window.datomsimViewer.colouring());
      // The walkers start moving at time 0: only their latches may be stale then.
      const moving = await runPage.evaluate(() => window.datomsimViewer.motionsInFlight().length);
      assert(start.latches.stale <= 2 * 12 * moving, `${start.latches.stale} stale at the start, ${moving} moving`);
      const duration = await runPage.evaluate(() => window.datomsimViewer.duration);
      await runPage.evaluate((t) => window.datomsimViewer.seek(t), duration);
      const end = await runPage.evaluate(() => window.datomsimViewer.colouring());
      assert(end.latches.stale > start.latches.stale, `${end.latches.stale} stale at the end, ${start.latches.stale} at the start`);
      assert(end.legend.includes(`moved since the start: ${end.latches.stale}`), `legend: ${end.legend}`);
    });
    await runPage.close();

    const act = await open(context, pages.file('act.html'), errors);
    await check('actuated run: modules coloured by energy spent, the run\'s own figures at the end', async () => {
      const state = await act.evaluate(() => window.datomsimViewer.colouring());
      assert(state.modes.join() === 'own,energy', `modes ${state.modes}`);
      await act.evaluate(() => window.datomsimViewer.setColouring('energy'));
      const duration = await act.evaluate(() => window.datomsimViewer.duration);
      await act.evaluate(() => window.datomsimViewer.seek(0));
      const atStart = await act.evaluate(() => window.datomsimViewer.colouring());
      assert(Math.max(...atStart.spent) === 0, 'nothing spent at time 0');
      await act.evaluate(() => window.datomsimViewer.fit('3d'));
      const before = await shoot(act, 'colours-energy-start');
      await act.evaluate((t) => window.datomsimViewer.seek(t), duration);
      const atEnd = await act.evaluate(() => window.datomsimViewer.colouring());
      const ids = await act.evaluate(() => window.datomsimViewer.modules().map((m) => m.id));
      let worst = 0;
      for (const m of pages.act.energy.modules) {
        const shown = atEnd.spent[ids.indexOf(m.id)];
        worst = Math.max(worst, Math.abs(shown - m.total_J) / Math.max(m.total_J, 1e-12));
      }
      assert(worst < 1e-4, `per module, ${worst} relative difference from run --out's energy`);
      assert(atEnd.legend.includes('energy spent'), `legend: ${atEnd.legend}`);
      const after = await shoot(act, 'colours-energy-end');
      const dark = await shareNear(act, after, [190, 40, 60], 80);
      const darkBefore = await shareNear(act, before, [190, 40, 60], 80);
      assert(dark > darkBefore, `the modules that spent most darken: ${darkBefore} -> ${dark}`);
      await act.evaluate((t) => window.datomsimViewer.seek(t), duration * 0.6);
      await shoot(act, 'colours-energy-middle');
      console.log(`  worst relative difference ${worst.toExponential(2)}, ${pages.act.energy.total_J} J in all`);
    });
    await act.close();
  }
  await check('no console error', async () => assert(errors.length === 0, errors.join(' | ')));
} finally {
  await close();
  rmSync(scratch, { recursive: true, force: true });
}
finish();
