// The viewer's bars and legends (the DOM around the 3D view): what App.buildDom makes, for a
// trace's duration, and makes again when the studio's live run grows (App.extend).
import { PART_SCHEMES, PATH_COLOR, TARGET_EMPTY, TARGET_FILLED, distanceLegend, rgbToCss } from './colors.js';
import { formatSeconds } from './format.js';
import { element } from './panel.js';
import { ConcurrencyStrip } from './strip.js';

export const SPEEDS = [0.1, 0.25, 0.5, 1, 2, 4, 8, 16, 32];

export function button(label, title, onClick) {
  const b = element('button', { type: 'button', title, 'aria-label': title });
  if (ICONS[label]) b.innerHTML = ICONS[label];
  else b.textContent = label;
  b.addEventListener('click', onClick);
  return b;
}

// Transport icons as inline SVG: system fonts often lack the media control characters.
export const ICONS = {
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
export function mobileList(motions, limit = 12) {
  const ids = motions.slice(0, limit).map((m) => String(m.m));
  if (motions.length > limit) ids.push('\u2026');
  return ids.join(', ');
}

// The title, the legends, the panel, the help line and the transport bar of `app`, around its
// canvas holder.
export function buildAppDom(app) {
  const header = app.trace.header;
  app.canvasHolder = element('div', { className: 'dv-canvas' });
  const title = header.description || 'datomsim trace';
  app.noteLine = element('div', { className: 'dv-note' });
  app.noteLine.hidden = app.duration <= 0;
  // Motions in flight (when the trace has "motion" lines) and the target legend.
  app.motionLine = element('div', { className: 'dv-motions' });
  app.targets = app.trace.targets;
  app.targetShape = 0;
  // "[empty] target: N cells, [filled] M filled": each count after the colour of its balls.
  app.targetText = element('span');
  app.filledText = element('span');
  const empty = element('span', { className: 'dv-swatch dv-target-swatch', title: 'a target cell no module holds' });
  empty.style.background = rgbToCss(TARGET_EMPTY);
  const filled = element('span', { className: 'dv-swatch dv-target-swatch', title: 'a target cell a module holds' });
  filled.style.background = rgbToCss(TARGET_FILLED);
  app.targetLine = element('div', { className: 'dv-target' }, [empty, app.targetText, filled, app.filledText]);
  app.targetLine.hidden = app.targets.length === 0;
  app.distanceLine = app.buildDistanceLegend();
  // Video mode has no time slider: the time is a caption, to a tenth of a second.
  app.clockLine = element('div', { className: 'dv-clock' });
  app.clockLine.hidden = !app.videoMode || app.duration <= 0;
  app.top = element('div', { className: 'dv-top' }, [
    element('div', { className: 'dv-title', text: title }),
    app.clockLine,
    element('div', {
      className: 'dv-subtitle',
      text:
        (app.catoms
          ? `${header.modules.length} 3D Catoms, r = ${header.dimensions.r}`
          : `${header.modules.length} modules, r = ${header.dimensions.r}, t = ${header.dimensions.t ?? 0}`) +
        (app.duration > 0 ? `, ${formatTime(app.duration)}` : ', scene (no changes)'),
    }),
    app.distanceLine,
    app.colourings.legend,
    app.targetLine,
    app.motionLine,
    app.noteLine,
  ]);

  // Playback controls.
  app.playButton = button('play', 'Play / pause (space)', () => app.togglePlay());
  app.slider = element('input', {
    type: 'range',
    min: '0',
    max: String(app.duration),
    step: 'any',
    value: '0',
    className: 'dv-slider',
    'aria-label': 'time',
  });
  app.slider.addEventListener('input', () => {
    app.pause();
    app.seek(Number(app.slider.value));
  });
  app.timeLabel = element('span', { className: 'dv-time' });
  app.speedSelect = element('select', { title: 'Playing speed (trace seconds per second)', className: 'dv-speed' });
  for (const s of SPEEDS) {
    const option = element('option', { value: String(s), text: `${s}\u00D7` });
    if (s === 1) option.selected = true;
    app.speedSelect.appendChild(option);
  }
  app.speedSelect.addEventListener('change', () => {
    app.speed = Number(app.speedSelect.value);
  });

  const markers = element('div', { className: 'dv-markers' });
  if (app.duration > 0) {
    for (const note of app.trace.notes) {
      const tick = element('div', { className: 'dv-marker', title: `${formatTime(note.t)}: ${note.text}` });
      tick.style.left = `${(100 * note.t) / app.duration}%`;
      markers.appendChild(tick);
    }
  }
  const sliderCell = element('div', { className: 'dv-slider-cell' }, [app.slider, markers]);
  const sliderBox = element('div', { className: 'dv-slider-box' }, [sliderCell, element('span')]);
  // The concurrency strip, when the trace has motion lines.
  if (app.trace.motions.length > 0 && app.duration > 0) {
    app.strip = new ConcurrencyStrip(app.timeline.motionIndex, app.trace.refusals, app.duration, (t) =>
      app.pauseAndSeek(t),
    );
    sliderBox.append(app.strip.element, app.strip.label);
    app.root.classList.add('dv-has-strip');
  }
  app.motionLine.hidden = !app.strip;

  app.labelsToggle = checkbox('labels', false, (on) => app.setLabelsVisible(on));
  app.overlayToggle = checkbox('distances', true, (on) => app.setOverlayVisible(on));
  app.focusToggle = checkbox('focus', false, (on) => {
    app.view.focus = on;
    app.redraw();
  });
  app.focusToggle.wrapper.title = app.catoms
    ? 'Fade every module but the selected one and those moving (X)'
    : 'Fade every module but the selected one and those deforming or moving (X)';
  app.latchesToggle = checkbox('latches', false, (on) => {
    app.view.showLatches = on;
    app.redraw();
  });
  app.targetsToggle = checkbox('target', true, (on) => app.setTargetsVisible(on));
  app.targetsToggle.wrapper.title = 'Show the target cells (G)';
  app.targetsToggle.wrapper.hidden = app.targets.length === 0;
  app.targetSelect = element('select', { title: 'Which target shape to show and count' });
  app.targets.forEach((shape, k) => {
    app.targetSelect.appendChild(element('option', { value: String(k), text: `target ${k + 1} of ${app.targets.length}` }));
  });
  app.targetSelect.hidden = app.targets.length < 2;
  app.targetSelect.addEventListener('change', () => app.setTargetShape(Number(app.targetSelect.value)));
  app.schemeSelect = element('select', { title: 'Connector colour: red as in the paper, or a dark tint of the module' });
  for (const scheme of PART_SCHEMES) {
    app.schemeSelect.appendChild(element('option', { value: scheme, text: `connectors: ${scheme === 'paper' ? 'red' : 'tint'}` }));
  }
  app.schemeSelect.addEventListener('change', () => {
    app.view.scheme = app.schemeSelect.value;
    app.redraw();
  });
  // A Catom's connectors are always a darker shade of its colour.
  app.schemeSelect.hidden = app.catoms;
  app.colourings.select.addEventListener('change', () => app.setColouring(app.colourings.select.value));

  const disabled = app.duration <= 0;
  const transport = [
    button('start', 'Start (Home)', () => app.pauseAndSeek(0)),
    button('back', 'Previous change (\u2190)', () => app.stepBack()),
    app.playButton,
    button('step', 'Next change (\u2192)', () => app.step()),
    button('end', 'End (End)', () => app.pauseAndSeek(app.duration)),
  ];
  if (disabled) {
    for (const b of transport) b.disabled = true;
    app.slider.disabled = true;
  }
  app.bar = element('div', { className: 'dv-bar' }, [
    element('div', { className: 'dv-transport' }, transport),
    sliderBox,
    app.timeLabel,
    app.speedSelect,
    element('div', { className: 'dv-toggles' }, [
      app.labelsToggle.wrapper,
      app.overlayToggle.wrapper,
      app.targetsToggle.wrapper,
      app.targetSelect,
      app.latchesToggle.wrapper,
      app.focusToggle.wrapper,
      app.schemeSelect,
      app.colourings.select,
      button('fit', 'Fit the scene (F)', () => app.fit('3d')),
      button('top', 'Seen from the top, as the paper\'s distance maps (T)', () => app.fit('top')),
    ]),
  ]);

  app.panel = element('div', { className: 'dv-panel' });
  app.panel.hidden = true;
  app.help = element('div', {
    className: 'dv-help',
    text: 'drag: orbit \u00B7 right-drag: pan \u00B7 wheel: zoom \u00B7 click: module \u00B7 space: play \u00B7 \u2190 \u2192: step \u00B7 F: fit \u00B7 T: top \u00B7 L: labels \u00B7 X: focus' +
      (app.trace.targets.length ? ' \u00B7 G: target' : '') +
      (app.colourings.modes.length > 1 ? ' \u00B7 C: colours' : ''),
  });
  app.root.append(app.canvasHolder, app.top, app.panel, app.help, app.bar);
}

// "motions to the goal: [0] [1] ... [9] [10-31]  [path]": the colours of the distance cubes,
// shown while they are.
export function buildDistanceLegend(app) {
  const line = element('div', { className: 'dv-distances' });
  const distances = app.overlay?.distances ?? [];
  const path = app.overlay?.path ?? [];
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
