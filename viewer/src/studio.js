// The studio's page (docs/studio.md): the scene and its live run come from the server over its
// socket, the viewer (app.js) draws them, and the bar above edits the scene, runs a program,
// steps, plays and stops it. Every request is answered; a refused one shows its error and changes
// nothing.
import { App } from './app.js';
import { NEIGHBOUR_OFFSETS, addCells, nearestDirection } from './lattice.js';
import { GENERATE_EXAMPLES, generateFields } from './generate_fields.js';
import { parseTrace } from './trace.js';

const STUDIO_STYLE = `
#datomsim-studio .ds-bar { position: fixed; top: 0; left: 0; right: 0;
  display: flex; flex-wrap: wrap; align-items: center; gap: 4px 8px; padding: 4px 8px;
  box-sizing: border-box; background: #1f2430; color: #e8ecf2; font: 13px system-ui, sans-serif; }
#datomsim-studio .ds-bar input { width: 64px; }
#datomsim-studio .ds-bar .ds-group { display: flex; align-items: center; gap: 4px;
  padding-right: 8px; border-right: 1px solid #3a4150; }
#datomsim-studio .ds-status { flex: 1 1 100%; white-space: nowrap; overflow: hidden;
  text-overflow: ellipsis; }
#datomsim-studio .ds-status.ds-error { color: #ff8a80; }
#datomsim-viewer { top: var(--ds-bar, 64px); }
#datomsim-studio .ds-moves { position: fixed; top: calc(var(--ds-bar, 64px) + 8px); right: 8px; max-height: 60%; overflow: auto;
  z-index: 5; background: rgba(255, 255, 255, 0.95); border: 1px solid #c5cbd6; padding: 6px 8px;
  font: 12px ui-monospace, monospace; white-space: pre; }
`;

function element(tag, properties = {}, ...children) {
  const node = Object.assign(document.createElement(tag), properties);
  node.append(...children);
  return node;
}

function labelled(text, input) {
  return element('label', {}, `${text} `, input);
}

export function startStudio(root) {
  const style = element('style', { textContent: STUDIO_STYLE });
  document.head.appendChild(style);

  const program = element('select', { id: 'ds-program' });
  const goal = element('input', { id: 'ds-goal', placeholder: 'x,y,z' });
  const start = element('input', { id: 'ds-start', placeholder: 'x,y,z' });
  const seed = element('input', { id: 'ds-seed', value: '1' });
  const runButton = element('button', { id: 'ds-run', textContent: 'Run' });
  const stepButton = element('button', { id: 'ds-step', textContent: 'Step' });
  const playButton = element('button', { id: 'ds-play', textContent: 'Play' });
  const speed = element('select', { id: 'ds-speed' });
  for (const [value, text] of [['1', 'real time'], ['10', '10x'], ['0', 'fastest']]) {
    speed.append(element('option', { value, textContent: text }));
  }
  const stopButton = element('button', { id: 'ds-stop', textContent: 'Stop' });
  const cell = element('input', { id: 'ds-cell', placeholder: 'x,y,z' });
  const addButton = element('button', { id: 'ds-add', textContent: 'Add' });
  const removeButton = element('button', { id: 'ds-remove', textContent: 'Remove' });
  const colour = element('input', { id: 'ds-colour', type: 'color', value: '#ff8000', title: 'The colour Colour gives' });
  const colourButton = element('button', { id: 'ds-recolour', textContent: 'Colour', title: 'Give the module in the cell the colour beside' });
  const undoButton = element('button', { id: 'ds-undo', textContent: 'Undo' });
  const redoButton = element('button', { id: 'ds-redo', textContent: 'Redo' });
  const movesButton = element('button', { id: 'ds-moves', textContent: 'Moves', title: 'Every rule of every pivot around the cell, valid or refused with its reason' });
  const saveJson = element('button', { id: 'ds-save-json', textContent: 'Save JSON' });
  const saveXml = element('button', { id: 'ds-save-xml', textContent: 'Save XML' });
  const openInput = element('input', { id: 'ds-open', type: 'file', accept: '.json,.xml' });
  // A new scene as `datomsim generate KIND` makes it, its options as KEY=VALUE words.
  const generateKind = element('select', { id: 'ds-generate-kind' });
  for (const kind of Object.keys(GENERATE_EXAMPLES)) generateKind.append(element('option', { value: kind, textContent: kind }));
  const generateOptions = element('input', { id: 'ds-generate-options', placeholder: GENERATE_EXAMPLES.box });
  generateOptions.style.width = '150px';
  generateKind.addEventListener('change', () => {
    generateOptions.placeholder = GENERATE_EXAMPLES[generateKind.value];
  });
  const generateButton = element('button', { id: 'ds-generate', textContent: 'New', title: 'A new scene, as datomsim generate makes it (undone with Undo)' });
  openInput.style.width = '170px';
  // A scene file whose targets the scene takes (its modules are not taken).
  const targetInput = element('input', { id: 'ds-target', type: 'file', accept: '.json,.xml', title: 'A scene file whose targets the scene takes, its modules not' });
  targetInput.style.width = '170px';
  // The run's history: a branch from the moment the timeline shows, the run's trace and offline
  // page, a picture of the view.
  const branchButton = element('button', { id: 'ds-branch', textContent: 'Branch', title: 'The scene at the moment the timeline shows, to edit and run again (undone with Undo)' });
  const saveTrace = element('button', { id: 'ds-save-trace', textContent: 'Save trace', title: 'The run\'s trace, as datomsim run --trace writes it' });
  const savePage = element('button', { id: 'ds-save-page', textContent: 'Save page', title: 'The run in a page that works offline, as datomsim view writes it' });
  const screenshot = element('button', { id: 'ds-screenshot', textContent: 'Screenshot', title: 'The view as a PNG picture' });
  const movesPanel = element('div', { id: 'ds-moves-panel', className: 'ds-moves' });
  movesPanel.hidden = true;
  const status = element('div', { id: 'ds-status', className: 'ds-status', textContent: 'connecting...' });
  const bar = element(
    'div',
    { className: 'ds-bar' },
    element('span', { className: 'ds-group' }, labelled('program', program), labelled('goal', goal),
      labelled('start', start), labelled('seed', seed), runButton),
    element('span', { className: 'ds-group' }, stepButton, playButton, speed, stopButton),
    element('span', { className: 'ds-group' }, labelled('cell', cell), addButton, removeButton,
      colour, colourButton, movesButton, undoButton, redoButton),
    element('span', { className: 'ds-group' }, saveJson, saveXml, openInput, labelled('target', targetInput)),
    element('span', { className: 'ds-group' }, labelled('new', generateKind), generateOptions, generateButton),
    element('span', { className: 'ds-group' }, branchButton, saveTrace, savePage, screenshot),
    status,
  );
  const stage = element('div', { id: 'datomsim-viewer' });
  root.append(bar, stage, movesPanel);
  // The viewer below the bar, however many lines the bar takes on this window.
  const fitBelowBar = () => {
    const height = `${bar.offsetHeight}px`;
    if (document.documentElement.style.getPropertyValue('--ds-bar') === height) return;
    document.documentElement.style.setProperty('--ds-bar', height);
    window.dispatchEvent(new Event('resize'));
  };
  new ResizeObserver(fitBelowBar).observe(bar);

  // What the page knows, for the person and for tests (window.datomsimStudio.state()).
  const state = { inspected: null, moves: null, modules: 0, running: false, over: false, time: 0, events: 0, motions: 0, error: null, result: null, ran: false, branch: null };
  let traceText = '';
  let app = null;
  let playing = false;

  // The trace so far at time t: a new viewer for a new scene or run (its camera kept), the same
  // one extended as a run grows (a new one each time would make a new 3D view).
  function show(t, fresh = false) {
    const trace = parseTrace(traceText);
    if (app && !fresh) {
      app.extend(trace);
    } else {
      const camera = app ? app.cameraState() : null;
      if (app) app.dispose();
      stage.replaceChildren();
      app = new App(stage, trace, null);
      if (camera) app.setCameraState(camera);
    }
    app.seek(t);
    app.onPick = picked;
    window.datomsimViewer = app.api();
  }

  // A click on a module puts its cell in the cell field last used (goal, start or cell); a
  // shift-click on one of its faces adds a module in the cell that face looks at. On the ground,
  // the same with the ground layer's cell under the pointer.
  let cellField = cell;
  for (const field of [goal, start, cell]) field.addEventListener('focus', () => (cellField = field));
  async function picked(index, point, event, groundCell) {
    if (index < 0) {
      if (!groundCell) return;
      if (!event.shiftKey) {
        cellField.value = groundCell.join(',');
        return;
      }
      if (state.running) return;
      cell.value = groundCell.join(',');
      if (took(await ask({ op: 'add', cell: cell.value }))) await loadScene();
      return;
    }
    const module = app.frame.modules[index];
    if (!event.shiftKey) {
      cellField.value = module.cell.join(',');
      // During a run, what its program is doing, kept up to date as the run goes.
      if (state.running) {
        state.inspected = { id: module.id, state: null };
        await inspect();
      }
      return;
    }
    if (state.running) return;
    const p = module.position.toArray();
    const away = [point[0] - p[0], point[1] - p[1], point[2] - p[2]];
    const length = Math.hypot(...away) || 1;
    const next = addCells(module.cell, NEIGHBOUR_OFFSETS[nearestDirection(away.map((c) => c / length))]);
    cell.value = next.join(',');
    if (took(await ask({ op: 'add', cell: cell.value }))) await loadScene();
  }

  function say() {
    status.classList.toggle('ds-error', Boolean(state.error));
    if (state.error) {
      status.textContent = state.error;
    } else if (state.running || state.result) {
      const result = state.result;
      const end = result
        ? `, ended${result.failure ? `: ${result.failure}` : ''}${result.arrived === false ? ' (the mobile did not arrive)' : ''}`
        : '';
      const inspected = state.inspected
        ? `; module ${state.inspected.id}: ${state.inspected.state ?? 'its program tells nothing'}`
        : '';
      status.textContent = `t = ${state.time.toFixed(2)} s, ${state.events} events, ${state.motions} motions${end}${inspected}`;
    } else if (state.branch) {
      const b = state.branch;
      status.textContent = `the scene at ${b.time} s of the run: ${b.modules} modules, ${b.motions_undone} motion${b.motions_undone === 1 ? '' : 's'} under way taken back (their mobiles where they started); edit it or Run`;
    } else {
      status.textContent = `${state.modules} modules; choose a program and Run, or edit the scene`;
    }
    stepButton.disabled = playButton.disabled = stopButton.disabled = !state.running;
    runButton.disabled = state.running;
    for (const button of [addButton, removeButton, colourButton, undoButton, redoButton, generateButton]) button.disabled = state.running;
    openInput.disabled = targetInput.disabled = state.running;
    branchButton.disabled = saveTrace.disabled = !state.ran;
  }

  const token = new URLSearchParams(window.location.search).get('token');
  const socket = new WebSocket(`ws://${window.location.host}/ws${token ? `?token=${encodeURIComponent(token)}` : ''}`);
  const waiting = [];
  function ask(request) {
    return new Promise((resolve) => {
      waiting.push(resolve);
      socket.send(JSON.stringify(request));
    });
  }
  socket.addEventListener('message', (event) => waiting.shift()(JSON.parse(event.data)));
  socket.addEventListener('close', () => {
    state.error = 'the studio has closed its connection: is datomsim studio still running?';
    playing = false;
    say();
  });

  // A reply: its error shown, or its values taken. True when it was answered with ok.
  function took(reply) {
    state.error = reply.ok ? null : reply.error;
    if (!reply.ok) say();
    return reply.ok;
  }

  function append(records) {
    for (const record of records ?? []) traceText += `${JSON.stringify(record)}\n`;
  }

  async function loadScene() {
    const reply = await ask({ op: 'scene' });
    if (!took(reply)) return;
    state.modules = reply.scene.modules.length;
    if (program.options.length === 0) {
      for (const name of reply.programs) program.append(element('option', { value: name, textContent: name }));
      program.value = 'follow-gradient';
    }
    traceText = reply.trace_header;
    state.result = null;
    state.branch = null;
    show(0, true);
    say();
  }

  // The inspected module's state now (the program's own words: `inspect`).
  async function inspect() {
    if (!state.inspected || !state.running) return;
    const reply = await ask({ op: 'inspect', id: state.inspected.id });
    if (!took(reply)) return;
    state.inspected.state = reply.state;
    say();
  }

  async function advance(request) {
    const reply = await ask({ op: 'advance', ...request });
    if (!took(reply)) return false;
    append(reply.records);
    Object.assign(state, { time: reply.time, over: reply.over, events: reply.events, motions: reply.motions });
    show(state.time);
    say();
    await inspect();
    // Over: nothing more can happen; its result is what the person wants next.
    if (reply.over) await stop();
    return !reply.over;
  }

  // Advances the run as time goes by (real time, ten times, or 5 s of the run per step), until
  // paused or over.
  async function play() {
    if (playing) return;
    playing = true;
    playButton.textContent = 'Pause';
    let last = performance.now();
    try {
      while (playing && state.running && !state.over) {
        await new Promise((resolve) => setTimeout(resolve, 200));
        const now = performance.now();
        const factor = Number(speed.value);
        const by = factor > 0 ? ((now - last) / 1000) * factor : 5;
        last = now;
        if (!(await advance({ by }))) break;
      }
    } finally {
      playing = false;
      playButton.textContent = 'Play';
    }
  }

  // The run ended, or stopped: its result, and the trace's last records.
  async function stop() {
    playing = false;
    const reply = await ask({ op: 'stop' });
    if (!took(reply)) return;
    traceText += reply.trace_tail;
    Object.assign(state, { running: false, over: true, result: reply.result, inspected: null });
    show(state.time);
    say();
  }

  runButton.addEventListener('click', async () => {
    const request = { op: 'run', program: program.value, seed: seed.value.trim() || '1' };
    if (goal.value.trim()) request.goal = goal.value.trim();
    if (start.value.trim()) request.start = start.value.trim();
    const reply = await ask(request);
    if (!took(reply)) return;
    traceText = '';
    append(reply.records);
    Object.assign(state, { running: true, over: false, time: 0, events: 0, motions: 0, result: null, inspected: null, ran: true });
    show(0, true);
    say();
  });
  stepButton.addEventListener('click', () => {
    playing = false;
    advance({ to: 'next' });
  });
  playButton.addEventListener('click', () => {
    if (playing) playing = false;
    else play();
  });
  stopButton.addEventListener('click', stop);
  const edit = (op) => async () => {
    const request = { op };
    if (op === 'add' || op === 'remove' || op === 'recolour') request.cell = cell.value.trim();
    if (op === 'recolour') request.rgb = colour.value;
    if (took(await ask(request))) await loadScene();
  };
  addButton.addEventListener('click', edit('add'));
  removeButton.addEventListener('click', edit('remove'));
  colourButton.addEventListener('click', edit('recolour'));
  undoButton.addEventListener('click', edit('undo'));
  redoButton.addEventListener('click', edit('redo'));

  // The moves at the cell typed: valid ones first, then the refused with their reason.
  movesButton.addEventListener('click', async () => {
    const reply = await ask({ op: 'moves', at: cell.value.trim() });
    if (!took(reply)) return;
    const moves = reply.moves.moves;
    const line = (m) => `pivot ${m.pivot.join(',')} piston ${m.piston ?? m.face} ${m.turn ?? ''} -> ${m.goal.join(',')}`;
    const valid = moves.filter((m) => m.valid).map(line);
    const refused = moves.filter((m) => !m.valid).map((m) => `${line(m)}: ${m.refusal}`);
    movesPanel.textContent =
      `${valid.length} of ${moves.length} rules hold at ${reply.moves.at.join(',')}\n` +
      [...valid, '', ...refused].join('\n');
    movesPanel.hidden = false;
    state.moves = { valid: valid.length, all: moves.length };
    say();
  });
  movesPanel.addEventListener('click', () => {
    movesPanel.hidden = true;
  });

  function download(blob, name) {
    const link = element('a', { href: URL.createObjectURL(blob), download: name });
    link.click();
    URL.revokeObjectURL(link.href);
  }
  // The scene as a file, downloaded.
  const save = (format) => async () => {
    const reply = await ask({ op: 'save', format });
    if (!took(reply)) return;
    download(new Blob([reply.text], { type: format === 'xml' ? 'application/xml' : 'application/json' }), `scene.${format}`);
  };
  // The moment the timeline shows, as a new scene (the run stopped if it was going).
  branchButton.addEventListener('click', async () => {
    playing = false;
    const reply = await ask({ op: 'branch', time: app.time });
    if (!took(reply)) return;
    Object.assign(state, { running: false, over: false, inspected: null });
    await loadScene();
    state.branch = reply;
    say();
  });
  saveTrace.addEventListener('click', async () => {
    const reply = await ask({ op: 'trace' });
    if (took(reply)) download(new Blob([reply.text], { type: 'application/x-ndjson' }), 'run.jsonl');
  });
  savePage.addEventListener('click', async () => {
    const reply = await ask({ op: 'page' });
    if (took(reply)) download(new Blob([reply.text], { type: 'text/html' }), 'run.html');
  });
  // The canvas keeps its drawing (view3d.js: preserveDrawingBuffer), so it is read as shown.
  screenshot.addEventListener('click', () => {
    app.view.render();
    app.view.renderer.domElement.toBlob((blob) => download(blob, 'studio.png'), 'image/png');
  });
  generateButton.addEventListener('click', async () => {
    const request = { op: 'generate', kind: generateKind.value, ...generateFields(generateOptions.value) };
    if (took(await ask(request))) await loadScene();
  });

  saveJson.addEventListener('click', save('json'));
  saveXml.addEventListener('click', save('xml'));
  // A file chosen: its name and text sent with `op` (open: the scene; target: its targets).
  const sendFile = (input, op) => async () => {
    const file = input.files[0];
    if (!file) return;
    const reply = await ask({ op, name: file.name, text: await file.text() });
    input.value = '';
    if (took(reply)) await loadScene();
  };
  openInput.addEventListener('change', sendFile(openInput, 'open'));
  targetInput.addEventListener('change', sendFile(targetInput, 'target'));

  window.datomsimStudio = { state: () => ({ ...state }) };
  socket.addEventListener('open', loadScene);
}
