// The viewer application: controls, playback and the module panel around a View3D.
//
// Playback only maps wall-clock time to trace time (times the speed); each picture is
// timeline.frameAt(t), so the speed, pauses and seeks never change what is shown at a given t.
import { viewerApi } from './api.js';
import { ICONS, buildAppDom, buildDistanceLegend, button, formatTime, mobileList } from './app_bars.js';
import { installAppInput } from './app_input.js';
import { Colourings } from './colourings.js';
import { formatFragment, parseFragment } from './fragment.js';
import { Kinematics } from './kinematics.js';
import { OverloadMarks } from './latch_marks.js';
import { fillPanel } from './panel.js';
import { Timeline } from './timeline.js';
import { CATOM3D, DATOM, nextChangeTime, previousChangeTime } from './trace.js';
import { View3D } from './view3d.js';

export { SPEEDS, formatTime } from './app_bars.js';

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
    buildAppDom(this);
  }

  installInput() {
    installAppInput(this);
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

  buildDistanceLegend() {
    return buildDistanceLegend(this);
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
