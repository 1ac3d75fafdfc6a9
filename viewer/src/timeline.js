// The state of every module at any time t, computed from the trace alone.
//
// Seeking is deterministic: the state at t is the header's scene with every change that starts at
// or before t applied in trace order, and the changes still running at t (piston strokes, turns)
// evaluated at t. Nothing is accumulated frame by frame, so the picture at t does not depend on
// how the viewer got there, nor on the playing speed. For speed the timeline keeps a copy of the
// state every `checkpointEvery` changes and replays from the nearest one.
import { Matrix4, Quaternion, Vector3 } from 'three';
import { MotionIndex } from './concurrency.js';
import { NEIGHBOUR_OFFSETS, addCells, cellKey, directionVector, nearestDirection } from './lattice.js';
import { REFUSAL_NOTE } from './trace.js';

// The unit quaternion of an orientation matrix given by rows (module frame -> world).
export function quaternionOfRows(rows) {
  const [r0, r1, r2] = rows;
  // Matrix4.set takes its arguments row by row.
  const m = new Matrix4().set(...r0, 0, ...r1, 0, ...r2, 0, 0, 0, 0, 1);
  return new Quaternion().setFromRotationMatrix(m).normalize();
}

function ramp(t, t0, d) {
  if (d <= 0) return t >= t0 ? 1 : 0;
  return Math.min(1, Math.max(0, (t - t0) / d));
}

// Progress of a turn at time fraction u: linear, or the C++ samples of "progress" at equal time
// steps when the trace gives them.
export function turnProgress(turn, u) {
  const samples = turn.progress;
  if (!samples) return u;
  const x = u * (samples.length - 1);
  const s = Math.min(samples.length - 2, Math.floor(x));
  return samples[s] + (samples[s + 1] - samples[s]) * (x - s);
}

function cloneModule(m) {
  return {
    id: m.id,
    index: m.index,
    cell: m.cell.slice(),
    o: m.o,
    pos: m.pos.slice(),
    quat: m.quat.slice(),
    rgb: m.rgb.slice(),
    latches: m.latches,
    partners: new Map(m.partners),
    // One stroke per own piston (null: never moved): strokes are never changed once made.
    pistons: m.pistons.slice(),
    turn: m.turn && { ...m.turn },
    moved: m.moved,
  };
}

function cloneState(state) {
  return {
    applied: state.applied,
    modules: state.modules.map(cloneModule),
    note: state.note,
    end: state.end,
  };
}

export class Timeline {
  constructor(trace, { checkpointEvery = 64 } = {}) {
    this.trace = trace;
    this.header = trace.header;
    this.events = trace.events;
    this.duration = trace.duration;
    this.checkpointEvery = checkpointEvery;
    this.orientationQuats = this.header.orientations.map(quaternionOfRows);
    this.indexOfId = new Map(this.header.modules.map((m, index) => [m.id, index]));
    // The motions in flight at any time, from the "motion" lines (none in older traces).
    this.motionIndex = new MotionIndex(trace.motions ?? []);

    const initial = {
      applied: 0,
      modules: this.header.modules.map((m, index) => ({
        id: m.id,
        index,
        cell: m.cell.slice(),
        o: m.o,
        pos: m.pos.slice(),
        quat: this.orientationQuats[m.o].toArray(),
        rgb: m.rgb.slice(),
        latches: m.latches ?? 0,
        partners: new Map(),
        pistons: [null, null, null, null, null, null],
        turn: null,
        moved: false,
      })),
      note: null,
      end: null,
    };
    // Partners of the scene's initial latches: the module each latched connector faces.
    const byCell = new Map(initial.modules.map((m) => [cellKey(m.cell), m]));
    for (const m of initial.modules) {
      for (let c = 0; c < 12; ++c) {
        if (!(m.latches & (1 << c))) continue;
        const partner = this.facingPartner(m, byCell, c);
        if (partner) m.partners.set(c, partner);
      }
    }
    this.checkpoints = [cloneState(initial)];
    const state = initial;
    for (let e = 0; e < this.events.length; ++e) {
      this.apply(state, this.events[e]);
      if ((e + 1) % checkpointEvery === 0) this.checkpoints.push(cloneState(state));
    }
  }

  // Number of changes that start at or before t.
  countUntil(t) {
    let lo = 0;
    let hi = this.events.length;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (this.events[mid].t <= t) lo = mid + 1;
      else hi = mid;
    }
    return lo;
  }

  // The discrete state at t: every change starting at or before t applied. Running strokes and
  // turns are kept with their start, for evaluate().
  stateAt(t) {
    const n = this.countUntil(t);
    const c = Math.min(Math.floor(n / this.checkpointEvery), this.checkpoints.length - 1);
    const state = cloneState(this.checkpoints[c]);
    for (let e = state.applied; e < n; ++e) this.apply(state, this.events[e]);
    return state;
  }

  apply(state, event) {
    state.applied += 1;
    const body = event.body;
    const moduleOf = (id) => state.modules[this.indexOfId.get(id)];
    switch (event.kind) {
      case 'piston': {
        const m = moduleOf(body.m);
        m.pistons[body.p] = { p: body.p, from: body.from, to: body.to, t0: event.t, d: body.d, seq: event.seq };
        break;
      }
      case 'turn': {
        const m = moduleOf(body.m);
        this.settleTurn(m, event.t);
        m.turn = {
          axis: body.axis,
          centre: body.centre,
          deg: body.deg,
          t0: event.t,
          d: body.d,
          progress: body.progress,
        };
        m.moved = true;
        break;
      }
      case 'place': {
        const m = moduleOf(body.m);
        m.turn = null;
        m.pos = body.pos.slice();
        m.quat = this.orientationQuats[body.o].toArray();
        m.o = body.o;
        if (body.cell) m.cell = body.cell.slice();
        m.moved = false;
        break;
      }
      case 'latch': {
        const a = moduleOf(body.a);
        const b = moduleOf(body.b);
        if (body.on) {
          a.latches |= 1 << body.ca;
          b.latches |= 1 << body.cb;
          a.partners.set(body.ca, { m: body.b, c: body.cb });
          b.partners.set(body.cb, { m: body.a, c: body.ca });
        } else {
          a.latches &= ~(1 << body.ca);
          b.latches &= ~(1 << body.cb);
          a.partners.delete(body.ca);
          b.partners.delete(body.cb);
        }
        break;
      }
      case 'color':
        moduleOf(body.m).rgb = body.rgb.slice();
        break;
      case 'note':
        // Refusals are ticks of the concurrency strip; the note line keeps the motions' notes.
        if (!REFUSAL_NOTE.test(String(body))) state.note = { t: event.t, text: String(body) };
        break;
      case 'end':
        state.end = { t: event.t, summary: body };
        break;
      default:
        break;
    }
  }

  // Bakes a module's turn, as far as it went at time t, into its base pose.
  settleTurn(m, t) {
    if (!m.turn) return;
    const { position, quaternion } = this.turnedPose(m, t);
    m.pos = position.toArray();
    m.quat = quaternion.toArray();
    m.turn = null;
  }

  // A module's pose at t: its base pose, turned about the running turn's axis if any.
  turnedPose(m, t) {
    const position = new Vector3(...m.pos);
    const quaternion = new Quaternion().fromArray(m.quat);
    if (m.turn) {
      const turn = m.turn;
      const angle = ((turn.deg * Math.PI) / 180) * turnProgress(turn, ramp(t, turn.t0, turn.d));
      const axis = new Vector3(...turn.axis).normalize();
      const rotation = new Quaternion().setFromAxisAngle(axis, angle);
      const centre = new Vector3(...turn.centre);
      position.sub(centre).applyQuaternion(rotation).add(centre);
      quaternion.premultiply(rotation);
    }
    return { position, quaternion };
  }

  // Piston of a module at t: {piston, fraction, others}, piston -1 at rest. Each own piston
  // follows its own last stroke. A Datom compresses one piston at a time; should a trace leave
  // several compressed, the picture shows the one whose stroke started last, and `others` lists
  // the rest.
  pistonAt(m, t) {
    let shown = null;
    const compressed = [];
    for (const s of m.pistons) {
      if (!s) continue;
      const f = Math.max(0, Math.min(1, s.from + (s.to - s.from) * ramp(t, s.t0, s.d)));
      if (f <= 0) continue;
      const entry = { p: s.p, fraction: f, t0: s.t0, seq: s.seq };
      compressed.push(entry);
      if (!shown || entry.t0 > shown.t0 || (entry.t0 === shown.t0 && entry.seq > shown.seq)) shown = entry;
    }
    if (!shown) return { piston: -1, fraction: 0, others: [] };
    const others = compressed.filter((c) => c !== shown).map((c) => ({ p: c.p, fraction: c.fraction }));
    return { piston: shown.p, fraction: shown.fraction, others };
  }

  // Everything the picture needs at time t: for each module (header order) its position,
  // rotation, piston and fraction, colour and latches; the current note; the motions in flight.
  frameAt(t) {
    const state = this.stateAt(t);
    const motions = this.motionIndex.inFlightAt(t);
    const modules = state.modules.map((m) => {
      const { position, quaternion } = this.turnedPose(m, t);
      const { piston, fraction, others } = this.pistonAt(m, t);
      return {
        id: m.id,
        index: m.index,
        cell: m.cell,
        o: m.o,
        position,
        quaternion,
        piston,
        fraction,
        otherPistons: others,
        rgb: m.rgb,
        latches: m.latches,
        partners: m.partners,
        moving: Boolean(m.turn) && ramp(t, m.turn.t0, m.turn.d) < 1,
        inTransit: m.moved,
      };
    });
    return { t, modules, motions, note: state.note, end: state.end, applied: state.applied };
  }

  // The module a latched own connector holds, {m: id, c: its connector}, or null when unknown:
  // the partner of the scene's initial latches, or the one a latch change named.
  latchPartner(frame, index, connector) {
    return frame.modules[index].partners.get(connector) ?? null;
  }

  // The module in the neighbour cell an own connector of module m faces ({m: id, c: its connector
  // facing back}), from a map cell key -> module; null when that cell is empty.
  facingPartner(m, byCell, connector) {
    const rows = this.header.orientations[m.o];
    const v = directionVector(connector);
    const world = rows.map((row) => row[0] * v[0] + row[1] * v[1] + row[2] * v[2]);
    const direction = nearestDirection(world);
    const neighbourCell = addCells(m.cell, NEIGHBOUR_OFFSETS[direction]);
    const other = byCell.get(cellKey(neighbourCell));
    if (!other) return null;
    // The neighbour's own connector facing back.
    const back = (direction + 6) % 12;
    const otherRows = this.header.orientations[other.o];
    let c = -1;
    for (let own = 0; own < 12; ++own) {
      const u = directionVector(own);
      const w = otherRows.map((row) => row[0] * u[0] + row[1] * u[1] + row[2] * u[2]);
      if (nearestDirection(w) === back) c = own;
    }
    return { m: other.id, c };
  }
}
