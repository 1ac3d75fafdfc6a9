// End-to-end test of the viewer: the datomsim binary writes the pages of the paper's runs, and
// headless Chromium opens them from disk (file://, no server, no network).
//
//   node e2e/view.e2e.mjs --datomsim PATH [--shots DIR] [--viewer-js FILE]
//                                        (or DATOMSIM=PATH, DATOMSIM_SHOTS=DIR, DATOMSIM_VIEWER_JS=FILE)
//
// The pages carry the viewer built from viewer/src (build.mjs, into the scratch folder), or FILE,
// so that the test checks these sources whatever bundle lies next to the binary.
//
// For each page: no console error, no request leaves the file, the canvas is drawn (the
// screenshot is not blank). On the paper's runs: stepping changes the picture, seeking is
// deterministic, a click on a module shows its panel, and playing at speed reaches the end of the
// run with the mobile at the goal. On a run of 10 walkers moving at once: the concurrency strip's
// maximum is the run's max_concurrent_motions, at a time of many motions in flight as many module
// bodies are away from their cells, playing to a time and seeking to it give the same picture.
// On the same run with target shapes added to its header: the target cells are drawn and counted.
// With a distance map: its legend, captions that hide no module seen from the top, and an address
// that names the moment shown and opens there. On the demo's self-reconfiguration (the arch built from a layer on its box): the target is
// partly filled at the start and filled at the end, and its busiest time shows that many motions.
// On pages of 3D Catoms (the paper's run and its scene at rest, their header naming the Catom): one
// Catom per module in its cell and no Datom part, a Catom's panel, the run played to the goal.
// Screenshots go to DIR (default /tmp/viewer-shots). Ends with "N passed, M failed".
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { VIEWPORT, launchBrowser } from './browser.mjs';
import { assert, check, commonOptions, finish, repository } from './harness.mjs';

const GOAL = [6, 5, 2];
const START = [0, 0, 2];

const { datomsim, shots, givenBundle } = commonOptions();
// Rows of a screenshot left out of its statistics: the control bar (92 px with the strip).
const BAR = 100;
// The walkers' scene: a 12x6x1 floor (ids 1..72) and 10 walkers on top, ids 73..82.
const WALKER_CELLS = [[1, 1, 1], [1, 3, 1], [3, 2, 1], [2, 4, 1], [9, 1, 1], [10, 3, 1], [8, 2, 1], [9, 4, 1], [5, 1, 1], [6, 4, 1]];
const TARGET = [[4, 2, 1], [5, 2, 1], [6, 2, 1], [4, 3, 1], [5, 3, 1], [6, 3, 1]];
if (!datomsim || !existsSync(datomsim)) {
  console.error('view.e2e: give the datomsim binary: --datomsim PATH or DATOMSIM=PATH');
  process.exit(2);
}


function run(...args) {
  return execFileSync(datomsim, args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}

// The viewer script of the pages: FILE of --viewer-js, else viewer/src bundled now.
function viewerBundle(scratch) {
  if (givenBundle) return resolve(givenBundle);
  const file = join(scratch, 'viewer.bundle.js');
  execFileSync(process.execPath, [join(repository, 'viewer', 'build.mjs'), '--outfile', file], { stdio: 'ignore' });
  return file;
}

// The pages, written with `datomsim view` and the bundle: the demo's traces with their
// `datomsim reach` maps, a scene shown at rest, the walkers' run, and the walkers' run with
// targets added to its header.
function makePages(scratch) {
  const bundle = viewerBundle(scratch);
  const view = (...args) => run('view', ...args, '--viewer-js', bundle);
  const demo = join(scratch, 'demo');
  run('demo', '-o', demo, '--no-video');
  const pages = [];
  for (const hole of [2, 1]) {
    const name = `arch-hole${hole}`;
    const scene = join(repository, 'scenes', `paper-${name}.json`);
    const reach = join(scratch, `${name}-reach.json`);
    run('reach', scene, '--goal', GOAL.join(','), '--start', START.join(','), '--out', reach);
    const file = join(scratch, `${name}.html`);
    view(join(demo, `${name}-trace.jsonl`), '--reach', reach, '-o', file);
    pages.push({ name, file, run: true, overlay: JSON.parse(readFileSync(reach, 'utf8')) });
  }
  // 3D Catoms: the paper's run with the two-high arch rolled by Catoms (`run --module catom3d`),
  // and its scene at rest (the run's header alone).
  const catomScene = join(repository, 'scenes', 'paper-arch-hole2.json');
  const catomTrace = join(scratch, 'catom-run.jsonl');
  const catomReach = join(scratch, 'catom-reach.json');
  run('run', catomScene, '--module', 'catom3d', '--program', 'follow-gradient', '--goal', GOAL.join(','),
    '--start', START.join(','), '--trace', catomTrace, '--out', join(scratch, 'catom-run.json'));
  run('reach', catomScene, '--module', 'catom3d', '--goal', GOAL.join(','), '--start', START.join(','), '--out', catomReach);
  const [catomHeader] = readFileSync(catomTrace, 'utf8').split('\n');
  writeFileSync(join(scratch, 'catom-scene.jsonl'), catomHeader + '\n');
  for (const name of ['catom-run', 'catom-scene']) {
    const file = join(scratch, `${name}.html`);
    view(join(scratch, `${name}.jsonl`), '--reach', catomReach, '-o', file);
    pages.push({ name, file, catoms: { run: name === 'catom-run', modules: JSON.parse(catomHeader).modules } });
  }
  // The demo's self-reconfiguration: the arch built from a layer of modules on its box.
  const buildFile = join(scratch, 'arch-build.html');
  view(join(demo, 'arch-build-trace.jsonl'), '-o', buildFile);
  const buildRun = JSON.parse(readFileSync(join(demo, 'arch-build-run.json'), 'utf8'));
  // Each motion's start and end, read from the trace itself (its "motion" lines).
  const buildMotions = readFileSync(join(demo, 'arch-build-trace.jsonl'), 'utf8')
    .split('\n')
    .filter((line) => line.includes('"motion":{'))
    .map((line) => JSON.parse(line))
    .map((e) => ({ t: e.t, end: e.motion.end, m: e.motion.m }));
  pages.push({ name: 'arch-build', file: buildFile, reshape: buildRun, motions: buildMotions });

  const sceneFile = join(scratch, 'scene-hole1.html');
  view(join(repository, 'scenes', 'paper-arch-hole1.json'), '-o', sceneFile);
  pages.push({ name: 'scene-hole1', file: sceneFile, run: false, overlay: null });

  // Walkers: the floor, 10 modules on top, all walking at once.
  const floor = join(scratch, 'floor.json');
  run('generate', 'box', '--size', '12,6,1', '-o', floor);
  const scene = JSON.parse(readFileSync(floor, 'utf8'));
  WALKER_CELLS.forEach((cell, k) => scene.modules.push({ id: 73 + k, cell, orientation: 0, color: [200, 100, 0] }));
  const walk = join(scratch, 'walk.json');
  writeFileSync(walk, JSON.stringify(scene));
  const trace = join(scratch, 'walk.jsonl');
  const out = join(scratch, 'run.json');
  run('run', walk, '--program', 'walkers', '--trace', trace, '--out', out);
  const summary = JSON.parse(readFileSync(out, 'utf8'));
  const text = readFileSync(trace, 'utf8');
  const walkFile = join(scratch, 'walk.html');
  view(trace, '-o', walkFile);
  const refusals = text.split('\n').filter((line) => /"note":"motion refused/.test(line)).length;
  pages.push({ name: 'walkers', file: walkFile, walkers: { summary, refusals } });

  // The same run with two target shapes in its header: 6 cells of the floor's top, and the
  // walkers' start cells.
  const lines = text.split('\n');
  const header = JSON.parse(lines[0]);
  header.targets = [TARGET, WALKER_CELLS];
  lines[0] = JSON.stringify(header);
  const targetTrace = join(scratch, 'walk-target.jsonl');
  writeFileSync(targetTrace, lines.join('\n'));
  const targetFile = join(scratch, 'walk-target.html');
  view(targetTrace, '-o', targetFile);
  pages.push({ name: 'walkers-target', file: targetFile, targets: true });
  return pages;
}

// Statistics of a PNG screenshot, decoded by the browser: luminance variance and distinct colours
// of the 3D view (the control bar left out).
async function pictureStats(page, png) {
  return page.evaluate(async ([b64, bar]) => {
    const image = new Image();
    image.src = `data:image/png;base64,${b64}`;
    await image.decode();
    const canvas = document.createElement('canvas');
    canvas.width = image.width;
    canvas.height = image.height;
    const context = canvas.getContext('2d');
    context.drawImage(image, 0, 0);
    const height = image.height - bar;
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
  }, [png.toString('base64'), BAR]);
}

// Fraction of pixels that differ between two PNG screenshots of the same size.
async function difference(page, a, b) {
  return page.evaluate(
    async ([pa, pb, bar]) => {
      const load = async (b64) => {
        const image = new Image();
        image.src = `data:image/png;base64,${b64}`;
        await image.decode();
        const canvas = document.createElement('canvas');
        canvas.width = image.width;
        canvas.height = image.height;
        const context = canvas.getContext('2d');
        context.drawImage(image, 0, 0);
        return context.getImageData(0, 0, image.width, image.height - bar).data;
      };
      const [x, y] = [await load(pa), await load(pb)];
      let differ = 0;
      for (let k = 0; k < x.length; k += 4) {
        if (Math.abs(x[k] - y[k]) + Math.abs(x[k + 1] - y[k + 1]) + Math.abs(x[k + 2] - y[k + 2]) > 24) ++differ;
      }
      return differ / (x.length / 4);
    },
    [a.toString('base64'), b.toString('base64'), BAR],
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

      await check(`${name}: a legend gives the distance colours and the path`, async () => {
        const legend = await page.evaluate(`${api}.distanceLegend()`);
        const maximum = Math.max(...spec.overlay.distances.map((d) => d[3]));
        const labels = [...Array(Math.min(maximum, 9) + 1).keys()].join(' ');
        const ramp = maximum >= 10 ? ` 10\u2013${maximum}` : '';
        const expected = `motions to the goal: ${labels}${ramp} path, ${spec.overlay.path.length - 1} motions`;
        assert(legend === expected, `legend "${legend}", not "${expected}"`);
        await page.evaluate(`${api}.setOverlay(false)`);
        assert((await page.evaluate(`${api}.distanceLegend()`)) === null, 'the legend stays without the map');
        await page.evaluate(`${api}.setOverlay(true)`);
      });

      await check(`${name}: seen from the top, the captions hide no module`, async () => {
        for (const [width, height] of [[1280, 800], [900, 560], [700, 700]]) {
          await page.setViewportSize({ width, height });
          // The longest note of the run is on screen: its captions are the tallest.
          await page.evaluate(`${api}.seek(${duration * 0.5}); ${api}.fit('top')`);
          await settle(page);
          const hidden = await page.evaluate(() => {
            const v = window.datomsimViewer;
            const box = document.querySelector('.dv-top').getBoundingClientRect();
            return v
              .modules()
              .filter((m) => {
                const p = v.screenPositionOf(m.id);
                return p.x >= box.left && p.x <= box.right && p.y >= box.top && p.y <= box.bottom + 12;
              })
              .map((m) => m.id);
          });
          assert(hidden.length === 0, `at ${width}x${height} the captions cover modules ${hidden.join(', ')}`);
        }
        await shoot(page, `${name}-top-captions`);
        await page.setViewportSize(VIEWPORT);
        await page.evaluate(`${api}.fit()`);
      });

      await check(`${name}: the address names the moment shown, and opens there`, async () => {
        await page.evaluate(`${api}.seek(4.5); ${api}.fit('top'); ${api}.selectId(1)`);
        const fragment = await page.evaluate(`${api}.fragment()`);
        assert(fragment === '#t=4.5&view=top&select=1', `the address says ${fragment}`);
        const other = await context.newPage();
        await other.goto(`${pathToFileURL(spec.file).href}#t=7.25&view=top&select=1`);
        await other.waitForFunction(() => window.datomsimViewer && window.datomsimViewer.ready);
        const opened = await other.evaluate(() => [window.datomsimViewer.time(), window.datomsimViewer.selectedInfo()]);
        assert(opened[0] === 7.25, `opened at ${opened[0]} s, not 7.25 s`);
        assert(opened[1] && /Datom 1/.test(opened[1]), 'the module of the link is not selected');
        await other.evaluate(() => { window.location.hash = '#t=2&view=3d'; });
        await other.waitForFunction(() => window.datomsimViewer.time() === 2);
        await other.close();
        await page.evaluate(`${api}.selectId(-1); ${api}.fit()`);
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

  if (spec.catoms) await testCatoms(page, spec);
  if (spec.walkers) await testWalkers(page, spec);
  if (spec.targets) await testTargets(page, spec);
  if (spec.reshape) await testReshape(page, spec);

  await check(`${name}: no console error and no request leaves the file`, async () => {
    assert(errors.length === 0, `console errors: ${errors.join(' | ')}`);
    assert(requests.length === 0, `requests: ${requests.join(' ')}`);
  });
  await page.close();
}

// A page of 3D Catoms: one Catom drawn per module, where the module is; no Datom part; a Catom's
// panel; a run played to its end puts the mobile at the goal.
async function testCatoms(page, spec) {
  const name = spec.name;
  const api = 'window.datomsimViewer';
  const { modules } = spec.catoms;

  await check(`${name}: draws one 3D Catom per module, in its cell, and no Datom part`, async () => {
    await page.evaluate(`${api}.seek(0)`);
    assert((await page.evaluate(`${api}.moduleKind`)) === 'catom3d', 'the page does not read the header as Catoms');
    const drawn = await page.evaluate(`${api}.drawn()`);
    const count = (kind) => drawn.meshes.filter((m) => m.kind === kind).reduce((sum, m) => sum + m.instances, 0);
    assert(count('datom part') === 0, `${count('datom part')} Datom parts drawn`);
    assert(count('catom body') === modules.length, `${count('catom body')} Catom bodies for ${modules.length} modules`);
    assert(count('catom connector') === 12 * modules.length, `${count('catom connector')} connector plates`);
    const misplaced = modules.filter((m, k) => Math.hypot(...drawn.bodies[k].map((x, i) => x - cellToWorld(m.cell, 2)[i])) > 1e-4);
    assert(misplaced.length === 0, `bodies away from their cells: ${misplaced.map((m) => m.id).join(', ')}`);
    const subtitle = await page.evaluate(() => document.querySelector('.dv-subtitle').textContent);
    assert(subtitle.startsWith(`${modules.length} 3D Catoms`), `subtitle: ${subtitle}`);
    assert(await page.evaluate(() => document.querySelector('.dv-bar select[title^="Connector colour"]').hidden), 'the Datom connector colours are offered');
  });

  await check(`${name}: a click on a Catom shows its panel, without pistons; labels show`, async () => {
    await page.evaluate(`${api}.fit()`);
    await settle(page);
    const point = await page.evaluate(`${api}.screenPositionOf(1)`);
    await page.mouse.click(point.x, point.y);
    const info = await page.evaluate(`${api}.selectedInfo()`);
    assert(info && /3D Catom 1/.test(info), `no panel for module 1 (got ${info})`);
    assert(/latches/.test(info) && /orientation/.test(info) && !/piston/.test(info), info);
    await page.keyboard.press('l');
    const labels = await page.evaluate(() => [...document.querySelectorAll('.dv-label')].filter((l) => l.style.display !== 'none').length);
    assert(labels === modules.length, `${labels} labels shown for ${modules.length} modules`);
    await shoot(page, `${name}-panel-labels`);
    await page.keyboard.press('l');
    await page.keyboard.press('Escape');
    assert((await page.evaluate(`${api}.selectedInfo()`)) === null, 'Esc left the panel open');
  });

  await check(`${name}: the distance map, the top view, focus and latches`, async () => {
    assert((await page.evaluate(`${api}.distanceLegend()`)) !== null, 'no distance legend');
    await page.evaluate(`${api}.fit('top')`);
    const top = await shoot(page, `${name}-top`);
    assert((await pictureStats(page, top)).colours > 500, 'blank top view');
    await page.evaluate(`${api}.setOverlay(false); ${api}.fit(); ${api}.setLatches(true); ${api}.selectId(1); ${api}.setFocus(true)`);
    await shoot(page, `${name}-focus-latches`);
    await page.evaluate(`${api}.setFocus(false); ${api}.selectId(-1); ${api}.setLatches(false); ${api}.setOverlay(true)`);
    // Close, from the front left: the squares where neighbours touch.
    const [x, y, z] = cellToWorld(modules[0].cell, 2);
    await page.evaluate(`${api}.camera([${x - 4}, ${y - 7}, ${z + 5}], [${x + 2}, ${y + 2}, ${z}])`);
    await shoot(page, `${name}-close`);
    await page.evaluate(`${api}.fit()`);
  });

  if (!spec.catoms.run) return;
  await check(`${name}: turns and places move the Catoms: the mobile leaves its cell and ends at the goal`, async () => {
    const duration = await page.evaluate(`${api}.duration`);
    const middle = await page.evaluate(() => {
      const times = window.datomsimViewer.changeTimes;
      for (let k = 1; k < times.length; ++k) if (times[k] - times[k - 1] >= 0.9 && times[k - 1] > 0) return (times[k] + times[k - 1]) / 2;
      return times[1];
    });
    await page.evaluate(`${api}.seek(${middle})`);
    const moving = await page.evaluate(`${api}.drawn()`);
    const index = modules.findIndex((m) => m.id === 1);
    const away = Math.hypot(...moving.bodies[index].map((x, i) => x - cellToWorld(modules[index].cell, 2)[i]));
    assert(away > 0.1, `the mobile's body is ${away} from its cell in the middle of a turn`);
    await shoot(page, `${name}-turning`);
    await page.evaluate(`${api}.seek(0); ${api}.setSpeed(32); ${api}.play()`);
    await page.waitForFunction((d) => window.datomsimViewer.time() >= d, duration, { timeout: 120000, polling: 200 });
    const ended = await page.evaluate(`${api}.drawn()`);
    const goal = cellToWorld(GOAL, 2);
    const distance = Math.hypot(...ended.bodies[index].map((x, i) => x - goal[i]));
    assert(distance < 1e-3, `the mobile's body ends ${distance} away from the goal`);
    await shoot(page, `${name}-end`);
  });
}

// The ids of the module bodies away from their cells' centres (by more than 0.05 spacing): those
// mid-motion.
async function awayFromCells(page) {
  const modules = await page.evaluate(() => window.datomsimViewer.modules());
  return modules
    .filter((m) => Math.hypot(...m.position.map((p, k) => p - cellToWorld(m.cell, 2)[k])) > 0.1)
    .map((m) => m.id);
}

// The walkers' run: 10 motions at once at most.
async function testWalkers(page, spec) {
  const name = spec.name;
  const api = 'window.datomsimViewer';
  const { summary, refusals } = spec.walkers;
  const concurrency = await page.evaluate(`${api}.concurrency()`);
  const duration = await page.evaluate(`${api}.duration`);

  await check(`${name}: the strip's maximum is the run's max_concurrent_motions (${summary.max_concurrent_motions})`, async () => {
    assert(summary.max_concurrent_motions >= 5, `the run has only ${summary.max_concurrent_motions} motions at once`);
    assert(concurrency.max === summary.max_concurrent_motions, `strip max ${concurrency.max}`);
    const label = await page.evaluate(() => document.querySelector('.dv-strip-label')?.textContent);
    assert(label === `max ${summary.max_concurrent_motions}`, `the strip's label is ${label}`);
    assert(concurrency.refusals === refusals, `${concurrency.refusals} refusal ticks, the trace has ${refusals}`);
    // The strip is drawn: wide, and its plot colour fills a good part of it.
    const drawn = await page.evaluate(() => {
      const canvas = document.querySelector('.dv-strip-canvas');
      const { data } = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height);
      let plot = 0;
      for (let k = 0; k < data.length; k += 4) if (data[k] === 0x4f && data[k + 1] === 0x79 && data[k + 2] === 0xb5) ++plot;
      return { width: canvas.clientWidth, plot: plot / (data.length / 4) };
    });
    assert(drawn.width > 600, `the strip is only ${drawn.width} px wide`);
    assert(drawn.plot > 0.2, `the plot fills ${(100 * drawn.plot).toFixed(1)} % of the strip`);
  });

  // A time in the middle of the first stretch with the most motions in flight.
  const { from, to } = concurrency.maxAt[0];
  const busy = (from + to) / 2;
  await check(`${name}: at ${busy.toFixed(3)} s, ${concurrency.max} motions in flight and as many modules mid-motion`, async () => {
    await page.evaluate(`${api}.seek(${busy})`);
    const inFlight = await page.evaluate(`${api}.motionsInFlight()`);
    assert(inFlight.length === concurrency.max && inFlight.length >= 5, `${inFlight.length} motions in flight`);
    const away = await awayFromCells(page);
    const mobiles = inFlight.map((m) => m.m).sort((a, b) => a - b);
    assert(away.length >= 5, `only ${away.length} module bodies away from their cells`);
    assert(JSON.stringify(away.sort((a, b) => a - b)) === JSON.stringify(mobiles), `away ${away}, mobiles ${mobiles}`);
    const line = await page.evaluate(() => document.querySelector('.dv-motions').textContent);
    assert(line.startsWith(`${concurrency.max} motions in flight (max ${concurrency.max})`), line);
    // The marker of the current time is over the strip, where the time is.
    const marker = await page.evaluate(() => {
      const inner = document.querySelector('.dv-strip-inner').getBoundingClientRect();
      const cursor = document.querySelector('.dv-strip-cursor').getBoundingClientRect();
      return { x: (cursor.left + cursor.right) / 2 - inner.left, width: inner.width };
    });
    const expected = (busy / duration) * marker.width;
    assert(Math.abs(marker.x - expected) < 2, `the time marker is at ${marker.x} px, expected ${expected}`);
    await shoot(page, `${name}-concurrent`);
    // Closer, from the front, on the walkers.
    await page.evaluate(`${api}.camera([12, -8, 17], [12, 6.5, 1.5])`);
    await shoot(page, `${name}-concurrent-close`);
    await page.evaluate(`${api}.fit()`);
    // The panel of a mobile says what it does.
    await page.evaluate(`${api}.selectId(${mobiles[0]})`);
    const info = await page.evaluate(`${api}.selectedInfo()`);
    assert(/motion\s+mobile, about pivot \d+ to/.test(info), `the panel of mobile ${mobiles[0]}: ${info}`);
    await page.evaluate(`${api}.selectId(-1)`);
  });

  await check(`${name}: playing to a time shows what seeking to it shows`, async () => {
    await page.evaluate(`${api}.seek(${Math.max(0, from - 1.5)}); ${api}.setSpeed(2); ${api}.play()`);
    await page.waitForFunction((t) => window.datomsimViewer.time() >= t, from, { timeout: 60000, polling: 50 });
    await page.evaluate(`${api}.pause()`);
    const t = await page.evaluate(`${api}.time()`);
    const played = await shoot(page, `${name}-played`);
    const awayPlayed = await awayFromCells(page);
    await page.evaluate(`${api}.seek(${duration}); ${api}.seek(0); ${api}.seek(${t})`);
    const sought = await shoot(page, `${name}-sought`);
    assert(JSON.stringify(await awayFromCells(page)) === JSON.stringify(awayPlayed), 'other modules away from their cells');
    const changed = await difference(page, played, sought);
    assert(changed === 0, `${(100 * changed).toFixed(3)} % of the pixels differ at ${t} s`);
    rmSync(join(shots, `${name}-played.png`));
    rmSync(join(shots, `${name}-sought.png`));
  });

  await check(`${name}: a click on the strip seeks there`, async () => {
    const box = await page.evaluate(() => {
      const r = document.querySelector('.dv-strip-inner').getBoundingClientRect();
      return { x: r.left, y: r.top, width: r.width, height: r.height };
    });
    await page.mouse.click(box.x + box.width * 0.25, box.y + box.height / 2);
    const t = await page.evaluate(`${api}.time()`);
    assert(Math.abs(t - duration * 0.25) < duration / box.width + 1e-6, `seeked to ${t}, expected ${duration * 0.25}`);
    await page.evaluate(`${api}.seek(${busy})`);
    await settle(page);
    await page.screenshot({ path: join(shots, `${name}-strip.png`), clip: { x: 0, y: VIEWPORT.height - BAR - 40, width: VIEWPORT.width, height: BAR + 40 } });
  });
}

// The walkers' run with two target shapes in its header.
// A reconfiguration's page: the target filling up, several modules moving at once.
async function testReshape(page, spec) {
  const name = spec.name;
  const api = 'window.datomsimViewer';
  const run = spec.reshape;
  const duration = await page.evaluate(`${api}.duration`);
  const cells = run.final.length;

  await check(`${name}: the target is partly filled at the start and filled at the end`, async () => {
    assert(run.success === true && run.missing.length === 0, `the demo's run did not build the arch: ${run.reason}`);
    await page.evaluate(`${api}.seek(0)`);
    const start = await page.evaluate(`${api}.targets()`);
    assert(start.cells === cells, `the target has ${start.cells} cells, the run ${cells}`);
    assert(start.filled < cells, `${start.filled} of ${cells} filled at the start`);
    await shoot(page, `${name}-start`);
    await page.evaluate(`${api}.seek(${duration})`);
    const end = await page.evaluate(`${api}.targets()`);
    assert(end.filled === cells, `${end.filled} of ${cells} filled at the end`);
    assert(end.legend === `target: ${cells} cells, ${cells} filled`, `legend ${end.legend}`);
    await shoot(page, `${name}-end`);
  });

  await check(`${name}: in the middle, the run's most motions at once, as many modules mid-motion`, async () => {
    const concurrency = await page.evaluate(`${api}.concurrency()`);
    assert(concurrency.max === run.max_concurrent_motions && concurrency.max >= 4, `strip max ${concurrency.max}, run ${run.max_concurrent_motions}`);
    // A motion that has just started or is about to end has its module's body still (or again)
    // within a hair of a cell: seek the moment of the most motions at once where the motion
    // nearest either end is farthest from it.
    const motions = spec.motions;
    let best = { time: 0, margin: -1 };
    for (const { from, to } of concurrency.maxAt) {
      for (let k = 1; k < 10; k++) {
        const time = from + ((to - from) * k) / 10;
        const margins = motions
          .filter((m) => m.t <= time && time < m.end)
          .map((m) => Math.min(time - m.t, m.end - time) / (m.end - m.t));
        const margin = Math.min(...margins);
        if (margins.length === concurrency.max && margin > best.margin) best = { time, margin };
      }
    }
    await page.evaluate(`${api}.seek(${best.time})`);
    const inFlight = await page.evaluate(`${api}.motionsInFlight()`);
    const away = await awayFromCells(page);
    const mobiles = new Set(inFlight.map((m) => m.m));
    assert(inFlight.length === concurrency.max, `${inFlight.length} motions in flight`);
    assert(away.every((id) => mobiles.has(id)), `away ${away}, mobiles ${[...mobiles]}`);
    // Every module a tenth or more into its motion, and as far from its end, is away.
    const underWay = inFlight.filter((m) => Math.min(best.time - m.t, m.end - best.time) / (m.end - m.t) >= 0.1);
    assert(underWay.every((m) => away.includes(m.m)) && underWay.length >= 4,
      `${away.length} module bodies away from their cells, ${underWay.length} motions under way`);
    const middle = await page.evaluate(`${api}.targets()`);
    assert(middle.filled > 0 && middle.filled < cells, `${middle.filled} of ${cells} filled`);
    await shoot(page, `${name}-middle`);
  });
}

async function testTargets(page, spec) {
  const name = spec.name;
  const api = 'window.datomsimViewer';
  const filledNow = async (shape) => {
    const modules = await page.evaluate(`${api}.modules()`);
    const held = new Set(modules.map((m) => m.cell.join(',')));
    return shape.filter((c) => held.has(c.join(','))).length;
  };
  const duration = await page.evaluate(`${api}.duration`);

  await check(`${name}: the target's cells are counted, filled ones at the current time`, async () => {
    for (const t of [0, duration * 0.3, duration * 0.6, duration]) {
      await page.evaluate(`${api}.seek(${t})`);
      const targets = await page.evaluate(`${api}.targets()`);
      const filled = await filledNow(TARGET);
      assert(targets.shapes === 2 && targets.cells === TARGET.length, JSON.stringify(targets));
      assert(targets.filled === filled, `${targets.filled} filled, the modules hold ${filled} at ${t}`);
      assert(targets.legend === `target 1 of 2: ${TARGET.length} cells, ${filled} filled`, `legend ${targets.legend}`);
    }
    await page.evaluate(`${api}.seek(0); ${api}.setTargetShape(1)`);
    const second = await page.evaluate(`${api}.targets()`);
    assert(second.cells === 10 && second.filled === 10, `the walkers' start cells at 0: ${JSON.stringify(second)}`);
    await page.evaluate(`${api}.setTargetShape(0)`);
  });

  await check(`${name}: the target cells are drawn, translucent, and hide with G`, async () => {
    // Seen from the top at a time some target cells are empty.
    await page.evaluate(`${api}.seek(${duration * 0.3}); ${api}.fit('top')`);
    const shown = await shoot(page, `${name}-top`);
    await page.keyboard.press('g');
    assert((await page.evaluate(`${api}.targets().visible`)) === false, 'G did not hide the target');
    const hidden = await shoot(page, `${name}-top-hidden`);
    const changed = await difference(page, shown, hidden);
    assert(changed > 0.003, `showing the target changes only ${(100 * changed).toFixed(3)} % of the pixels`);
    rmSync(join(shots, `${name}-top-hidden.png`));
    await page.keyboard.press('g');
    assert((await page.evaluate(`${api}.targets().visible`)) === true, 'G did not show the target');
    await page.evaluate(`${api}.fit()`);
    await shoot(page, `${name}`);
    await page.evaluate(`${api}.camera([10, -4, 10], [10, 5.5, 1.5])`);
    await shoot(page, `${name}-close`);
    await page.evaluate(`${api}.fit()`);
  });
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
finish();
