import assert from 'node:assert/strict';
import { describe, it } from 'node:test';
import { MotionIndex, concurrencySteps, countAt, maxConcurrency, targetFill } from '../src/concurrency.js';
import { cellToWorld } from '../src/lattice.js';
import { Timeline } from '../src/timeline.js';
import { parseTrace } from '../src/trace.js';
import { WALKERS, module, syntheticTrace, walkersText } from './fixtures/synthetic.js';

const motion = (m, t, end) => ({ t, end, m, pivot: 100 + m, goal: [0, 0, 0], blockers: [] });

describe('motions in flight', () => {
  // Three overlapping motions: [0, 2), [1, 3), [1.5, 2.5).
  const motions = [motion(1, 0, 2), motion(2, 1, 3), motion(3, 1.5, 2.5)];

  it('counts three overlapping motions: 3 at most, from 1.5 to 2', () => {
    const steps = concurrencySteps(motions);
    assert.deepEqual(steps, [
      { t: 0, count: 1 },
      { t: 1, count: 2 },
      { t: 1.5, count: 3 },
      { t: 2, count: 2 },
      { t: 2.5, count: 1 },
      { t: 3, count: 0 },
    ]);
    const expected = [[0, 1], [0.5, 1], [1, 2], [1.49, 2], [1.5, 3], [1.99, 3], [2, 2], [2.5, 1], [2.9, 1], [3, 0], [10, 0]];
    for (const [t, count] of expected) assert.equal(countAt(steps, t), count, `at ${t}`);
    assert.deepEqual(maxConcurrency(steps), { max: 3, at: [{ from: 1.5, to: 2 }] });
  });

  it('lists the motions in flight at a time, a motion from its start to its end (excluded)', () => {
    const index = new MotionIndex(motions);
    assert.equal(index.max, 3);
    assert.deepEqual(index.inFlightAt(1.7).map((m) => m.m), [1, 2, 3]);
    assert.deepEqual(index.inFlightAt(2).map((m) => m.m), [2, 3]);
    assert.deepEqual(index.inFlightAt(0).map((m) => m.m), [1]);
    assert.deepEqual(index.inFlightAt(3).map((m) => m.m), []);
    assert.deepEqual(index.inFlightAt(-1), []);
  });

  it('never counts a motion that ends at T with one that starts at T, nor one of no duration', () => {
    const steps = concurrencySteps([motion(1, 0, 1), motion(2, 1, 2), motion(3, 1.5, 1.5)]);
    assert.deepEqual(steps, [
      { t: 0, count: 1 },
      { t: 2, count: 0 },
    ]);
    assert.equal(maxConcurrency(steps).max, 1);
    assert.deepEqual(concurrencySteps([]), [{ t: 0, count: 0 }]);
    assert.deepEqual(maxConcurrency(concurrencySteps([])), { max: 0, at: [] });
  });

  it('does not depend on the order of the motions', () => {
    const a = concurrencySteps(motions);
    const b = concurrencySteps(motions.slice().reverse());
    assert.deepEqual(a, b);
  });

  it('gives the maximum of the run (max_concurrent_motions) on a walkers trace', () => {
    const trace = parseTrace(walkersText());
    const index = new MotionIndex(trace.motions);
    assert.equal(index.max, WALKERS.maxConcurrent);
    // The index agrees with counting every motion, at every start, end and between them.
    const times = new Set();
    for (const m of trace.motions) [m.t, m.end, (m.t + m.end) / 2, m.t - 1e-6, m.end - 1e-6].forEach((t) => times.add(t));
    for (const t of times) {
      const brute = trace.motions.filter((m) => m.t <= t && t < m.end);
      assert.deepEqual(index.inFlightAt(t), brute, `at ${t}`);
      assert.equal(index.countAt(t), brute.length, `count at ${t}`);
    }
  });
});

describe('target cells filled', () => {
  it('counts the target cells that hold a module at a time', () => {
    const modules = [module(1, [0, 0, 1]), module(2, [0, 0, 0]), module(3, [1, 0, 0]), module(4, [5, 5, 0])];
    const target = [[1, 0, 0], [1, 0, 1], [0, 0, 1], [2, 0, 0]];
    const trace = parseTrace(
      syntheticTrace({
        modules,
        header: { targets: [target] },
        events: [
          { t: 0, motion: { m: 1, pivot: 2, goal: [1, 0, 1], blockers: [], end: 2 } },
          { t: 0, turn: { m: 1, axis: [0, 1, 0], centre: [2, 1, 1.5], deg: 90, d: 1 } },
          { t: 1, turn: { m: 1, axis: [0, 1, 0], centre: [2, 1, 1.5], deg: 90, d: 1 } },
          { t: 2, place: { m: 1, cell: [1, 0, 1], pos: cellToWorld([1, 0, 1], 2), o: 0 } },
          { t: 3, place: { m: 4, cell: [2, 0, 0], pos: cellToWorld([2, 0, 0], 2), o: 0 } },
        ],
      }),
    );
    const timeline = new Timeline(trace);
    const fillAt = (t) => targetFill(trace.targets[0], timeline.frameAt(t).modules);
    // At 0: (1,0,0) and (0,0,1) are held; the mobile holds (0,0,1) until its place line.
    assert.deepEqual(fillAt(0), { cells: 4, filled: 2, isFilled: [true, false, true, false] });
    assert.equal(fillAt(1.99).filled, 2, 'a mobile holds its cell until it arrives');
    assert.deepEqual(fillAt(2).isFilled, [true, true, false, false]);
    assert.equal(fillAt(2).filled, 2);
    assert.equal(fillAt(3).filled, 3);
  });

  it('counts a cell listed twice once', () => {
    const fill = targetFill([[0, 0, 0], [0, 0, 0], [1, 0, 0]], [{ cell: [0, 0, 0] }]);
    assert.deepEqual(fill, { cells: 2, filled: 1, isFilled: [true, true, false] });
    assert.deepEqual(targetFill([], [{ cell: [0, 0, 0] }]), { cells: 0, filled: 0, isFilled: [] });
  });
});
