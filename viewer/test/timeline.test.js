import assert from 'node:assert/strict';
import { describe, it } from 'node:test';
import { Vector3 } from 'three';
import { Kinematics } from '../src/kinematics.js';
import { cellToWorld } from '../src/lattice.js';
import { Timeline, turnProgress } from '../src/timeline.js';
import { parseTrace } from '../src/trace.js';
import { WALKERS, fixtureText, module, syntheticTrace, walkersText } from './fixtures/synthetic.js';

function near(a, b, tolerance = 1e-6) {
  assert.ok(Math.abs(a - b) <= tolerance, `${a} != ${b}`);
}

function nearArray(a, b, tolerance = 1e-6) {
  assert.equal(a.length, b.length);
  a.forEach((x, k) => near(x, b[k], tolerance));
}

function timelineOf(options) {
  return new Timeline(parseTrace(syntheticTrace(options)));
}

// What a frame shows, as plain numbers.
function picture(frame) {
  return frame.modules.map((m) => [
    ...m.position.toArray(),
    ...m.quaternion.toArray(),
    m.piston,
    m.fraction,
    m.latches,
    ...m.rgb,
  ]);
}

describe('Timeline, one change at a time', () => {
  const a = module(1, [0, 0, 0]);
  const b = module(2, [1, 0, 0]);

  it('starts from the header scene', () => {
    const frame = timelineOf({ modules: [a, b] }).frameAt(0);
    nearArray(frame.modules[1].position.toArray(), b.pos);
    nearArray(frame.modules[1].quaternion.toArray(), [0, 0, 0, 1]);
    assert.equal(frame.modules[0].piston, -1);
  });

  it('moves a piston linearly in fraction over its duration, and holds the end', () => {
    const timeline = timelineOf({
      modules: [a, b],
      events: [
        { t: 1, piston: { m: 2, p: 3, from: 0, to: 1, d: 0.5 } },
        { t: 3, piston: { m: 2, p: 3, from: 1, to: 0, d: 0.5 } },
      ],
    });
    const at = (t) => timeline.frameAt(t).modules[1];
    assert.equal(at(0.99).piston, -1);
    assert.equal(at(1.25).piston, 3);
    near(at(1.25).fraction, 0.5);
    near(at(2).fraction, 1);
    near(at(3.4).fraction, 0.2);
    assert.equal(at(3.5).piston, -1, 'back at rest');
  });

  it('turns a body about an axis through a point, progressively', () => {
    const centre = [1, 1, 0.5];
    const timeline = timelineOf({
      modules: [a],
      events: [{ t: 0, turn: { m: 1, axis: [0, 0, 1], centre, deg: 90, d: 2 } }],
    });
    const start = new Vector3(...a.pos);
    const expected = (deg) =>
      start
        .clone()
        .sub(new Vector3(...centre))
        .applyAxisAngle(new Vector3(0, 0, 1), (deg * Math.PI) / 180)
        .add(new Vector3(...centre));
    nearArray(timeline.frameAt(1).modules[0].position.toArray(), expected(45).toArray());
    nearArray(timeline.frameAt(5).modules[0].position.toArray(), expected(90).toArray());
    near(timeline.frameAt(1).modules[0].quaternion.angleTo(timeline.frameAt(0).modules[0].quaternion), Math.PI / 4);
    assert.equal(timeline.frameAt(1).modules[0].moving, true);
  });

  it('follows the progress samples of a turn when the trace gives them', () => {
    const turn = { progress: [0, 0.1, 0.5, 1] };
    near(turnProgress(turn, 0), 0);
    near(turnProgress(turn, 1 / 3), 0.1);
    near(turnProgress(turn, 0.5), 0.3);
    near(turnProgress(turn, 1), 1);
    near(turnProgress({}, 0.25), 0.25);
    const timeline = timelineOf({
      modules: [a],
      events: [{ t: 0, turn: { m: 1, axis: [0, 0, 1], centre: [0, 0, 0], deg: 90, d: 3, progress: [0, 0.1, 0.5, 1] } }],
    });
    const angle = timeline.frameAt(1).modules[0].quaternion.angleTo(timeline.frameAt(0).modules[0].quaternion);
    near(angle, (0.1 * Math.PI) / 2);
  });

  it('chains two turns: the second starts from where the first ended', () => {
    const timeline = timelineOf({
      modules: [a],
      events: [
        { t: 0, turn: { m: 1, axis: [0, 0, 1], centre: [0, 0, 0], deg: 90, d: 1 } },
        { t: 1, turn: { m: 1, axis: [0, 0, 1], centre: [0, 0, 0], deg: 90, d: 1 } },
      ],
    });
    const p = timeline.frameAt(2).modules[0].position;
    nearArray(p.toArray(), [-a.pos[0], -a.pos[1], a.pos[2]]);
  });

  it('snaps to the pose a place gives', () => {
    const timeline = timelineOf({
      modules: [a],
      events: [
        { t: 0, turn: { m: 1, axis: [0, 0, 1], centre: [0, 0, 0], deg: 90, d: 1 } },
        { t: 0.5, place: { m: 1, cell: [2, 0, 0], pos: cellToWorld([2, 0, 0], 2), o: 1 } },
      ],
    });
    const frame = timeline.frameAt(0.75);
    nearArray(frame.modules[0].position.toArray(), cellToWorld([2, 0, 0], 2));
    nearArray(frame.modules[0].quaternion.toArray(), timeline.orientationQuats[1].toArray());
    assert.deepEqual(frame.modules[0].cell, [2, 0, 0]);
    assert.equal(frame.modules[0].o, 1);
  });

  it('makes and releases latches, and changes colours', () => {
    const timeline = timelineOf({
      modules: [a, b],
      events: [
        { t: 1, latch: { a: 1, ca: 0, b: 2, cb: 6, on: true } },
        { t: 2, color: { m: 2, rgb: [255, 0, 0] } },
        { t: 3, latch: { a: 1, ca: 0, b: 2, cb: 6, on: false } },
      ],
    });
    const f1 = timeline.frameAt(1.5);
    assert.equal(f1.modules[0].latches, 1);
    assert.equal(f1.modules[1].latches, 1 << 6);
    assert.deepEqual(timeline.latchPartner(f1, 0, 0), { m: 2, c: 6 });
    assert.deepEqual(timeline.frameAt(2).modules[1].rgb, [255, 0, 0]);
    assert.equal(timeline.frameAt(3).modules[0].latches, 0);
  });

  it('applies a change written before an earlier one at its own time', () => {
    const timeline = timelineOf({
      modules: [a],
      events: [
        { t: 2, piston: { m: 1, p: 1, from: 0, to: 1, d: 1 } },
        { t: 1, piston: { m: 1, p: 0, from: 0, to: 1, d: 0.5 } },
      ],
    });
    assert.equal(timeline.frameAt(1.5).modules[0].piston, 0);
    assert.equal(timeline.frameAt(2.5).modules[0].piston, 1);
  });
});

describe('Timeline on a run of the simulator', () => {
  const trace = parseTrace(fixtureText());
  const timeline = new Timeline(trace);
  const times = [];
  for (let k = 0; k <= 200; ++k) times.push((trace.duration * k) / 200);
  times.push(...trace.changeTimes);

  it('shows the same picture at a time however it got there (seeking is deterministic)', () => {
    const forward = times.map((t) => picture(timeline.frameAt(t)));
    const shuffled = times.map((t, k) => [t, k]).sort((x, y) => ((x[1] * 7919) % 101) - ((y[1] * 7919) % 101));
    for (const [t, k] of shuffled) assert.deepEqual(picture(timeline.frameAt(t)), forward[k], `t = ${t}`);
    const noCheckpoints = new Timeline(trace, { checkpointEvery: 1e9 });
    const everyEvent = new Timeline(trace, { checkpointEvery: 1 });
    for (let k = 0; k < times.length; k += 5) {
      assert.deepEqual(picture(noCheckpoints.frameAt(times[k])), forward[k]);
      assert.deepEqual(picture(everyEvent.frameAt(times[k])), forward[k]);
    }
  });

  it('brings the mobile from its start to the goal', () => {
    const index = timeline.indexOfId.get(1);
    assert.deepEqual(timeline.frameAt(0).modules[index].cell, [0, 0, 2]);
    const end = timeline.frameAt(trace.duration).modules[index];
    assert.deepEqual(end.cell, [6, 5, 2]);
    nearArray(end.position.toArray(), cellToWorld([6, 5, 2], trace.header.spacing), 1e-4);
  });

  it('ends every pair of turns where the next place puts the mobile (no jump)', () => {
    const places = trace.events.filter((e) => e.kind === 'place');
    assert.ok(places.length >= 7);
    for (const place of places) {
      const index = timeline.indexOfId.get(place.body.m);
      const before = timeline.frameAt(place.t - 1e-9).modules[index];
      nearArray(before.position.toArray(), place.body.pos, 1e-3);
      near(before.quaternion.angleTo(timeline.orientationQuats[place.body.o]), 0, 1e-3);
    }
  });

  it('has the pivot and the mobile compressed at the middle of a motion', () => {
    const turn = trace.events.find((e) => e.kind === 'turn');
    const middle = turn.t + turn.body.d;
    const frame = timeline.frameAt(middle - 1e-9);
    const compressed = frame.modules.filter((m) => m.piston >= 0 && m.fraction > 0.999);
    assert.ok(compressed.length >= 2, 'pivot and mobile');
  });
});

describe('Timeline with concurrent motions', () => {
  const a = module(1, [0, 0, 1]);
  const b = module(2, [4, 0, 1]);
  const pa = module(3, [0, 0, 0]);
  const pb = module(4, [4, 0, 0]);
  const centreA = [1.5, 1, 2];
  const centreB = [9.5, 1, 2];
  const timeline = timelineOf({
    modules: [a, b, pa, pb],
    events: [
      { t: 0, motion: { m: 1, pivot: 3, goal: [1, 0, 1], blockers: [], end: 2 } },
      { t: 0, piston: { m: 3, p: 4, from: 0, to: 1, d: 1 } },
      { t: 0, piston: { m: 1, p: 3, from: 0, to: 1, d: 1 } },
      { t: 0, turn: { m: 1, axis: [0, 1, 0], centre: centreA, deg: 90, d: 1 } },
      { t: 0.5, motion: { m: 2, pivot: 4, goal: [3, 0, 1], blockers: [], end: 2.5 } },
      { t: 0.5, piston: { m: 4, p: 2, from: 0, to: 1, d: 1 } },
      { t: 0.5, piston: { m: 2, p: 1, from: 0, to: 1, d: 1 } },
      { t: 0.5, turn: { m: 2, axis: [0, -1, 0], centre: centreB, deg: 90, d: 1 } },
      { t: 1, piston: { m: 3, p: 4, from: 1, to: 0, d: 1 } },
      { t: 1, piston: { m: 1, p: 3, from: 1, to: 0, d: 1 } },
    ],
  });

  it('turns each mobile about its own hinge, each from its own start', () => {
    const at = (t, k) => timeline.frameAt(t).modules[k];
    const distance = (p, c) => Math.hypot(p[0] - c[0], p[1] - c[1], p[2] - c[2]);
    for (const t of [0, 0.25, 0.5, 0.75, 1]) {
      near(distance(at(t, 0).position.toArray(), centreA), distance(a.pos, centreA));
      near(distance(at(t, 1).position.toArray(), centreB), distance(b.pos, centreB));
    }
    // Module 2 has not started at 0.4 while module 1 is turning; halfway in each at 0.5 and 1.
    nearArray(at(0.4, 1).position.toArray(), b.pos);
    near(at(0.5, 0).quaternion.angleTo(at(0, 0).quaternion), Math.PI / 4);
    near(at(1, 1).quaternion.angleTo(at(0, 1).quaternion), Math.PI / 4);
    assert.equal(at(0.75, 0).moving, true);
    assert.equal(at(0.75, 1).moving, true);
  });

  it('moves the pistons of each module on their own', () => {
    const frame = timeline.frameAt(1.25);
    const [m1, m2, p1, p2] = frame.modules;
    assert.deepEqual([m1.piston, p1.piston, m2.piston, p2.piston], [3, 4, 1, 2]);
    near(m1.fraction, 0.75);
    near(p1.fraction, 0.75);
    near(m2.fraction, 0.75);
    near(p2.fraction, 0.75);
  });

  it('lists the motions in flight in the frame', () => {
    assert.deepEqual(timeline.frameAt(0.25).motions.map((m) => m.m), [1]);
    assert.deepEqual(timeline.frameAt(1).motions.map((m) => m.m), [1, 2]);
    assert.deepEqual(timeline.frameAt(2).motions.map((m) => m.m), [2]);
    assert.deepEqual(timeline.frameAt(2.5).motions, []);
  });

  it('keeps each own piston of a module apart: a later stroke of another piston does not undo the first', () => {
    const t2 = timelineOf({
      modules: [a],
      events: [
        { t: 0, piston: { m: 1, p: 0, from: 0, to: 1, d: 1 } },
        { t: 2, piston: { m: 1, p: 1, from: 0, to: 1, d: 1 } },
        { t: 4, piston: { m: 1, p: 1, from: 1, to: 0, d: 1 } },
      ],
    });
    const at = (t) => t2.frameAt(t).modules[0];
    assert.equal(at(2.5).piston, 1, 'the stroke that started last is drawn');
    assert.deepEqual(at(2.5).otherPistons, [{ p: 0, fraction: 1 }]);
    assert.equal(at(5).piston, 0, 'piston 0 is still compressed');
    near(at(5).fraction, 1);
    assert.deepEqual(at(1).otherPistons, []);
  });
});

describe('Timeline on a run with concurrent motions (walkers)', () => {
  const trace = parseTrace(walkersText());
  const timeline = new Timeline(trace);
  const times = [];
  for (let k = 0; k <= 300; ++k) times.push((trace.duration * k) / 300);
  times.push(...trace.changeTimes);

  it('shows the same picture at a time however it got there (seeking is deterministic)', () => {
    const forward = times.map((t) => picture(timeline.frameAt(t)));
    const shuffled = times.map((t, k) => [t, k]).sort((x, y) => ((x[1] * 7919) % 101) - ((y[1] * 7919) % 101));
    for (const [t, k] of shuffled) assert.deepEqual(picture(timeline.frameAt(t)), forward[k], `t = ${t}`);
    const noCheckpoints = new Timeline(trace, { checkpointEvery: 1e9 });
    const everyEvent = new Timeline(trace, { checkpointEvery: 1 });
    for (let k = 0; k < times.length; k += 3) {
      assert.deepEqual(picture(noCheckpoints.frameAt(times[k])), forward[k]);
      assert.deepEqual(picture(everyEvent.frameAt(times[k])), forward[k]);
    }
  });

  it('turns every mobile rigidly about its own hinge while the others move', () => {
    const turns = trace.events.filter((e) => e.kind === 'turn');
    assert.equal(turns.length, 2 * WALKERS.motions);
    for (const turn of turns) {
      const index = timeline.indexOfId.get(turn.body.m);
      const c = new Vector3(...turn.body.centre);
      const radius = timeline.frameAt(turn.t).modules[index].position.distanceTo(c);
      for (const u of [0.2, 0.5, 0.8, 1]) {
        const p = timeline.frameAt(turn.t + u * turn.body.d - 1e-9).modules[index].position;
        near(p.distanceTo(c), radius, 1e-6);
      }
    }
  });

  it('ends every pair of turns where the next place puts the mobile (no jump)', () => {
    const places = trace.events.filter((e) => e.kind === 'place');
    assert.equal(places.length, WALKERS.motions);
    for (const place of places) {
      const index = timeline.indexOfId.get(place.body.m);
      const before = timeline.frameAt(place.t - 1e-9).modules[index];
      nearArray(before.position.toArray(), place.body.pos, 1e-3);
      near(before.quaternion.angleTo(timeline.orientationQuats[place.body.o]), 0, 1e-3);
    }
  });

  it('has every mobile off its cell and every pivot compressed while their motions are in flight', () => {
    const [{ from, to }] = timeline.motionIndex.maxAt;
    const t = (from + to) / 2;
    const frame = timeline.frameAt(t);
    assert.equal(frame.motions.length, WALKERS.maxConcurrent);
    for (const motion of frame.motions) {
      const mobile = frame.modules[timeline.indexOfId.get(motion.m)];
      const pivot = frame.modules[timeline.indexOfId.get(motion.pivot)];
      const away = mobile.position.distanceTo(new Vector3(...cellToWorld(mobile.cell, 2)));
      assert.ok(away > 0.1, `mobile ${motion.m} is at its cell at ${t}`);
      assert.ok(pivot.piston >= 0 && pivot.fraction > 0, `pivot ${motion.pivot} at rest at ${t}`);
      assert.ok(mobile.piston >= 0 && mobile.fraction > 0, `mobile ${motion.m} at rest at ${t}`);
    }
    const still = frame.modules.filter((m) => !frame.motions.some((motion) => motion.m === m.id));
    for (const m of still) nearArray(m.position.toArray(), cellToWorld(m.cell, 2), 1e-4);
  });

  it('brings every walker to a cell of the floor top at the end', () => {
    const end = timeline.frameAt(trace.duration);
    for (const id of WALKERS.ids) {
      const m = end.modules[timeline.indexOfId.get(id)];
      assert.equal(m.cell[2], 1);
      nearArray(m.position.toArray(), cellToWorld(m.cell, 2), 1e-4);
    }
  });
});

describe('latch partners of the initial scene', () => {
  it('finds the neighbour a latched connector faces', () => {
    const trace = parseTrace(fixtureText());
    const timeline = new Timeline(trace);
    const frame = timeline.frameAt(0);
    // Module 2 at (1,1,0) is latched by connector 0 to module 3 at (2,1,0), connector 6.
    const index = timeline.indexOfId.get(2);
    assert.ok(frame.modules[index].latches & 1);
    assert.deepEqual(timeline.latchPartner(frame, index, 0), { m: 3, c: 6 });
  });
});

describe('Kinematics and Timeline together', () => {
  it('draws a deformed module of the run with the piston the trace names', () => {
    const trace = parseTrace(fixtureText());
    const timeline = new Timeline(trace);
    const kin = new Kinematics(trace.header);
    const piston = trace.events.find((e) => e.kind === 'piston');
    const frame = timeline.frameAt(piston.t + piston.body.d / 2);
    const m = frame.modules[timeline.indexOfId.get(piston.body.m)];
    assert.equal(m.piston, piston.body.p);
    const plate = kin.parts.find((p) => p.kind === 'piston' && p.piston === piston.body.p);
    const rest = kin.partPose(plate.i, -1, 0).centre.length();
    const half = kin.partPose(plate.i, m.piston, m.fraction).centre.length();
    assert.ok(half < rest, 'the plate has moved in');
  });
});
