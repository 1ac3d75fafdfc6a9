import assert from 'node:assert/strict';
import { describe, it } from 'node:test';
import {
  MODULE_KINDS,
  TraceError,
  checkOverlay,
  moduleKindOf,
  nextChangeTime,
  parseTrace,
  previousChangeTime,
  splitJsonValues,
} from '../src/trace.js';
import { WALKERS, fixtureText, module, syntheticTrace, walkersText } from './fixtures/synthetic.js';

describe('splitJsonValues', () => {
  it('reads one value per line and values spread over several lines', () => {
    const values = splitJsonValues('{"a":1}\n{"b":\n [1,\n 2]}\n\n{"c":"}{\\"x"}\n');
    assert.deepEqual(
      values.map((v) => [v.value, v.line]),
      [
        [{ a: 1 }, 1],
        [{ b: [1, 2] }, 2],
        [{ c: '}{"x' }, 6],
      ],
    );
  });

  it('names the line of a bad value', () => {
    assert.throws(() => splitJsonValues('{"a":1}\n{"b":}\n'), /line 2: invalid JSON/);
    assert.throws(() => splitJsonValues('{"a":1}\n\n{"b":[1}\n'), TraceError);
    assert.throws(() => splitJsonValues('{"a":1}\n42\n'), /line 2: expected a JSON object/);
    assert.throws(() => splitJsonValues('{"a":1}\n{"b":[1,2]\n'), /line 2: unterminated/);
  });
});

describe('parseTrace on a run of the simulator', () => {
  const trace = parseTrace(fixtureText());

  it('reads the header and its 130 modules', () => {
    assert.equal(trace.header.format, 'datomsim-trace');
    assert.equal(trace.header.modules.length, 130);
    assert.equal(trace.header.kinematics.rest.length, 43);
  });

  it('sorts changes by time, keeping the file order at equal times', () => {
    for (let k = 1; k < trace.events.length; ++k) {
      const a = trace.events[k - 1];
      const b = trace.events[k];
      assert.ok(a.t < b.t || (a.t === b.t && a.seq < b.seq), `events ${k - 1} and ${k} out of order`);
    }
  });

  it('lasts until the end of its last change', () => {
    const last = Math.max(...trace.events.map((e) => e.t + (e.body && e.body.d ? e.body.d : 0)));
    assert.equal(trace.duration, last);
    assert.ok(trace.end, 'the run has an end line');
  });

  it('steps through the starts and ends of changes', () => {
    const times = trace.changeTimes;
    assert.equal(times[0], 0);
    const firstTurn = trace.events.find((e) => e.kind === 'turn');
    assert.ok(times.includes(firstTurn.t));
    assert.ok(times.includes(firstTurn.t + firstTurn.body.d), 'the middle of a motion is a step');
    assert.equal(nextChangeTime(times, 0), times[1]);
    assert.equal(nextChangeTime(times, times[times.length - 1]), null);
    assert.equal(previousChangeTime(times, times[2]), times[1]);
    assert.equal(previousChangeTime(times, 0), null);
    assert.equal(nextChangeTime(times, (times[3] + times[4]) / 2), times[4]);
  });

  it('collects the notes for the timeline', () => {
    assert.ok(trace.notes.length >= 7);
    assert.match(trace.notes[0].text, /module 1 turns/);
  });
});

describe('parseTrace refusals', () => {
  const modules = [module(1, [0, 0, 0]), module(2, [1, 0, 0])];

  it('refuses a file that is not a trace', () => {
    assert.throws(() => parseTrace(''), /empty/);
    assert.throws(() => parseTrace('{"format":"datomsim-scene","version":1}\n'), /not a datomsim trace/);
    assert.throws(() => parseTrace(syntheticTrace({ modules, header: { version: 2 } })), /unsupported trace version 2/);
  });

  it('names the line and the module of a change about an unknown module', () => {
    const text = syntheticTrace({
      modules,
      events: [{ t: 0, note: 'hello' }, { t: 1, piston: { m: 7, p: 0, from: 0, to: 1, d: 1 } }],
    });
    assert.throws(() => parseTrace(text), /line 3: "piston" names unknown module 7/);
  });

  it('refuses bad values in changes', () => {
    const bad = [
      { t: -1, note: 'x' },
      { t: 0, piston: { m: 1, p: 6, from: 0, to: 1, d: 1 } },
      { t: 0, turn: { m: 1, axis: [0, 0], centre: [0, 0, 0], deg: 90, d: 1 } },
      { t: 0, place: { m: 1, pos: [0, 0, 0], o: 24 } },
      { t: 0, turn: { m: 1, axis: [0, 0, 1], centre: [0, 0, 0], deg: 90, d: 1, progress: [0] } },
    ];
    for (const event of bad) {
      assert.throws(() => parseTrace(syntheticTrace({ modules, events: [event] })), TraceError, JSON.stringify(event));
    }
  });

  it('ignores changes of a kind it does not know', () => {
    const trace = parseTrace(syntheticTrace({ modules, events: [{ t: 1, sparkle: { m: 1 } }] }));
    assert.equal(trace.events.length, 0);
  });
});

describe("the header's module kind", () => {
  const modules = [module(1, [0, 0, 0]), module(2, [1, 0, 0])];

  it('is the Datom when the header has no "module"', () => {
    const trace = parseTrace(syntheticTrace({ modules }));
    assert.equal('module' in trace.header, false);
    assert.equal(trace.module, 'datom');
    assert.equal(moduleKindOf(trace.header), 'datom');
  });

  it('reads "catom3d" and "datom"', () => {
    assert.deepEqual(MODULE_KINDS, ['datom', 'catom3d']);
    assert.equal(parseTrace(syntheticTrace({ modules, header: { module: 'catom3d' } })).module, 'catom3d');
    assert.equal(parseTrace(syntheticTrace({ modules, header: { module: 'datom' } })).module, 'datom');
  });

  it('refuses any other value, naming the field and the value', () => {
    const cases = [
      ['sphere', '"sphere"'],
      ['Catom3D', '"Catom3D"'],
      [3, '3'],
      [null, 'null'],
      [['catom3d'], '["catom3d"]'],
    ];
    for (const [value, written] of cases) {
      assert.throws(
        () => parseTrace(syntheticTrace({ modules, header: { module: value } })),
        (error) => {
          assert.ok(error instanceof TraceError, String(error));
          assert.equal(error.message, `line 1: "module" must be "datom" or "catom3d", not ${written}`);
          return true;
        },
        JSON.stringify(value),
      );
    }
  });
});

describe('overlays', () => {
  const modules = [module(1, [0, 0, 0])];

  it('reads distances and a path from the header', () => {
    const trace = parseTrace(
      syntheticTrace({ modules, header: { overlay: { goal: [1, 0, 1], distances: [[1, 0, 1, 0]], path: [[0, 0, 1], [1, 0, 1]] } } }),
    );
    assert.deepEqual(trace.overlay.distances, [[1, 0, 1, 0]]);
    assert.equal(trace.overlay.path.length, 2);
  });

  it('reads the top-level "distances" and "path" of a header too', () => {
    const trace = parseTrace(syntheticTrace({ modules, header: { distances: [[1, 0, 1, 3]] } }));
    assert.deepEqual(trace.overlay.distances, [[1, 0, 1, 3]]);
  });

  it('refuses malformed entries and treats an empty overlay as none', () => {
    assert.throws(() => checkOverlay({ distances: [[1, 2, 3]] }), /distances\[0\]/);
    assert.throws(() => checkOverlay({ path: [[1, 2]] }), /path\[0\]/);
    assert.throws(() => checkOverlay([1]), /not an object/);
    assert.equal(checkOverlay({ distances: [] }), null);
    assert.equal(checkOverlay(null), null);
  });
});

describe('motion lines', () => {
  const modules = [module(1, [0, 0, 1]), module(2, [0, 0, 0]), module(3, [1, 0, 0]), module(4, [2, 0, 0])];
  const motion = (over = {}) => ({ m: 1, pivot: 2, goal: [1, 0, 1], blockers: [3], end: 2, ...over });

  it('reads a motion line: who moves, about which pivot, to where, until when, who makes way', () => {
    const trace = parseTrace(
      syntheticTrace({
        modules,
        events: [
          { t: 0, note: 'module 1 turns left about pivot 2 (piston 4) towards 1,0,1' },
          { t: 0, motion: motion() },
          { t: 0.5, note: 'motion refused: module 4: cell 1,0,1 is reserved by the motion of module 1 (until 2 s)' },
          { t: 0.5, note: 'deformation refused: module 3 cannot compress piston 2' },
        ],
      }),
    );
    assert.deepEqual(trace.motions, [{ t: 0, end: 2, m: 1, pivot: 2, goal: [1, 0, 1], blockers: [3], line: 3 }]);
    assert.equal(trace.duration, 2, 'a motion lasts until its end');
    assert.ok(trace.changeTimes.includes(2));
    assert.deepEqual(trace.notes.map((n) => n.t), [0], 'the motion notes mark the timeline');
    assert.deepEqual(trace.refusals.map((n) => n.t), [0.5, 0.5], 'refusals are kept apart');
    assert.match(trace.refusals[0].text, /^motion refused: module 4/);
  });

  it('refuses bad motion lines, naming the line', () => {
    const bad = [
      [motion({ m: 9 }), /line 2: "motion" names unknown module 9 in "m"/],
      [motion({ pivot: 8 }), /line 2: "motion" names unknown module 8 in "pivot"/],
      [motion({ blockers: [3, 7] }), /line 2: "motion" names unknown module 7 in "blockers"/],
      [motion({ blockers: 3 }), /line 2: "motion" needs a list "blockers"/],
      [motion({ goal: [1, 0] }), /line 2: "motion" needs "goal"/],
      [motion({ goal: [1, 0.5, 1] }), /line 2: "motion" needs "goal"/],
      [motion({ goal: undefined }), /line 2: "motion" needs "goal"/],
      [motion({ end: 0.5 }), /line 2: "motion" needs an "end" time >= its "t"/],
      [motion({ end: '2' }), /line 2: "motion" needs an "end"/],
      [motion({ m: undefined }), /line 2: "motion" names unknown module undefined/],
    ];
    for (const [body, pattern] of bad) {
      const text = syntheticTrace({ modules, events: [{ t: 1, motion: body }] });
      assert.throws(() => parseTrace(text), pattern, JSON.stringify(body));
    }
    assert.throws(() => parseTrace(syntheticTrace({ modules, events: [{ t: 1, motion: 5 }] })), /line 2: "motion" must be an object/);
  });

  it('accepts a motion that ends when it starts', () => {
    const trace = parseTrace(syntheticTrace({ modules, events: [{ t: 1, motion: motion({ end: 1, blockers: [] }) }] }));
    assert.equal(trace.motions.length, 1);
  });
});

describe('target shapes in the header', () => {
  const modules = [module(1, [0, 0, 0])];

  it('reads a list of shapes, each a list of cells', () => {
    const targets = [[[0, 0, 0], [1, 0, 0]], [[5, 5, 1]]];
    const trace = parseTrace(syntheticTrace({ modules, header: { targets } }));
    assert.deepEqual(trace.targets, targets);
    assert.deepEqual(parseTrace(syntheticTrace({ modules })).targets, [], 'none when the header has none');
    assert.deepEqual(parseTrace(syntheticTrace({ modules, header: { targets: [] } })).targets, []);
  });

  it('refuses what is not a list of lists of integer cells, naming the header line', () => {
    const bad = [
      [{ cells: [] }, /line 1: "targets" must be a list/],
      [[5], /line 1: targets\[0\] must be a list of cells/],
      [[[0, 0, 0]], /line 1: targets\[0\]\[0\] is not a cell \[x,y,z\] of integers: 0/],
      [[[[0, 0, 0], [1, 0]]], /line 1: targets\[0\]\[1\] is not a cell/],
      [[[[0, 0, 0]], [[0, 0.5, 0]]], /line 1: targets\[1\]\[0\] is not a cell/],
      [[[['0', 0, 0]]], /line 1: targets\[0\]\[0\] is not a cell/],
    ];
    for (const [targets, pattern] of bad) {
      assert.throws(() => parseTrace(syntheticTrace({ modules, header: { targets } })), pattern, JSON.stringify(targets));
    }
  });
});

describe('parseTrace on a run with concurrent motions (walkers)', () => {
  const trace = parseTrace(walkersText());

  it('reads its motions, refusals and target', () => {
    assert.equal(trace.motions.length, WALKERS.motions);
    assert.equal(trace.refusals.length, WALKERS.refusals);
    assert.equal(trace.notes.length, WALKERS.motions, 'one note per motion');
    assert.deepEqual(trace.targets, [[[3, 1, 1], [4, 1, 1], [3, 2, 1], [4, 2, 1]]]);
    for (const m of trace.motions) {
      assert.ok(WALKERS.ids.includes(m.m), `mobile ${m.m}`);
      assert.ok(m.end > m.t);
    }
  });
});

// The table of bad traces that `datomsim view` is held to as well (tests/unit/export): both
// readers refuse the same traces with the same message and line.
describe('the shared table of trace cases', async () => {
  const { readFileSync } = await import('node:fs');
  const { fileURLToPath } = await import('node:url');
  const here = (name) => fileURLToPath(new URL(`./fixtures/${name}`, import.meta.url));
  const table = JSON.parse(readFileSync(here('trace-cases.json'), 'utf8'));
  const base = readFileSync(here(table.base), 'utf8');

  // The case's trace: the base's values, one changed or one added, one value per line.
  function traceOf(testCase) {
    const values = splitJsonValues(base).map((v) => v.value);
    if (testCase.set) {
      const [path, value] = testCase.set;
      let at = values[testCase.value];
      for (const key of path.slice(0, -1)) at = at[key];
      const last = path[path.length - 1];
      if (value === null && Array.isArray(at)) at.splice(last, 1);
      else if (value === null) delete at[last];
      else at[last] = value;
    }
    if (testCase.append) values.push(testCase.append);
    return values.map((v) => JSON.stringify(v)).join('\n') + '\n';
  }

  for (const testCase of table.cases) {
    it(testCase.name, () => {
      const text = traceOf(testCase);
      if (testCase.error === null) {
        assert.doesNotThrow(() => parseTrace(text));
        return;
      }
      const [line, message] = testCase.error;
      assert.throws(() => parseTrace(text), (error) => {
        assert.ok(error instanceof TraceError, String(error));
        assert.equal(error.message, `line ${line}: ${message}`);
        return true;
      });
    });
  }
});
