import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { describe, it } from 'node:test';
import { fileURLToPath } from 'node:url';
import {
  ENERGY_RAMP,
  EnergyAccount,
  LoadsError,
  SAFETY_BANDS,
  checkLoads,
  energyColor,
  formatSi,
  latchLoadAt,
  pairKey,
  safetyColor,
} from '../src/colouring.js';
import { Timeline } from '../src/timeline.js';
import { TraceError, parseTrace } from '../src/trace.js';
import { fixtureText, module, syntheticTrace } from './fixtures/synthetic.js';

const repository = join(dirname(fileURLToPath(import.meta.url)), '..', '..');

const ACTUATORS = {
  name: 'test',
  compress_J: 0.2,
  release_J: 0.05,
  latch_J: 0.01,
  unlatch_J: 0.004,
  holding_W: 0.002,
  latch_s: 0.5,
  unlatch_s: 0.25,
};

function indexOf(trace) {
  return new Map(trace.header.modules.map((m, index) => [m.id, index]));
}

describe('latch safety colours', () => {
  it('are the bands of the safety maps (render::safetyBands)', () => {
    const source = readFileSync(join(repository, 'src', 'render', 'value_map.cpp'), 'utf8');
    const body = source.slice(source.indexOf('std::vector<ValueBand> safetyBands()'));
    const table = body.slice(0, body.indexOf('}};') + 3);
    const rows = [...table.matchAll(/\{([^{},]+), \{(\d+), (\d+), (\d+)\}, "([^"]+)"\}/g)];
    assert.equal(rows.length, SAFETY_BANDS.length);
    rows.forEach((row, k) => {
      assert.deepEqual(SAFETY_BANDS[k].rgb, row.slice(2, 5).map(Number), row[5]);
      assert.equal(SAFETY_BANDS[k].label, row[5]);
      const bound = row[1].trim();
      if (/^[\d.]+$/.test(bound)) assert.equal(SAFETY_BANDS[k].bound, Number(bound));
    });
  });

  it('put a safety factor in the first band it is below; no load in the last', () => {
    assert.deepEqual(safetyColor(0.3), [200, 0, 0], 'overloaded');
    assert.deepEqual(safetyColor(0.999), [200, 0, 0]);
    assert.deepEqual(safetyColor(1), [245, 110, 30], 'exactly 1 holds');
    assert.deepEqual(safetyColor(7), [170, 220, 110]);
    assert.deepEqual(safetyColor(1e9), [40, 110, 150]);
    assert.deepEqual(safetyColor(null), [215, 215, 215]);
  });
});

describe('energy colours', () => {
  it('run from pale at nothing spent to dark at the most, darker as the energy grows', () => {
    assert.deepEqual(energyColor(0, 2), ENERGY_RAMP[0]);
    assert.deepEqual(energyColor(2, 2), ENERGY_RAMP[ENERGY_RAMP.length - 1]);
    assert.deepEqual(energyColor(5, 2), ENERGY_RAMP[ENERGY_RAMP.length - 1], 'clamped');
    assert.deepEqual(energyColor(1, 0), ENERGY_RAMP[0], 'nothing spent anywhere');
    const luminance = ([r, g, b]) => 0.2126 * r + 0.7152 * g + 0.0722 * b;
    let previous = Infinity;
    for (let k = 0; k <= 40; ++k) {
      const l = luminance(energyColor(k / 40, 1));
      assert.ok(l < previous, `darker at ${k / 40}`);
      previous = l;
    }
  });

  it('write energies and forces with SI prefixes', () => {
    assert.equal(formatSi(0.00123, 'J'), '1.23 mJ');
    assert.equal(formatSi(4.56e-7, 'N m'), '456 nN m');
    assert.equal(formatSi(2.5, 'J'), '2.5 J');
    assert.equal(formatSi(0, 'J'), '0 J');
    assert.equal(formatSi(null, 'J'), 'none');
  });
});

describe('energy spent', () => {
  // Modules 1 and 2 latched to each other from the start (one pair); module 3 alone.
  const modules = [
    module(1, [0, 0, 0], { latches: 1 << 0 }),
    module(2, [1, 0, 0], { latches: 1 << 6 }),
    module(3, [5, 5, 0]),
  ];
  const events = [
    { t: 1, piston: { m: 3, p: 0, from: 0, to: 1, d: 2 } },
    { t: 3, piston: { m: 3, p: 0, from: 1, to: 0, d: 1 } },
    { t: 4, latch: { a: 1, ca: 0, b: 2, cb: 6, on: false } },
    { t: 6, latch: { a: 1, ca: 0, b: 2, cb: 6, on: true } },
  ];
  const trace = parseTrace(syntheticTrace({ modules, events, header: { actuators: ACTUATORS } }));
  const energy = new EnergyAccount(trace, indexOf(trace));
  const close = (actual, expected, what) => assert.ok(Math.abs(actual - expected) < 1e-12, `${what}: ${actual} vs ${expected}`);

  it('charges a piston move evenly over its duration, to the module that moves it', () => {
    close(energy.at(0.5)[2], 0, 'before');
    close(energy.at(2)[2], 0.1, 'half a compression');
    close(energy.at(3)[2], 0.2, 'a compression');
    close(energy.at(3.5)[2], 0.225, 'and half a release');
  });

  it('charges a latched pair its holding power and its changes, half to each module', () => {
    // Holding: one pair from 0 to 4 and from 6 on: 0.001 W to each module.
    close(energy.at(2)[0], 0.002, 'holding');
    // At 4.25: holding 0.004, half the unlatching (over 0.25 s) 0.002.
    close(energy.at(4.25)[0], 0.004 + 0.002, 'unlatching');
    // At 5.75: the latching runs from 5.5 to 6; half of it drawn, half to each module: 0.0025.
    close(energy.at(5.75)[1], 0.004 + 0.002 + 0.0025, 'latching');
    close(energy.at(6)[1], 0.004 + 0.002 + 0.005, 'latched again');
    assert.equal(energy.end, 6);
    assert.deepEqual(energy.at(6), energy.at(energy.end));
    close(energy.max, 0.25, 'the most a module spends: module 3');
  });

  it('is refused when the header\'s figures are not numbers >= 0', () => {
    const bad = { ...ACTUATORS, holding_W: -1 };
    assert.throws(
      () => parseTrace(syntheticTrace({ modules, header: { actuators: bad } })),
      (error) => error instanceof TraceError && /"actuators.holding_W" must be a number >= 0, not -1/.test(error.message),
    );
    assert.throws(() => parseTrace(syntheticTrace({ modules, header: { actuators: [] } })), /"actuators" must be an object/);
  });
});

describe('latch loads', () => {
  const trace = parseTrace(fixtureText());
  const timeline = new Timeline(trace);
  const start = timeline.frameAt(0);
  // A document with every latched pair of the start, safety growing with the pair's order.
  const pairs = [];
  const seen = new Set();
  for (const m of start.modules) {
    for (let c = 0; c < 12; ++c) {
      const partner = timeline.latchPartner(start, m.index, c);
      if (!(m.latches & (1 << c)) || !partner || seen.has(pairKey(m.id, partner.m))) continue;
      seen.add(pairKey(m.id, partner.m));
      pairs.push([m.id, partner.m]);
    }
  }
  const doc = {
    file: 'loads.json',
    latch_force_n: 1,
    latch_moment_n_m: 0.01,
    overloaded: 1,
    latches: pairs.map(([a, b], k) => [a, b, 0.01, 1e-6, k === 0 ? 0.5 : k === 1 ? null : 10 + k]),
  };

  it('are read from the page\'s document and counted', () => {
    const loads = checkLoads(doc, trace.header);
    assert.equal(loads.byPair.size, pairs.length);
    assert.equal(loads.overloaded, 1);
    assert.equal(loads.byPair.get(pairKey(pairs[0][1], pairs[0][0])).safety, 0.5, 'either order of the pair');
  });

  it('are refused, naming the file and the entry, when they do not fit the trace', () => {
    const refused = (change, pattern) =>
      assert.throws(
        () => checkLoads({ ...doc, ...change }, trace.header),
        (error) => error instanceof LoadsError && error.message.startsWith('loads.json: ') && pattern.test(error.message),
        JSON.stringify(change).slice(0, 80),
      );
    refused({ latches: [[1, 99999, 0, 0, 1]], overloaded: 0 }, /latches\[0\]: module 99999 is not in the scene/);
    refused({ latches: [doc.latches[2], doc.latches[2]], overloaded: 0 }, /latches\[1\]: latch .* is listed twice/);
    refused({ latches: [[1, 2, -1, 0, 1]] }, /latches\[0\] is \[1,2,-1,0,1\], not \[a,b,force,moment,safety\]/);
    refused({ latches: 'many' }, /"latches" is not a list/);
    refused({ latch_force_n: 0 }, /"latch_force_n" is not a positive number/);
    refused({ overloaded: 3 }, /"overloaded" is 3, the latches say 1/);
    assert.throws(() => checkLoads(null, trace.header), /the loads: the loads are not an object/);
  });

  it('hold at the start and go stale once a module of the latch has moved', () => {
    const loads = checkLoads(doc, trace.header);
    const [a, b] = pairs[0];
    const index = timeline.indexOfId.get(a);
    const connector = [...Array(12).keys()].find((c) => timeline.latchPartner(start, index, c)?.m === b);
    const atStart = latchLoadAt(loads, start, index, connector, timeline, trace.header);
    assert.equal(atStart.stale, false);
    assert.equal(atStart.load.safety, 0.5);
    // At the end the mobile has left its cell: each of its latches is stale, the others hold.
    const end = timeline.frameAt(trace.duration);
    const mobile = end.modules.find((m) => m.cell.join() !== trace.header.modules[m.index].cell.join());
    assert.ok(mobile, 'the run moves a module');
    let stale = 0;
    for (let c = 0; c < 12; ++c) {
      const at = latchLoadAt(loads, end, mobile.index, c, timeline, trace.header);
      if (at) stale += at.stale ? 1 : 0;
    }
    assert.ok(stale > 0, 'the mobile\'s latches are stale');
    const still = end.modules.find((m) => m.index === index && !m.inTransit);
    if (still && still.cell.join() === trace.header.modules[index].cell.join() && end.modules[timeline.indexOfId.get(b)].cell.join() === trace.header.modules[timeline.indexOfId.get(b)].cell.join()) {
      const at = latchLoadAt(loads, end, index, connector, timeline, trace.header);
      if (at) assert.equal(at.stale, false);
    }
  });
});

describe('the address of a colouring', () => {
  it('names a colouring other than the modules\' own, and reads it back', async () => {
    const { formatFragment, parseFragment } = await import('../src/fragment.js');
    assert.equal(formatFragment({ t: 1, colours: 'loads' }), '#t=1&view=3d&colours=loads');
    assert.equal(formatFragment({ t: 1 }), '#t=1&view=3d', 'nothing for the own colours');
    assert.equal(parseFragment('#t=2&colours=energy').colours, 'energy');
    assert.equal(parseFragment('#colours=heat').colours, undefined, 'an unknown colouring is ignored');
  });
});
