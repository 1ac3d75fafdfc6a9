// The viewer application: controls, playback and the module panel around a View3D.
//
// Playback only maps wall-clock time to trace time (times the speed); each picture is
// timeline.frameAt(t), so the speed, pauses and seeks never change what is shown at a given t.
import { PART_SCHEMES, PATH_COLOR, TARGET_EMPTY, TARGET_FILLED, distanceLegend, rgbToCss } from './colors.js';
import { formatSeconds } from './format.js';
import { viewerApi } from './api.js';
import { Colourings } from './colourings.js';
import { formatFragment, parseFragment } from './fragment.js';
import { Kinematics } from './kinematics.js';
import { OverloadMarks } from './latch_marks.js';
import { element, fillPanel } from './panel.js';
import { ConcurrencyStrip } from './strip.js';
import { Timeline } from './timeline.js';
import { CATOM3D, DATOM, nextChangeTime, previousChangeTime } from './trace.js';
import { View3D } from './view3d.js';

export const SPEEDS = [0.1, 0.25, 0.5, 1, 2, 4, 8, 16, 32];

function button(label, title, onClick) {
  const b = element('button', { type: 'button', title, 'aria-label': title });
  if (ICONS[label]) b.innerHTML = ICONS[label];
  else b.textContent = label;
  b.addEventListener('click', onClick);
  return b;
}

// Transport icons as inline SVG: system fonts often lack the media control characters.
const ICONS = {
  start: '<svg viewBox="0 0 16 16"><path d="M3 3h2v10H3zM13 3v10L6 8z"/></svg>',
  back: '<svg viewBox="0 0 16 16"><path d="M4 3h2v10H4zM13 3v10L7 8z"/></svg>',
  play: '<svg viewBox="0 0 16 16"><path d="M4 2.5v11L13 8z"/></svg>',
  pause: '<svg viewBox="0 0 16 16"><path d="M4 3h3v10H4zM9 3h3v10H9z"/></svg>',
  step: '<svg viewBox="0 0 16 16"><path d="M3 3v10l6-5zM10 3h2v10h-2z"/></svg>',
  end: '<svg viewBox="0 0 16 16"><path d="M3 3v10l7-5zM11 3h2v10h-2z"/></svg>',
};

function checkbox(label, checked, onChange) {
  const input = element('input', { type: 'checkbox' });
  input.checked = checked;
  input.addEventListener('change', () => onChange(input.checked));
  const wrapper = element('label', { className: 'dv-toggle' }, [input, document.createTextNode(label)]);
  return { wrapper, input };
}

export const formatTime = formatSeconds;

// The mobiles of the motions in flight, as "73, 74, 75", at most `limit` of them.
function mobileList(motions, limit = 12) {
  const ids = motions.slice(0, limit).map((m) => String(m.m));
  if (motions.length > limit) ids.push('\u2026');
  return ids.join(', ');
}

export class App {
  // loads: the page's latch loads document (colouring.js checks it against the trace), or null.
  constructor(root, trace, overlay, loads = null) {
    this.root = root;
    this.trace = trace;
    this.timeline = new Timeline(trace);
    this.loads = loads;
    this.colourings = new Colourings(trace, this.timeline, loads);
    this.kinematics = new Kinematics(trace.header);
    // A 3D Catom has no pistons: what tells of them (the panel's pistons, the connector colours of
    // the Datom's figures) is left out for Catoms.
    this.moduleKind = trace.module ?? DATOM;
    this.catoms = this.moduleKind === CATOM3D;
    this.duration = trace.duration;
    this.time = 0;
    this.speed = 1;
    this.playing = false;
    this.lastWall = null;
    this.overlay = overlay;
    // The moment and view the URL names (fragment.js); video mode hides the controls.
    const opening = parseFragment(window.location.hash);
    this.videoMode = Boolean(opening.video);
    this.viewName = '3d';
    if (this.videoMode) root.classList.add('dv-video');

    this.shadows = opening.shadows ?? true;

    // Every listener on the window ends with the app (dispose: the studio replaces its app as
    // its run grows).
    this.listening = new AbortController();
    this.disposed = false;
    this.buildDom();
    this.view = new View3D(this.canvasHolder, this.timeline, this.kinematics, overlay, { shadows: this.shadows });
    this.view.setOverlayVisible(true);
    this.marks = new OverloadMarks(this.view.scene, trace.header.spacing, this.colourings.loads?.overloaded ?? 0);
    this.overlayToggle.wrapper.hidden = !overlay;
    if (this.strip) this.strip.draw();
    this.installInput();
    this.seek(0);
    this.applyFragment(opening);
    window.addEventListener('hashchange', () => this.applyFragment(parseFragment(window.location.hash)), {
      signal: this.listening.signal,
    });
    this.tick = this.tick.bind(this);
    requestAnimationFrame(this.tick);
  }

  buildDom() {
    const header = this.trace.header;
    this.canvasHolder = element('div', { className: 'dv-canvas' });
    const title = header.description || 'datomsim trace';
    this.noteLine = element('div', { className: 'dv-note' });
    this.noteLine.hidden = this.duration <= 0;
    // Motions in flight (when the trace has "motion" lines) and the target legend.
    this.motionLine = element('div', { className: 'dv-motions' });
    this.targets = this.trace.targets;
    this.targetShape = 0;
    // "[empty] target: N cells, [filled] M filled": each count after the colour of its balls.
    this.targetText = element('span');
    this.filledText = element('span');
    const empty = element('span', { className: 'dv-swatch dv-target-swatch', title: 'a target cell no module holds' });
    empty.style.background = rgbToCss(TARGET_EMPTY);
    const filled = element('span', { className: 'dv-swatch dv-target-swatch', title: 'a target cell a module holds' });
    filled.style.background = rgbToCss(TARGET_FILLED);
    this.targetLine = element('div', { className: 'dv-target' }, [empty, this.targetText, filled, this.filledText]);
    this.targetLine.hidden = this.targets.length === 0;
    this.distanceLine = this.buildDistanceLegend();
    // Video mode has no time slider: the time is a caption, to a tenth of a second.
    this.clockLine = element('div', { className: 'dv-clock' });
    this.clockLine.hidden = !this.videoMode || this.duration <= 0;
    this.top = element('div', { className: 'dv-top' }, [
      element('div', { className: 'dv-title', text: title }),
      this.clockLine,
      element('div', {
        className: 'dv-subtitle',
        text:
          (this.catoms
            ? `${header.modules.length} 3D Catoms, r = ${header.dimensions.r}`
            : `${header.modules.length} modules, r = ${header.dimensions.r}, t = ${header.dimensions.t ?? 0}`) +
          (this.duration > 0 ? `, ${formatTime(this.duration)}` : ', scene (no changes)'),
      }),
      this.distanceLine,
      this.colourings.legend,
      this.targetLine,
      this.motionLine,
      this.noteLine,
    ]);

    // Playback controls.
    this.playButton = button('play', 'Play / pause (space)', () => this.togglePlay());
    this.slider = element('input', {
      type: 'range',
      min: '0',
      max: String(this.duration),
      step: 'any',
      value: '0',
      className: 'dv-slider',
      'aria-label': 'time',
    });
    this.slider.addEventListener('input', () => {
      this.pause();
      this.seek(Number(this.slider.value));
    });
    this.timeLabel = element('span', { className: 'dv-time' });
    this.speedSelect = element('select', { title: 'Playing speed (trace seconds per second)', className: 'dv-speed' });
    for (const s of SPEEDS) {
      const option = element('option', { value: String(s), text: `${s}\u00D7` });
      if (s === 1) option.selected = true;
      this.speedSelect.appendChild(option);
    }
    this.speedSelect.addEventListener('change', () => {
      this.speed = Number(this.speedSelect.value);
    });

    const markers = element('div', { className: 'dv-markers' });
    if (this.duration > 0) {
      for (const note of this.trace.notes) {
        const tick = element('div', { className: 'dv-marker', title: `${formatTime(note.t)}: ${note.text}` });
        tick.style.left = `${(100 * note.t) / this.duration}%`;
        markers.appendChild(tick);
      }
    }
    const sliderCell = element('div', { className: 'dv-slider-cell' }, [this.slider, markers]);
    const sliderBox = element('div', { className: 'dv-slider-box' }, [sliderCell, element('span')]);
    // The concurrency strip, when the trace has motion lines.
    if (this.trace.motions.length > 0 && this.duration > 0) {
      this.strip = new ConcurrencyStrip(this.timeline.motionIndex, this.trace.refusals, this.duration, (t) =>
        this.pauseAndSeek(t),
      );
      sliderBox.append(this.strip.element, this.strip.label);
      this.root.classList.add('dv-has-strip');
    }
    this.motionLine.hidden = !this.strip;

    this.labelsToggle = checkbox('labels', false, (on) => this.setLabelsVisible(on));
    this.overlayToggle = checkbox('distances', true, (on) => this.setOverlayVisible(on));
    this.focusToggle = checkbox('focus', false, (on) => {
      this.view.focus = on;
      this.redraw();
    });
    this.focusToggle.wrapper.title = this.catoms
      ? 'Fade every module but the selected one and those moving (X)'
      : 'Fade every module but the selected one and those deforming or moving (X)';
    this.latchesToggle = checkbox('latches', false, (on) => {
      this.view.showLatches = on;
      this.redraw();
    });
    this.targetsToggle = checkbox('target', true, (on) => this.setTargetsVisible(on));
    this.targetsToggle.wrapper.title = 'Show the target cells (G)';
    this.targetsToggle.wrapper.hidden = this.targets.length === 0;
    this.targetSelect = element('select', { title: 'Which target shape to show and count' });
    this.targets.forEach((shape, k) => {
      this.targetSelect.appendChild(element('option', { value: String(k), text: `target ${k + 1} of ${this.targets.length}` }));
    });
    this.targetSelect.hidden = this.targets.length < 2;
    this.targetSelect.addEventListener('change', () => this.setTargetShape(Number(this.targetSelect.value)));
    this.schemeSelect = element('select', { title: 'Connector colour: red as in the paper, or a dark tint of the module' });
    for (const scheme of PART_SCHEMES) {
      this.schemeSelect.appendChild(element('option', { value: scheme, text: `connectors: ${scheme === 'paper' ? 'red' : 'tint'}` }));
    }
    this.schemeSelect.addEventListener('change', () => {
      this.view.scheme = this.schemeSelect.value;
      this.redraw();
    });
    // A Catom's connectors are always a darker shade of its colour.
    this.schemeSelect.hidden = this.catoms;
    this.colourings.select.addEventListener('change', () => this.setColouring(this.colourings.select.value));

    const disabled = this.duration <= 0;
    const transport = [
      button('start', 'Start (Home)', () => this.pauseAndSeek(0)),
      button('back', 'Previous change (\u2190)', () => this.stepBack()),
      this.playButton,
      button('step', 'Next change (\u2192)', () => this.step()),
      button('end', 'End (End)', () => this.pauseAndSeek(this.duration)),
    ];
    if (disabled) {
      for (const b of transport) b.disabled = true;
      this.slider.disabled = true;
    }
    this.bar = element('div', { className: 'dv-bar' }, [
      element('div', { className: 'dv-transport' }, transport),
      sliderBox,
      this.timeLabel,
      this.speedSelect,
      element('div', { className: 'dv-toggles' }, [
        this.labelsToggle.wrapper,
        this.overlayToggle.wrapper,
        this.targetsToggle.wrapper,
        this.targetSelect,
        this.latchesToggle.wrapper,
        this.focusToggle.wrapper,
        this.schemeSelect,
        this.colourings.select,
        button('fit', 'Fit the scene (F)', () => this.fit('3d')),
        button('top', 'Seen from the top, as the paper\'s distance maps (T)', () => this.fit('top')),
      ]),
    ]);

    this.panel = element('div', { className: 'dv-panel' });
    this.panel.hidden = true;
    this.help = element('div', {
      className: 'dv-help',
      text: 'drag: orbit \u00B7 right-drag: pan \u00B7 wheel: zoom \u00B7 click: module \u00B7 space: play \u00B7 \u2190 \u2192: step \u00B7 F: fit \u00B7 T: top \u00B7 L: labels \u00B7 X: focus' +
        (this.trace.targets.length ? ' \u00B7 G: target' : '') +
        (this.colourings.modes.length > 1 ? ' \u00B7 C: colours' : ''),
    });
    this.root.append(this.canvasHolder, this.top, this.panel, this.help, this.bar);
  }

  installInput() {
    const canvas = this.view.renderer.domElement;
    let down = null;
    canvas.addEventListener('pointerdown', (event) => {
      down = { x: event.clientX, y: event.clientY };
    });
    canvas.addEventListener('pointerup', (event) => {
      if (!down) return;
      const moved = Math.hypot(event.clientX - down.x, event.clientY - down.y);
      down = null;
      if (moved > 4) return; // a drag of the camera, not a click
      const picked = this.view.pickPoint(event.clientX, event.clientY);
      this.select(picked.index);
      // The studio's: a click names a cell, a shift-click a face to add a module on.
      if (this.onPick) this.onPick(picked.index, picked.point, event);
    });
    const signal = this.listening.signal;
    window.addEventListener(
      'resize',
      () => {
        this.view.resize();
        if (this.strip) this.strip.draw();
      },
      { signal },
    );
    window.addEventListener('keydown', (event) => {
      if (event.target instanceof HTMLInputElement && event.target.type !== 'range' && event.target.type !== 'checkbox') return;
      if (event.target instanceof HTMLSelectElement) return;
      switch (event.key) {
        case ' ':
          this.togglePlay();
          break;
        case 'ArrowRight':
          this.step();
          break;
        case 'ArrowLeft':
          this.stepBack();
          break;
        case 'Home':
          this.pauseAndSeek(0);
          break;
        case 'End':
          this.pauseAndSeek(this.duration);
          break;
        case 'f':
        case 'F':
          this.fit('3d');
          return;
        case 't':
        case 'T':
          this.fit('top');
          return;
        case 'l':
        case 'L':
          this.setLabelsVisible(!this.labelsToggle.input.checked);
          return;
        case 'x':
        case 'X':
          this.setFocus(!this.view.focus);
          return;
        case 'g':
        case 'G':
          if (this.targets.length) this.setTargetsVisible(!this.targetsToggle.input.checked);
          return;
        case 'c':
        case 'C':
          this.setColouring(this.colourings.modes[(this.colourings.modes.indexOf(this.colourings.mode) + 1) % this.colourings.modes.length]);
          return;
        case 'Escape':
          this.select(-1);
          return;
        default:
          return;
      }
      event.preventDefault();
    }, { signal });
  }

  // The same modules with more of their run (the studio's live run, as it grows): the bars are
  // made again for the new duration; the 3D view, its camera and the selection stay.
  extend(trace) {
    const holder = this.canvasHolder;
    this.trace = trace;
    this.timeline = new Timeline(trace);
    this.colourings = new Colourings(trace, this.timeline, this.loads);
    this.duration = trace.duration;
    this.view.timeline = this.timeline;
    this.strip = null;
    this.root.replaceChildren();
    this.buildDom();
    this.root.replaceChild(holder, this.canvasHolder);
    this.canvasHolder = holder;
    this.overlayToggle.wrapper.hidden = !this.overlay;
    if (this.strip) this.strip.draw();
  }

  // Ends the app: its listeners on the window, its animation loop and its renderer.
  dispose() {
    this.disposed = true;
    this.listening.abort();
    this.view.renderer.dispose();
  }

  // Where the camera looks from, to keep it across apps (the studio's).
  cameraState() {
    return { position: this.view.camera.position.clone(), target: this.view.controls.target.clone() };
  }

  setCameraState(state) {
    this.view.camera.position.copy(state.position);
    this.view.controls.target.copy(state.target);
    this.view.controls.update();
    this.redraw();
  }

  // Shows the picture at trace time t (clamped to the trace), computed from the trace alone.
  seek(t) {
    this.time = Math.min(this.duration, Math.max(0, t));
    this.redraw();
    if (!this.playing) this.updateFragment();
  }

  // "motions to the goal: [0] [1] ... [9] [10-31]  [path]": the colours of the distance cubes,
  // shown while they are.
  buildDistanceLegend() {
    const line = element('div', { className: 'dv-distances' });
    const distances = this.overlay?.distances ?? [];
    const path = this.overlay?.path ?? [];
    line.hidden = distances.length === 0 && path.length === 0;
    if (line.hidden) return line;
    if (distances.length > 0) {
      const max = distances.reduce((m, d) => Math.max(m, d[3]), 0);
      line.append(element('span', { text: 'motions to the goal:' }));
      for (const entry of distanceLegend(max)) {
        const swatch = element('span', { className: 'dv-distance', text: entry.label, title: entry.title });
        swatch.style.background = entry.background;
        swatch.style.color = entry.dark ? '#fff' : '#1d2430';
        line.append(swatch);
      }
    }
    if (path.length > 0) {
      const swatch = element('span', { className: 'dv-path-swatch' });
      swatch.style.background = rgbToCss(PATH_COLOR);
      line.append(element('span', { className: 'dv-path' }, [swatch, document.createTextNode(`path, ${path.length - 1} motions`)]));
    }
    return line;
  }

  setOverlayVisible(on) {
    this.overlayToggle.input.checked = on;
    this.view.setOverlayVisible(on);
    this.distanceLine.hidden = !on || !this.overlay;
    this.view.render();
  }

  setLabelsVisible(on) {
    this.labelsToggle.input.checked = on;
    this.view.setLabelsVisible(on);
    this.view.render();
    this.updateFragment();
  }

  // Frames the scene from the front ('3d') or the top, clear of the captions at the top.
  fit(view = '3d') {
    this.viewName = view === 'top' ? 'top' : '3d';
    const captions = this.top.offsetTop + this.top.offsetHeight + 8;
    this.view.fit(this.viewName === 'top' ? 'top' : 'front', { reservedTop: captions });
    this.updateFragment();
  }

  // Opens at what a URL fragment names; what it does not name stays as it is.
  applyFragment(settings) {
    if (settings.labels !== undefined) this.setLabelsVisible(settings.labels);
    if (settings.colours !== undefined) this.setColouring(settings.colours);
    if (settings.select !== undefined) this.select(this.timeline.indexOfId.get(settings.select) ?? -1);
    this.fit(settings.view ?? this.viewName);
    if (settings.t !== undefined) this.pauseAndSeek(settings.t);
  }

  // The address bar names the moment shown (without a new history entry), so that a link to the
  // page opens there; not while playing.
  updateFragment() {
    if (this.playing || !this.view) return;
    const index = this.selectedIndex ?? -1;
    const fragment = formatFragment({
      t: this.time,
      view: this.viewName,
      select: index >= 0 ? this.trace.header.modules[index].id : null,
      labels: this.labelsToggle.input.checked,
      shadows: this.shadows,
      video: this.videoMode,
      colours: this.colourings.mode,
    });
    if (window.location.hash !== fragment) window.history.replaceState(null, '', fragment);
  }

  // A scene's video turns the camera around the scene, `degrees` from the fitted view, about the
  // vertical axis through the point it looks at. Every angle is a picture of its own.
  videoTurn(degrees) {
    const camera = this.view.camera;
    const target = this.view.controls.target;
    if (!this.turnStart) this.turnStart = camera.position.clone().sub(target);
    const angle = (degrees * Math.PI) / 180;
    const [x, y] = [this.turnStart.x, this.turnStart.y];
    camera.position.set(
      target.x + x * Math.cos(angle) - y * Math.sin(angle),
      target.y + x * Math.sin(angle) + y * Math.cos(angle),
      target.z + this.turnStart.z,
    );
    this.view.controls.update();
    this.view.render();
    return `turn=${degrees}`;
  }

  // Shows trace time t and names the picture: frames with the same name look the same (nothing
  // turns or strokes, the same changes applied, the same captions), so a video encodes it once
  // and the page does not draw it again (drawing is what a software renderer spends its time on).
  videoFrame(t) {
    const time = Math.min(this.duration, Math.max(0, t));
    const frame = this.timeline.frameAt(time);
    const stroking = (fraction) => fraction > 0 && fraction < 1;
    const animating = frame.modules.some(
      (m) => m.moving || stroking(m.fraction) || m.otherPistons.some((o) => stroking(o.fraction)),
    );
    const captions = [
      time.toFixed(1),
      frame.motions.map((m) => m.m).join(','),
      frame.note ? `${frame.note.t}:${frame.note.text}` : '',
    ];
    const key = animating ? `t=${time}` : `${frame.applied}|${captions.join('|')}`;
    if (key !== this.lastVideoKey) this.pauseAndSeek(time);
    this.lastVideoKey = key;
    return key;
  }

  redraw() {
    const frame = this.timeline.frameAt(this.time);
    this.frame = frame;
    this.colourings.prepare(frame);
    this.view.colouring = this.colourings.hook();
    this.marks.update(this.colourings.overloadedPoints());
    this.view.update(frame);
    this.view.render();
    this.slider.value = String(this.time);
    this.timeLabel.textContent = `${formatTime(this.time)} / ${formatTime(this.duration)}`;
    this.clockLine.textContent = `t = ${this.time.toFixed(1)} s of ${this.duration.toFixed(1)} s`;
    this.noteLine.textContent = frame.note ? `${formatTime(frame.note.t)}: ${frame.note.text}` : '';
    if (this.strip) {
      this.strip.setTime(this.time);
      const n = frame.motions.length;
      this.motionLine.textContent =
        `${n} motion${n === 1 ? '' : 's'} in flight (max ${this.timeline.motionIndex.max})` +
        (n ? `: ${mobileList(frame.motions)}` : '');
    }
    this.updateTargetLegend();
    this.updatePanel();
  }

  // "target: N cells, M filled" at the current time, for the shape shown.
  updateTargetLegend() {
    const fill = this.view.targetFill;
    if (!fill) return;
    const which = this.targets.length > 1 ? ` ${this.targetShape + 1} of ${this.targets.length}` : '';
    this.targetText.textContent = `target${which}: ${fill.cells} cells,`;
    this.filledText.textContent = `${fill.filled} filled`;
  }

  setTargetsVisible(on) {
    this.targetsToggle.input.checked = on;
    this.view.setTargetsVisible(on);
    this.view.render();
  }

  setTargetShape(k) {
    if (!(k >= 0 && k < this.targets.length)) return;
    this.targetShape = k;
    this.targetSelect.value = String(k);
    this.view.setTargetShape(k);
    this.redraw();
  }

  setFocus(on) {
    this.focusToggle.input.checked = on;
    this.view.focus = on;
    this.redraw();
  }

  pauseAndSeek(t) {
    this.pause();
    this.seek(t);
  }

  step() {
    this.pause();
    const next = nextChangeTime(this.trace.changeTimes, this.time);
    if (next !== null) this.seek(next);
  }

  stepBack() {
    this.pause();
    const previous = previousChangeTime(this.trace.changeTimes, this.time);
    if (previous !== null) this.seek(previous);
  }

  play() {
    if (this.duration <= 0) return;
    if (this.time >= this.duration) this.seek(0);
    this.playing = true;
    this.lastWall = null;
    this.playButton.innerHTML = ICONS.pause;
  }

  pause() {
    const wasPlaying = this.playing;
    this.playing = false;
    this.playButton.innerHTML = ICONS.play;
    if (wasPlaying) this.updateFragment();
  }

  togglePlay() {
    if (this.playing) this.pause();
    else this.play();
  }

  tick(now) {
    if (this.disposed) return;
    if (this.playing) {
      if (this.lastWall !== null) {
        const next = this.time + ((now - this.lastWall) / 1000) * this.speed;
        if (next >= this.duration) {
          this.seek(this.duration);
          this.pause();
        } else {
          this.seek(next);
        }
      }
      this.lastWall = now;
    }
    requestAnimationFrame(this.tick);
  }

  select(index) {
    this.selectedIndex = index;
    this.view.select(index);
    this.redraw();
    this.updateFragment();
  }

  updatePanel() {
    const index = this.selectedIndex ?? -1;
    if (index < 0) {
      this.panel.hidden = true;
      return;
    }
    fillPanel(this.panel, {
      frame: this.frame,
      index,
      catoms: this.catoms,
      timeline: this.timeline,
      extraRows: this.colourings.panelRows(this.frame.modules[index]),
      closeButton: button('close', 'Deselect (Esc)', () => this.select(-1)),
    });
    this.panel.hidden = false;
  }

  // The colouring shown: 'own', 'loads' or 'energy' (those the page has).
  setColouring(mode) {
    this.colourings.setMode(mode);
    this.redraw();
    this.updateFragment();
  }

  // What the end-to-end test and the console can drive (api.js).
  api() {
    return viewerApi(this);
  }
}
