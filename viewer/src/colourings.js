// The colourings a page offers besides the modules' own colours (docs/viewer.md): latches by load
// (a page made with `datomsim view --loads`) and modules by the energy spent (a trace of a run
// with --actuators). Its select in the control bar (key C cycles), its legend under the title, the
// colours View3D asks for, and the panel's rows.
import { partColor, rgbToCss } from './colors.js';
import {
  ENERGY_RAMP,
  EnergyAccount,
  LOADS_BODY,
  SAFETY_BANDS,
  STALE_LATCH,
  checkLoads,
  energyColor,
  formatSi,
  latchLoadAt,
  safetyBand,
  safetyColor,
} from './colouring.js';
import { formatSeconds } from './format.js';

// A connector not latched, while latches are coloured: a grey darker than the bodies.
const UNLATCHED = [140, 145, 154];

const NAMES = { own: 'colours: own', loads: 'colours: latch loads', energy: 'colours: energy spent' };

function span(className, text) {
  const node = document.createElement('span');
  if (className) node.className = className;
  if (text !== undefined) node.textContent = text;
  return node;
}

function swatch(rgb, title) {
  const node = span('dv-swatch');
  node.style.background = rgbToCss(rgb);
  if (title) node.title = title;
  return node;
}

export class Colourings {
  // loadsDoc: the page's loads document or null; throws LoadsError when it does not fit the trace.
  constructor(trace, timeline, loadsDoc) {
    this.trace = trace;
    this.timeline = timeline;
    this.header = trace.header;
    this.loads = loadsDoc ? checkLoads(loadsDoc, trace.header) : null;
    this.energy = trace.header.actuators ? new EnergyAccount(trace, timeline.indexOfId) : null;
    this.modes = ['own', ...(this.loads ? ['loads'] : []), ...(this.energy ? ['energy'] : [])];
    this.mode = 'own';
    this.select = document.createElement('select');
    this.select.title = 'Colour the modules by their own colours, the latches by load, or the modules by energy spent (C)';
    this.select.className = 'dv-colouring';
    for (const mode of this.modes) {
      const option = document.createElement('option');
      option.value = mode;
      option.textContent = NAMES[mode];
      this.select.appendChild(option);
    }
    this.select.hidden = this.modes.length < 2;
    this.legend = document.createElement('div');
    this.legend.className = 'dv-colour-legend';
    this.legend.hidden = true;
    this.frame = null;
    this.spent = null;
  }

  // The hook View3D calls while this colouring is on; null for the modules' own colours.
  hook() {
    if (this.mode === 'loads') {
      return {
        moduleRgb: () => LOADS_BODY,
        connectorRgb: (m, connector) => {
          const at = latchLoadAt(this.loads, this.frame, m.index, connector, this.timeline, this.header);
          if (!at) return UNLATCHED;
          return at.stale ? STALE_LATCH : safetyColor(at.load.safety);
        },
      };
    }
    if (this.mode === 'energy') {
      const rgb = (m) => energyColor(this.spent[m.index], this.energy.max);
      // Connectors a dark tint of the module's energy colour: the paper's red would read as heat.
      return { moduleRgb: rgb, connectorRgb: (m) => partColor('connector', rgb(m), 'tint') };
    }
    return null;
  }

  // Before the picture of `frame` is drawn: what the colours and the legend need at its time.
  prepare(frame) {
    this.frame = frame;
    if (this.mode === 'energy') this.spent = this.energy.at(frame.t);
    this.updateLegend();
  }

  setMode(mode) {
    this.mode = this.modes.includes(mode) ? mode : 'own';
    this.select.value = this.mode;
  }

  // The centres of the overloaded latches still in force, [x, y, z] each, in loads mode.
  overloadedPoints() {
    if (this.mode !== 'loads') return [];
    const points = [];
    for (const m of this.frame.modules) {
      for (let c = 0; c < 12; ++c) {
        const at = latchLoadAt(this.loads, this.frame, m.index, c, this.timeline, this.header);
        if (!at || at.stale || m.id > at.partner || !(at.load.safety !== null && at.load.safety < 1)) continue;
        const other = this.frame.modules[this.timeline.indexOfId.get(at.partner)];
        points.push([0, 1, 2].map((k) => (m.position.getComponent(k) + other.position.getComponent(k)) / 2));
      }
    }
    return points;
  }

  // Counts of the latches now: by band, stale, overloaded (only those still in force).
  latchCounts() {
    const byBand = new Array(SAFETY_BANDS.length).fill(0);
    let stale = 0;
    const overloaded = [];
    for (const m of this.frame.modules) {
      for (let c = 0; c < 12; ++c) {
        const at = latchLoadAt(this.loads, this.frame, m.index, c, this.timeline, this.header);
        if (!at || m.id > (at.partner ?? Infinity)) continue; // each pair once, from its lower id
        if (at.stale) ++stale;
        else {
          ++byBand[safetyBand(at.load.safety)];
          if (at.load.safety !== null && at.load.safety < 1) overloaded.push(`${at.load.a}-${at.load.b}`);
        }
      }
    }
    return { byBand, stale, overloaded };
  }

  updateLegend() {
    this.legend.hidden = this.mode === 'own';
    if (this.mode === 'loads') this.loadsLegend();
    else if (this.mode === 'energy') this.energyLegend();
  }

  // "latch safety factor (loads of the start, file): [below 1: overloaded] 2 ... [moved: stale] 5"
  loadsLegend() {
    const { byBand, stale, overloaded } = this.latchCounts();
    const file = this.loads.file.split('/').pop();
    const parts = [span('', `latch safety factor (${file}, the scene at the start):`)];
    SAFETY_BANDS.forEach((band, k) => {
      parts.push(span('dv-legend-item', ''));
      parts[parts.length - 1].append(swatch(band.rgb, band.label), `${band.label}: ${byBand[k]}`);
    });
    const staleItem = span('dv-legend-item', '');
    staleItem.append(swatch(STALE_LATCH, 'a module of the latch has moved since the start'), `moved since the start: ${stale}`);
    parts.push(staleItem);
    const alarm = span(overloaded.length ? 'dv-overloaded' : 'dv-ok');
    alarm.textContent = overloaded.length
      ? `${overloaded.length} overloaded: ${overloaded.slice(0, 8).join(', ')}${overloaded.length > 8 ? ', \u2026' : ''}`
      : 'none overloaded';
    parts.push(alarm);
    this.legend.replaceChildren(...parts);
  }

  // "energy spent by t = 3.2 s (actuators): [ramp] 0 ... 1.2 mJ; all modules 25 mJ"
  energyLegend() {
    const total = this.spent.reduce((sum, j) => sum + j, 0);
    const bar = span('dv-energy-bar');
    bar.style.background = `linear-gradient(to right, ${ENERGY_RAMP.map(rgbToCss).join(', ')})`;
    this.legend.replaceChildren(
      span('', `energy spent by ${formatSeconds(this.frame.t)} (${this.energy.name}):`),
      span('', '0'),
      bar,
      span('', `${formatSi(this.energy.max, 'J')} (the most a module spends by the end)`),
      span('dv-energy-total', `all modules: ${formatSi(total, 'J')}`),
    );
  }

  // The panel's rows for module `m` in the current mode.
  panelRows(m) {
    if (this.mode === 'energy') {
      return [['energy', `${formatSi(this.spent[m.index], 'J')} by now, of ${formatSi(this.energy.at(this.energy.end)[m.index], 'J')} by the end`]];
    }
    if (this.mode !== 'loads') return [];
    const rows = [];
    for (let c = 0; c < 12; ++c) {
      const at = latchLoadAt(this.loads, this.frame, m.index, c, this.timeline, this.header);
      if (!at) continue;
      if (at.stale) {
        rows.push(['load', `${c} \u2192 ${at.partner ?? '?'}: moved since the start`]);
        continue;
      }
      const { force, moment, safety } = at.load;
      rows.push([
        'load',
        `${c} \u2192 ${at.partner}: F ${formatSi(force, 'N')}, M ${formatSi(moment, 'N m')}, safety ${safety === null ? 'none (no load)' : Number(safety.toPrecision(3))}`,
      ]);
    }
    rows.push(['', `limits: ${formatSi(this.loads.forceLimit, 'N')}, ${formatSi(this.loads.momentLimit, 'N m')}`]);
    return rows;
  }

  // For the end-to-end test.
  state() {
    return {
      modes: this.modes.slice(),
      mode: this.mode,
      legend: this.legend.hidden ? null : this.legend.innerText.replace(/\s+/g, ' ').trim(),
      latches: this.mode === 'loads' ? this.latchCounts() : null,
      spent: this.mode === 'energy' ? Array.from(this.spent) : null,
      max: this.energy ? this.energy.max : null,
    };
  }
}
