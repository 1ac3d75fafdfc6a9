import assert from 'node:assert/strict';
import { describe, it } from 'node:test';
import { Vector3 } from 'three';
import { Kinematics } from '../src/kinematics.js';
import { cellToWorld } from '../src/lattice.js';
import { Timeline, turnProgress } from '../src/timeline.js';
import { parseTrace } from '../src/trace.js';
import { fixtureText, module, syntheticTrace } from './fixtures/synthetic.js';

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
