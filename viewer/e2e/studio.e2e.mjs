// End-to-end checks of the studio (docs/studio.md): `datomsim studio` started on a free port, its
// page opened in headless Chromium, driven by clicks as a person would.
//
//   node viewer/e2e/studio.e2e.mjs --datomsim build/release/bin/datomsim [--shots DIR]
//
// Prints one line per check and `N passed, M failed`; exits non-zero on a failure.
import { execFileSync, spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { launchBrowser } from './browser.mjs';
import { assert, check, commonOptions, finish, repository } from './harness.mjs';

const { datomsim, shots } = commonOptions();
if (!datomsim) {
  console.error('usage: node viewer/e2e/studio.e2e.mjs --datomsim PATH [--shots DIR]');
  process.exit(2);
}

const scene = join('scenes', 'paper-arch-hole1.json');

// The studio on a free port: its address, from the line it prints.
function startStudio() {
  const child = spawn(resolve(datomsim), ['studio', scene, '--port', '0'], {
    cwd: repository,
    stdio: ['ignore', 'pipe', 'pipe'],
  });
  return new Promise((resolveStart, reject) => {
    let out = '';
    child.stdout.on('data', (chunk) => {
      out += chunk;
      const found = out.match(/studio at (http:\/\/\S+)/);
      if (found) resolveStart({ child, url: found[1] });
    });
    child.on('exit', (code) => reject(new Error(`datomsim studio ended (${code}): ${out}`)));
  });
}

// What the command line says of the same run.
function commandLineRun() {
  const out = execFileSync(
    resolve(datomsim),
    ['run', scene, '--program', 'follow-gradient', '--goal', '6,5,2', '--start', '0,0,2'],
    { cwd: repository, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] },
  );
  return JSON.parse(out);
}

const { child, url } = await startStudio();
const { context, close } = await launchBrowser();
try {
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (error) => errors.push(String(error)));
  const state = () => page.evaluate(() => window.datomsimStudio.state());
  const waitFor = (predicate, argument = null) =>
    page.waitForFunction(predicate, argument, { timeout: 30000, polling: 100 });
  // Step clicked `count` times, each waited for until its events have run.
  const stepTimes = async (count) => {
    for (let k = 0; k < count; ++k) {
      const before = (await state()).events;
      await page.click('#ds-step');
      await waitFor((n) => window.datomsimStudio.state().events > n, before);
    }
  };

  await check('the page opens with the scene', async () => {
    await page.goto(url);
    await waitFor(() => window.datomsimStudio && window.datomsimStudio.state().modules > 0);
    const s = await state();
    assert(s.modules === 131, `modules ${s.modules}`);
    await page.screenshot({ path: join(shots, 'studio-scene.png') });
  });

  await check('a module added by its cell, then undone', async () => {
    await page.fill('#ds-cell', '0,0,1');
    await page.click('#ds-add');
    await waitFor(() => window.datomsimStudio.state().modules === 132);
    await page.click('#ds-undo');
    await waitFor(() => window.datomsimStudio.state().modules === 131);
  });

  await check('a click names the cell of a module, a shift-click adds a module on the face clicked', async () => {
    const modules = await page.evaluate(() => window.datomsimViewer.modules());
    const top = modules.reduce((a, b) => (b.cell[2] > a.cell[2] ? b : a));
    const at = await page.evaluate((id) => window.datomsimViewer.screenPositionOf(id), top.id);
    await page.focus('#ds-goal');
    await page.mouse.click(at.x, at.y);
    const goal = await page.inputValue('#ds-goal');
    assert(goal === top.cell.join(','), `goal ${goal} against the module's cell ${top.cell}`);
    await page.fill('#ds-goal', '');
    await page.keyboard.down('Shift');
    await page.mouse.click(at.x, at.y);
    await page.keyboard.up('Shift');
    await waitFor(() => window.datomsimStudio.state().modules === 132);
    const added = (await page.inputValue('#ds-cell')).split(',').map(Number);
    const offset = added.map((c, k) => c - top.cell[k]);
    const neighbours = ['1,0,0', '0,1,0', '0,0,1', '-1,0,1', '-1,-1,1', '0,-1,1', '-1,0,0', '0,-1,0', '0,0,-1', '1,0,-1', '1,1,-1', '0,1,-1'];
    assert(neighbours.includes(offset.join(',')), `the cell added ${added} is no neighbour of ${top.cell}`);
    assert(!modules.some((m) => m.cell.join(',') === added.join(',')), `${added} held a module already`);
    await page.screenshot({ path: join(shots, 'studio-added.png') });
    await page.click('#ds-undo');
    await waitFor(() => window.datomsimStudio.state().modules === 131);
  });

  await check('a click on the ground names its cell, a shift-click there adds a module', async () => {
    // Empty ground cells around the box, clicked where the camera shows them (clear of the bar
    // and the timeline); one the box hides names the module in front instead.
    const viewport = page.viewportSize();
    let ground = null;
    let at = null;
    const named = [];
    await page.focus('#ds-cell');
    for (const cell of [[4, 0, 0], [0, 4, 0], [8, 4, 0], [4, 8, 0], [0, 0, 0], [8, 0, 0], [0, 8, 0]]) {
      at = await page.evaluate((c) => window.datomsimViewer.screenPositionOfCell(c), cell);
      if (at.x < 40 || at.x > viewport.width - 40 || at.y < 160 || at.y > viewport.height - 120) continue;
      await page.fill('#ds-cell', '');
      await page.mouse.click(at.x, at.y);
      named.push(await page.inputValue('#ds-cell'));
      if (named.at(-1) === cell.join(',')) {
        ground = cell;
        break;
      }
    }
    assert(ground, `no ground cell named by its click: ${named.join(' ')}`);
    await page.keyboard.down('Shift');
    await page.mouse.click(at.x, at.y);
    await page.keyboard.up('Shift');
    await waitFor(() => window.datomsimStudio.state().modules === 132);
    const modules = await page.evaluate(() => window.datomsimViewer.modules());
    assert(modules.some((m) => m.cell.join(',') === ground.join(',')), `no module at ${ground}`);
    await page.screenshot({ path: join(shots, 'studio-ground.png') });
    await page.click('#ds-undo');
    await waitFor(() => window.datomsimStudio.state().modules === 131);
  });

  await check('a module recoloured from the bar, then undone', async () => {
    const first = (await page.evaluate(() => window.datomsimViewer.modules()))[0];
    await page.fill('#ds-cell', first.cell.join(','));
    await page.$eval('#ds-colour', (input) => {
      input.value = '#20c0ff';
    });
    await page.click('#ds-recolour');
    await waitFor(() => window.datomsimViewer.modules()[0].rgb.join(',') === '32,192,255');
    await page.click('#ds-undo');
    await waitFor(
      (rgb) => window.datomsimViewer.modules()[0].rgb.join(',') === rgb,
      first.rgb.join(','),
    );
  });

  await check('a bad cell is refused with the message, and changes nothing', async () => {
    await page.fill('#ds-cell', '400,0,0');
    await page.click('#ds-add');
    await waitFor(() => window.datomsimStudio.state().error !== null);
    const s = await state();
    assert(s.error.includes('400,0,0'), s.error);
    assert(s.modules === 131, `modules ${s.modules}`);
  });

  await check('the moves at a cell, as datomsim moves gives them', async () => {
    await page.fill('#ds-cell', '2,2,3');
    await page.click('#ds-moves');
    await waitFor(() => window.datomsimStudio.state().moves !== null);
    const s = await state();
    const expected = JSON.parse(
      execFileSync(resolve(datomsim), ['moves', scene, '--at', '2,2,3', '--format', 'json'], {
        cwd: repository,
        encoding: 'utf8',
      }),
    );
    assert(s.moves.all === expected.moves.length, `${s.moves.all} rules against ${expected.moves.length}`);
    assert(s.moves.valid === expected.moves.filter((m) => m.valid).length, `${s.moves.valid} valid`);
    const panel = await page.textContent('#ds-moves-panel');
    assert(panel.includes(`${s.moves.valid} of ${s.moves.all} rules hold at 2,2,3`), panel.slice(0, 200));
    await page.screenshot({ path: join(shots, 'studio-moves.png') });
    await page.click('#ds-moves-panel');
  });

  await check('a new scene generated from the bar, a bad option refused, then undone', async () => {
    await page.selectOption('#ds-generate-kind', 'arch');
    await page.fill('#ds-generate-options', 'hole=3');
    await page.click('#ds-generate');
    await waitFor(() => window.datomsimStudio.state().error !== null);
    const refused = await state();
    assert(refused.error.includes('--hole 3'), refused.error);
    assert(refused.modules === 131, `modules ${refused.modules}`);
    await page.fill('#ds-generate-options', 'hole=2');
    await page.click('#ds-generate');
    await waitFor(() => window.datomsimStudio.state().modules === 130);
    const modules = await page.evaluate(() => window.datomsimViewer.modules());
    assert(modules.some((m) => m.cell.join(',') === '6,5,2'), 'the mobile of the arch with hole 2 is not at 6,5,2');
    await page.screenshot({ path: join(shots, 'studio-generated.png') });
    await page.click('#ds-undo');
    await waitFor(() => window.datomsimStudio.state().modules === 131);
  });

  await check('the scene saved as JSON is the scene file, and opened again', async () => {
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#ds-save-json')]);
    const saved = join(shots, 'studio-saved.json');
    await download.saveAs(saved);
    const converted = join(shots, 'studio-converted.json');
    execFileSync(resolve(datomsim), ['-q', 'convert', scene, '-o', converted], { cwd: repository });
    assert(readFileSync(saved, 'utf8') === readFileSync(converted, 'utf8'), 'the saved scene differs from datomsim convert');
    await page.setInputFiles('#ds-open', { name: 'line.json', mimeType: 'application/json', buffer: readFileSync(join(repository, 'scenes', 'reshape-line.json')) });
    await waitFor(() => window.datomsimStudio.state().modules === 104);
    await page.click('#ds-undo');
    await waitFor(() => window.datomsimStudio.state().modules === 131);
  });

  await check('a target file gives the scene its shape, drawn, then undone', async () => {
    await page.setInputFiles('#ds-target', join(repository, 'scenes', 'reshape-arch-hole2.json'));
    await waitFor(() => window.datomsimViewer.targets().shapes === 1);
    await page.screenshot({ path: join(shots, 'studio-target.png') });
    await page.click('#ds-undo');
    await waitFor(() => window.datomsimViewer.targets().shapes === 0);
  });

  await check('follow-gradient runs live: stepped, played, stopped, as the command line runs it', async () => {
    await page.selectOption('#ds-program', 'follow-gradient');
    await page.fill('#ds-goal', '6,5,2');
    await page.fill('#ds-start', '0,0,2');
    await page.click('#ds-run');
    await waitFor(() => window.datomsimStudio.state().running);
    await stepTimes(3);
    const stepped = await state();
    assert(stepped.time > 0 && !stepped.over, JSON.stringify(stepped));
    await page.selectOption('#ds-speed', '0');
    await page.click('#ds-play');
    // Over, the run ends by itself and shows its result.
    await waitFor(() => window.datomsimStudio.state().result !== null);
    await page.screenshot({ path: join(shots, 'studio-run.png') });
    const s = await state();
    const expected = commandLineRun();
    assert(s.result.motions === expected.motions, `motions ${s.result.motions} against ${expected.motions}`);
    assert(s.result.events === expected.events, `events ${s.result.events} against ${expected.events}`);
    assert(JSON.stringify(s.result.path) === JSON.stringify(expected.path), 'the path differs');
  });

  await check('the run saved as its trace and page, a screenshot, and a branch from its middle', async () => {
    const [traceFile] = await Promise.all([page.waitForEvent('download'), page.click('#ds-save-trace')]);
    const saved = join(shots, 'studio-run.jsonl');
    await traceFile.saveAs(saved);
    const expected = join(shots, 'studio-cli.jsonl');
    execFileSync(resolve(datomsim), ['-q', 'run', scene, '--program', 'follow-gradient', '--goal', '6,5,2', '--start', '0,0,2', '--trace', expected, '--out', join(shots, 'studio-cli.json')], { cwd: repository });
    assert(readFileSync(saved, 'utf8') === readFileSync(expected, 'utf8'), 'the saved trace differs from datomsim run --trace');
    const [pageFile] = await Promise.all([page.waitForEvent('download'), page.click('#ds-save-page')]);
    await pageFile.saveAs(join(shots, 'studio-run.html'));
    assert(readFileSync(join(shots, 'studio-run.html'), 'utf8').includes('id="datomsim-trace"'), 'the saved page holds no trace');
    const [picture] = await Promise.all([page.waitForEvent('download'), page.click('#ds-screenshot')]);
    await picture.saveAs(join(shots, 'studio-screenshot.png'));
    const png = readFileSync(join(shots, 'studio-screenshot.png'));
    assert(png.length > 1000 && png.subarray(1, 4).toString() === 'PNG', 'the screenshot is no PNG');
    // Halfway through the first motion (0.15 s to 2.15 s): the mobile taken back to its start.
    await page.evaluate(() => window.datomsimViewer.seek(1.15));
    await page.click('#ds-branch');
    await waitFor(() => /taken back/.test(document.querySelector('#ds-status').textContent));
    const line = await page.textContent('#ds-status');
    assert(/at 1\.15 s of the run: 131 modules, 1 motion under way/.test(line), line);
    await page.screenshot({ path: join(shots, 'studio-branch.png') });
    await page.click('#ds-undo');
    await waitFor(() => window.datomsimStudio.state().branch === null);
  });

  await check('a mover clicked during a reconfiguration says what its program is doing', async () => {
    await page.selectOption('#ds-generate-kind', 'reshape');
    await page.fill('#ds-generate-options', 'case=line length=8');
    await page.click('#ds-generate');
    await waitFor(() => window.datomsimStudio.state().modules === 104);
    await page.selectOption('#ds-program', 'reconfigure');
    await page.fill('#ds-goal', '');
    await page.fill('#ds-start', '');
    await page.click('#ds-run');
    await waitFor(() => window.datomsimStudio.state().running);
    await stepTimes(3);
    // Module 104 ends the line, off the target: a mover.
    const at = await page.evaluate(() => window.datomsimViewer.screenPositionOf(104));
    await page.mouse.click(at.x, at.y);
    await waitFor(() => /module 104: /.test(document.querySelector('#ds-status').textContent));
    const line = await page.textContent('#ds-status');
    assert(/module 104: (waiting|moving|asking)/.test(line), line);
    await page.screenshot({ path: join(shots, 'studio-inspect.png') });
    await page.click('#ds-stop');
    await waitFor(() => !window.datomsimStudio.state().running);
  });

  await check('the page raised no error', async () => {
    assert(errors.length === 0, errors.join('\n'));
  });
} finally {
  await close();
  child.kill('SIGINT');
}
finish();
