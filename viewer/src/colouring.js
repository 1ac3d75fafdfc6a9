// The two colourings beyond the modules' own colours (docs/viewer.md): latches by their load under
// gravity (the loads `datomsim loads` computed for the trace's start) and modules by the energy
// their actuators spent up to the time shown (the header's "actuators" and the trace's piston and
// latch lines). Plain data and arithmetic, no drawing: the unit tests hold them to the C++.
import { mixRgb } from './colors.js';

export class LoadsError extends Error {}

// The safety factor bands of the safety maps (render::safetyBands, src/render/value_map.cpp): a
// latch takes the first band whose bound its safety factor is below; no load (null) is the last.
export const SAFETY_BANDS = [
  { bound: 1, rgb: [200, 0, 0], label: 'below 1: overloaded' },
  { bound: 1.5, rgb: [245, 110, 30], label: '1 to 1.5' },
  { bound: 2, rgb: [250, 190, 40], label: '1.5 to 2' },
  { bound: 5, rgb: [250, 240, 120], label: '2 to 5' },
  { bound: 10, rgb: [170, 220, 110], label: '5 to 10' },
  { bound: 100, rgb: [70, 170, 90], label: '10 to 100' },
  { bound: Number.MAX_VALUE, rgb: [40, 110, 150], label: '100 and more' },
  { bound: Infinity, rgb: [215, 215, 215], label: 'no load' },
];

// A latch whose loads no longer hold: one of its modules has left its cell of the start, or the
// pair was not latched then.
export const STALE_LATCH = [70, 70, 78];
// The modules' body while latches are coloured: light and grey, so that the latches stand out.
export const LOADS_BODY = [188, 192, 200];

export function safetyBand(safety) {
  const value = safety === null || safety === undefined ? Infinity : safety;
  return SAFETY_BANDS.findIndex((band) => value < band.bound || band.bound === Infinity);
}

export function safetyColor(safety) {
  return SAFETY_BANDS[safetyBand(safety)].rgb;
}

export function pairKey(a, b) {
  return a < b ? `${a}-${b}` : `${b}-${a}`;
}

function isCount(x) {
  return Number.isInteger(x) && x >= 0;
}

// Checks the page's loads document (export/loads_check.h writes it from `datomsim loads --out`)
// against the trace's header: every latch between two modules of the scene, each pair once.
// Returns {file, forceLimit, momentLimit, overloaded, byPair: Map pairKey -> {a, b, force,
// moment, safety}}. Errors name the file and the entry.
export function checkLoads(doc, header) {
  const name = doc && typeof doc.file === 'string' ? doc.file : 'the loads';
  const fail = (what) => {
    throw new LoadsError(`${name}: ${what}`);
  };
  if (!doc || typeof doc !== 'object' || Array.isArray(doc)) fail('the loads are not an object');
  for (const key of ['latch_force_n', 'latch_moment_n_m']) {
    if (!(Number.isFinite(doc[key]) && doc[key] > 0)) fail(`"${key}" is not a positive number`);
  }
  if (!Array.isArray(doc.latches)) fail('"latches" is not a list');
  const ids = new Set(header.modules.map((m) => m.id));
  const byPair = new Map();
  let overloaded = 0;
  doc.latches.forEach((entry, k) => {
    const ok =
      Array.isArray(entry) &&
      entry.length === 5 &&
      Number.isInteger(entry[0]) &&
      Number.isInteger(entry[1]) &&
      entry.slice(2, 4).every((x) => Number.isFinite(x) && x >= 0) &&
      (entry[4] === null || (Number.isFinite(entry[4]) && entry[4] >= 0));
    if (!ok) fail(`latches[${k}] is ${JSON.stringify(entry)}, not [a,b,force,moment,safety]`);
    const [a, b, force, moment, safety] = entry;
    for (const id of [a, b]) if (!ids.has(id)) fail(`latches[${k}]: module ${id} is not in the scene`);
    const key = pairKey(a, b);
    if (byPair.has(key)) fail(`latches[${k}]: latch ${a}-${b} is listed twice`);
    byPair.set(key, { a, b, force, moment, safety });
    if (safety !== null && safety < 1) ++overloaded;
  });
  if (doc.overloaded !== undefined && !(isCount(doc.overloaded) && doc.overloaded === overloaded)) {
    fail(`"overloaded" is ${JSON.stringify(doc.overloaded)}, the latches say ${overloaded}`);
  }
  return { file: name, forceLimit: doc.latch_force_n, momentLimit: doc.latch_moment_n_m, overloaded, byPair };
}

// Energy: a sequential ramp from pale (nothing spent) to dark (the most any module spends in the
// whole trace), so that colours fill up as the replay goes on and stay comparable across times.
export const ENERGY_RAMP = [
  [250, 248, 215],
  [253, 200, 100],
  [242, 120, 45],
  [190, 40, 60],
  [90, 15, 95],
];

export function energyColor(joules, max) {
  const x = max > 0 ? Math.min(1, Math.max(0, joules / max)) : 0;
  const scaled = x * (ENERGY_RAMP.length - 1);
  const k = Math.min(ENERGY_RAMP.length - 2, Math.floor(scaled));
  return mixRgb(ENERGY_RAMP[k], ENERGY_RAMP[k + 1], scaled - k);
}

// "1.23 mJ", "456 µJ", "2.5 J".
export function formatSi(value, unit) {
  if (value === null || value === undefined || !Number.isFinite(value)) return 'none';
  const prefixes = [
    [1, ''],
    [1e-3, 'm'],
    [1e-6, '\u00B5'],
    [1e-9, 'n'],
  ];
  const magnitude = Math.abs(value);
  if (magnitude === 0) return `0 ${unit}`;
  const [scale, prefix] = prefixes.find(([s]) => magnitude >= s) ?? prefixes[prefixes.length - 1];
  return `${Number((value / scale).toPrecision(3))} ${prefix}${unit}`;
}

// A module's energy at any time, as the C++ recorder accounts it (src/sim/energy.h): a piston move
// draws compress_J (towards compressed) or release_J evenly over its duration; a pair latching
// draws latch_J over the latching that ends at its latch line, letting go unlatch_J over the
// unlatching that starts at it, half to each module; each latched pair draws holding_W, half to
// each of its modules, from time 0 for the latches of the start. At the trace's end every move
// counts whole, as the run's report.
export class EnergyAccount {
  constructor(trace, indexOfId) {
    const a = trace.header.actuators;
    this.name = a.name ?? '';
    this.end = trace.duration;
    const n = trace.header.modules.length;
    this.ramps = Array.from({ length: n }, () => []); // [from, to, joules]
    this.holding = Array.from({ length: n }, () => []); // [from, to, watts]
    const ends = trace.header.modules.map((m) => popcount(m.latches ?? 0));
    const since = new Array(n).fill(0);
    const holdTo = (index, t) => {
      if (ends[index] > 0 && t > since[index]) this.holding[index].push([since[index], t, (a.holding_W / 2) * ends[index]]);
      since[index] = t;
    };
    for (const e of trace.events) {
      if (e.kind === 'piston') {
        const index = indexOfId.get(e.body.m);
        const joules = e.body.to > e.body.from ? a.compress_J : a.release_J;
        this.ramps[index].push([e.t, e.t + e.body.d, joules]);
      } else if (e.kind === 'latch') {
        const on = e.body.on;
        const joules = (on ? a.latch_J : a.unlatch_J) / 2;
        const ramp = on ? [Math.max(0, e.t - a.latch_s), e.t, joules] : [e.t, e.t + a.unlatch_s, joules];
        for (const id of [e.body.a, e.body.b]) {
          const index = indexOfId.get(id);
          holdTo(index, e.t);
          ends[index] += on ? 1 : -1;
          this.ramps[index].push(ramp);
        }
      }
    }
    for (let index = 0; index < n; ++index) {
      if (ends[index] > 0) this.holding[index].push([since[index], Infinity, (a.holding_W / 2) * ends[index]]);
    }
    this.max = Math.max(0, ...this.at(this.end));
  }

  // Joules each module (by index) has spent up to time t.
  at(t) {
    const whole = t >= this.end;
    return this.ramps.map((ramps, index) => {
      let joules = 0;
      for (const [from, to, j] of ramps) {
        if (whole || t >= to) joules += j;
        else if (t > from) joules += (j * (t - from)) / (to - from);
      }
      for (const [from, to, watts] of this.holding[index]) {
        const until = Math.min(t, to);
        if (until > from) joules += watts * (until - from);
      }
      return joules;
    });
  }
}

function popcount(mask) {
  let count = 0;
  for (let bits = mask; bits; bits &= bits - 1) ++count;
  return count;
}

// The modules' colour in loads mode and the colour of each of their connectors: latched ones by
// the safety factor of their latch while both modules are in their cells of the start, STALE_LATCH
// once either has moved (the loads are the start's); connectors not latched keep their colour.
export function latchLoadAt(loads, frame, index, connector, timeline, header) {
  const m = frame.modules[index];
  if (!(m.latches & (1 << connector))) return null;
  const partner = timeline.latchPartner(frame, index, connector);
  if (!partner) return { stale: true };
  const other = frame.modules[timeline.indexOfId.get(partner.m)];
  const atStart = (x) => !x.inTransit && sameCell(x.cell, header.modules[x.index].cell);
  const load = loads.byPair.get(pairKey(m.id, partner.m));
  if (!load || !atStart(m) || !atStart(other)) return { stale: true, partner: partner.m };
  return { stale: false, partner: partner.m, load };
}

function sameCell(a, b) {
  return a[0] === b[0] && a[1] === b[1] && a[2] === b[2];
}

export function lightened(rgb) {
  return mixRgb(rgb, [255, 255, 255], 0.25);
}
