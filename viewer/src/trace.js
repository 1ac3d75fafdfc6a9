// Reading a datomsim trace (docs/trace-format.md, src/sim/trace.h): the header (module model,
// orientations, sampled kinematics, initial scene) and the timed changes after it.
//
// A trace is JSON Lines, but the reader does not rely on one value per line: it splits the text
// into top-level JSON values, so a header spread over several lines reads too. Errors name the
// line where the bad value starts.

export const TRACE_FORMAT = 'datomsim-trace';
export const TRACE_VERSION = 1;
export const EVENT_KINDS = ['piston', 'turn', 'place', 'latch', 'color', 'motion', 'note', 'end'];
// What the modules are (the header's optional "module", src/world/module_kind.h): the Datom of the
// trace's kinematics, or the 3D Catom, a rigid body that only turns and is placed. A trace without
// "module" is one of Datoms.
export const MODULE_KINDS = ['datom', 'catom3d'];
export const DATOM = 'datom';
export const CATOM3D = 'catom3d';

// Notes that say a request was refused (src/record/trace_writer.cpp): drawn as ticks on the
// concurrency strip rather than as markers of the timeline.
export const REFUSAL_NOTE = /^(motion|deformation) refused\b/;

export class TraceError extends Error {
  constructor(message, line) {
    super(line ? `line ${line}: ${message}` : message);
    this.name = 'TraceError';
    this.line = line;
  }
}

function isWhitespace(c) {
  return c === ' ' || c === '\t' || c === '\n' || c === '\r';
}

// The top-level JSON values of `text`, each as {value, line} (1-based line of its first
// character). Only objects and arrays may stand at the top level.
export function splitJsonValues(text) {
  const values = [];
  let line = 1;
  let i = 0;
  const n = text.length;
  while (i < n) {
    const c = text[i];
    if (c === '\n') {
      ++line;
      ++i;
      continue;
    }
    if (isWhitespace(c)) {
      ++i;
      continue;
    }
    if (c !== '{' && c !== '[') {
      throw new TraceError(`expected a JSON object, found '${c}'`, line);
    }
    const start = i;
    const startLine = line;
    let depth = 0;
    let inString = false;
    for (; i < n; ++i) {
      const ch = text[i];
      if (ch === '\n') ++line;
      if (inString) {
        if (ch === '\\') ++i;
        else if (ch === '"') inString = false;
        continue;
      }
      if (ch === '"') inString = true;
      else if (ch === '{' || ch === '[') ++depth;
      else if (ch === '}' || ch === ']') {
        --depth;
        if (depth === 0) {
          ++i;
          break;
        }
      }
    }
    if (depth !== 0) throw new TraceError('unterminated JSON value', startLine);
    const source = text.slice(start, i);
    try {
      values.push({ value: JSON.parse(source), line: startLine });
    } catch (error) {
      throw new TraceError(`invalid JSON: ${error.message}`, startLine);
    }
  }
  return values;
}

function isFiniteNumber(x) {
  return typeof x === 'number' && Number.isFinite(x);
}

function isVec3(v) {
  return Array.isArray(v) && v.length === 3 && v.every(isFiniteNumber);
}

function isCell(v) {
  return Array.isArray(v) && v.length === 3 && v.every(Number.isInteger);
}

function ensure(condition, message, line) {
  if (!condition) throw new TraceError(message, line);
}

function checkPart(part, where, line) {
  ensure(part && typeof part === 'object', `${where} is not an object`, line);
  ensure(Number.isInteger(part.i) && part.i >= 0, `${where} has no part index "i"`, line);
  ensure(isVec3(part.centre), `${where} has no "centre"`, line);
  ensure(
    Array.isArray(part.axes) && part.axes.length === 3 && part.axes.every(isVec3),
    `${where} has no 3 "axes"`,
    line,
  );
  ensure(isVec3(part.size), `${where} has no "size"`, line);
}

// Checks the header and returns it; errors name the field.
export function checkHeader(header, line = 1) {
  ensure(header && typeof header === 'object' && !Array.isArray(header), 'the header is not an object', line);
  ensure(
    header.format === TRACE_FORMAT,
    `not a datomsim trace: the header's "format" is ${JSON.stringify(header.format)}, expected "${TRACE_FORMAT}"`,
    line,
  );
  ensure(
    header.version === TRACE_VERSION,
    `unsupported trace version ${JSON.stringify(header.version)}: this viewer reads version ${TRACE_VERSION}`,
    line,
  );
  if ('module' in header) {
    ensure(
      MODULE_KINDS.includes(header.module),
      `"module" must be "${MODULE_KINDS[0]}" or "${MODULE_KINDS[1]}", not ${JSON.stringify(header.module)}`,
      line,
    );
  }
  ensure(isFiniteNumber(header.spacing) && header.spacing > 0, '"spacing" must be a positive number', line);
  ensure(
    header.dimensions && isFiniteNumber(header.dimensions.r) && header.dimensions.r > 0,
    '"dimensions.r" must be a positive number',
    line,
  );
  ensure(
    Array.isArray(header.orientations) &&
      header.orientations.length === 24 &&
      header.orientations.every((m) => Array.isArray(m) && m.length === 3 && m.every(isVec3)),
    '"orientations" must hold 24 matrices of 3 rows',
    line,
  );
  const k = header.kinematics;
  ensure(k && typeof k === 'object', '"kinematics" is missing', line);
  const f = k.fractions;
  ensure(
    Array.isArray(f) && f.length >= 2 && f.every(isFiniteNumber) && f[0] === 0 && f[f.length - 1] === 1,
    '"kinematics.fractions" must run from 0 to 1',
    line,
  );
  for (let s = 1; s < f.length; ++s) {
    ensure(f[s] > f[s - 1], '"kinematics.fractions" must increase', line);
  }
  ensure(Array.isArray(k.rest) && k.rest.length > 0, '"kinematics.rest" must list the parts', line);
  k.rest.forEach((part, index) => {
    checkPart(part, `kinematics.rest[${index}]`, line);
    ensure(part.i === index, `kinematics.rest[${index}] has index ${part.i}`, line);
  });
  ensure(
    Array.isArray(k.pistons) && k.pistons.length === 6,
    '"kinematics.pistons" must hold the samples of 6 pistons',
    line,
  );
  k.pistons.forEach((samples, p) => {
    ensure(
      Array.isArray(samples) && samples.length === f.length,
      `kinematics.pistons[${p}] must hold ${f.length} samples`,
      line,
    );
    samples.forEach((parts, s) => {
      ensure(Array.isArray(parts), `kinematics.pistons[${p}][${s}] is not a list`, line);
      parts.forEach((part, index) => {
        checkPart(part, `kinematics.pistons[${p}][${s}][${index}]`, line);
        ensure(part.i < k.rest.length, `kinematics.pistons[${p}][${s}] names part ${part.i}`, line);
      });
    });
  });
  ensure(Array.isArray(header.modules), '"modules" must be a list', line);
  const ids = new Set();
  header.modules.forEach((m, index) => {
    const where = `modules[${index}]`;
    ensure(m && Number.isInteger(m.id), `${where} has no integer "id"`, line);
    ensure(!ids.has(m.id), `${where}: module ${m.id} appears twice`, line);
    ids.add(m.id);
    ensure(isCell(m.cell), `${where} (module ${m.id}) has no "cell"`, line);
    ensure(isVec3(m.pos), `${where} (module ${m.id}) has no "pos"`, line);
    ensure(Number.isInteger(m.o) && m.o >= 0 && m.o < 24, `${where} (module ${m.id}) has a bad "o"`, line);
    ensure(
      Array.isArray(m.rgb) && m.rgb.length === 3 && m.rgb.every(Number.isInteger),
      `${where} (module ${m.id}) has no "rgb"`,
      line,
    );
  });
  checkTargets(header.targets, line);
  checkActuators(header.actuators, line);
  return header;
}

// What a run's actuators draw (the header's optional "actuators", docs/trace-format.md): each
// figure a number >= 0, as export/trace_check.cpp says.
export const ACTUATOR_FIGURES = ['compress_J', 'release_J', 'latch_J', 'unlatch_J', 'holding_W', 'latch_s', 'unlatch_s'];

function checkActuators(actuators, line) {
  if (actuators === undefined || actuators === null) return;
  ensure(typeof actuators === 'object' && !Array.isArray(actuators), '"actuators" must be an object', line);
  for (const key of ACTUATOR_FIGURES) {
    const value = actuators[key];
    ensure(
      isFiniteNumber(value) && value >= 0,
      `"actuators.${key}" must be a number >= 0, not ${value === undefined ? 'null' : JSON.stringify(value)}`,
      line,
    );
  }
}

// The kind of the modules of a checked header: its "module", the Datom when it has none.
export function moduleKindOf(header) {
  return header.module ?? DATOM;
}

// Checks the header's optional "targets": a list of target shapes, each a list of cells
// [x, y, z] (integers). Returns the list (empty when the header has none).
export function checkTargets(targets, line) {
  if (targets === undefined) return [];
  ensure(Array.isArray(targets), '"targets" must be a list of target shapes', line);
  targets.forEach((shape, s) => {
    ensure(Array.isArray(shape), `targets[${s}] must be a list of cells`, line);
    shape.forEach((cell, k) => {
      ensure(isCell(cell), `targets[${s}][${k}] is not a cell [x,y,z] of integers: ${JSON.stringify(cell)}`, line);
    });
  });
  return targets;
}

// Checks an overlay: {"distances": [[x,y,z,d], ...], "path": [[x,y,z], ...], "goal": [x,y,z]},
// every field optional (the document `datomsim reach --out` writes is one). Returns it
// normalised, or null when it carries nothing.
export function checkOverlay(overlay, where = 'overlay') {
  if (overlay == null) return null;
  if (typeof overlay !== 'object' || Array.isArray(overlay)) {
    throw new TraceError(`${where} is not an object`);
  }
  const distances = overlay.distances ?? [];
  const path = overlay.path ?? [];
  if (!Array.isArray(distances)) throw new TraceError(`${where}.distances is not a list`);
  if (!Array.isArray(path)) throw new TraceError(`${where}.path is not a list`);
  distances.forEach((entry, index) => {
    if (!(Array.isArray(entry) && entry.length === 4 && entry.every(Number.isInteger))) {
      throw new TraceError(`${where}.distances[${index}] is not [x,y,z,d]`);
    }
  });
  path.forEach((entry, index) => {
    if (!isCell(entry)) throw new TraceError(`${where}.path[${index}] is not [x,y,z]`);
  });
  const goal = overlay.goal ?? null;
  if (goal !== null && !isCell(goal)) throw new TraceError(`${where}.goal is not [x,y,z]`);
  if (distances.length === 0 && path.length === 0) return null;
  return { distances, path, goal };
}

function checkEvent(kind, body, ids, line, t) {
  const known = (id, field) => ensure(ids.has(id), `"${kind}" names unknown module ${JSON.stringify(id)} in "${field}"`, line);
  const duration = () =>
    ensure(isFiniteNumber(body.d) && body.d >= 0, `"${kind}" needs a duration "d" >= 0`, line);
  switch (kind) {
    case 'piston':
      known(body.m, 'm');
      ensure(Number.isInteger(body.p) && body.p >= 0 && body.p < 6, '"piston" needs "p" in 0..5', line);
      ensure(isFiniteNumber(body.from) && isFiniteNumber(body.to), '"piston" needs "from" and "to"', line);
      duration();
      break;
    case 'turn':
      known(body.m, 'm');
      ensure(isVec3(body.axis) && isVec3(body.centre), '"turn" needs "axis" and "centre"', line);
      ensure(isFiniteNumber(body.deg), '"turn" needs "deg"', line);
      duration();
      if (body.progress !== undefined) {
        ensure(
          Array.isArray(body.progress) && body.progress.length >= 2 && body.progress.every(isFiniteNumber),
          '"turn.progress" must be a list of at least 2 numbers',
          line,
        );
      }
      break;
    case 'place':
      known(body.m, 'm');
      ensure(isVec3(body.pos), '"place" needs "pos"', line);
      ensure(Number.isInteger(body.o) && body.o >= 0 && body.o < 24, '"place" needs "o" in 0..23', line);
      break;
    case 'latch':
      known(body.a, 'a');
      known(body.b, 'b');
      ensure(Number.isInteger(body.ca) && Number.isInteger(body.cb), '"latch" needs "ca" and "cb"', line);
      break;
    case 'color':
      known(body.m, 'm');
      ensure(Array.isArray(body.rgb) && body.rgb.length === 3, '"color" needs "rgb"', line);
      break;
    case 'motion':
      known(body.m, 'm');
      known(body.pivot, 'pivot');
      ensure(isCell(body.goal), '"motion" needs "goal" [x,y,z] of integers', line);
      ensure(Array.isArray(body.blockers), '"motion" needs a list "blockers"', line);
      body.blockers.forEach((id) => known(id, 'blockers'));
      ensure(isFiniteNumber(body.end) && body.end >= t, '"motion" needs an "end" time >= its "t"', line);
      break;
    default:
      break;
  }
}

// Parses a whole trace. Returns {header, module, events, duration, changeTimes, notes, refusals,
// motions, targets, overlay, end}: module the modules' kind (MODULE_KINDS); events sorted by time,
// then by their order in the file (the simulator may write an event that starts later before one
// that starts now), each {t, kind, body, line, seq}; motions {t, end, m, pivot, goal, blockers}
// from the "motion" lines, sorted by start; notes split into refusals ("motion refused: ...") and
// the others.
export function parseTrace(text) {
  const values = splitJsonValues(text);
  if (values.length === 0) throw new TraceError('the trace is empty');
  const header = checkHeader(values[0].value, values[0].line);
  const ids = new Set(header.modules.map((m) => m.id));
  const events = [];
  let end = null;
  for (let v = 1; v < values.length; ++v) {
    const { value, line } = values[v];
    ensure(value && typeof value === 'object' && !Array.isArray(value), 'a change must be an object', line);
    ensure(isFiniteNumber(value.t) && value.t >= 0, 'a change needs a time "t" >= 0', line);
    const kind = EVENT_KINDS.find((k) => k in value);
    if (!kind) continue; // a change of a later format: ignored, as the format allows
    const body = value[kind];
    if (kind !== 'note' && kind !== 'end') {
      ensure(body && typeof body === 'object', `"${kind}" must be an object`, line);
      checkEvent(kind, body, ids, line, value.t);
    }
    if (kind === 'end') end = { t: value.t, summary: body };
    events.push({ t: value.t, kind, body, line, seq: events.length });
  }
  events.sort((a, b) => a.t - b.t || a.seq - b.seq);

  // Times worth stepping to: every start and every end of a change.
  const times = new Set([0]);
  let duration = 0;
  for (const e of events) {
    times.add(e.t);
    const until = e.kind === 'piston' || e.kind === 'turn' ? e.t + e.body.d : e.kind === 'motion' ? e.body.end : e.t;
    times.add(until);
    duration = Math.max(duration, until);
  }
  const changeTimes = [...times].sort((a, b) => a - b);
  const allNotes = events.filter((e) => e.kind === 'note').map((e) => ({ t: e.t, text: String(e.body) }));
  const notes = allNotes.filter((n) => !REFUSAL_NOTE.test(n.text));
  const refusals = allNotes.filter((n) => REFUSAL_NOTE.test(n.text));
  const motions = events
    .filter((e) => e.kind === 'motion')
    .map((e) => ({
      t: e.t,
      end: e.body.end,
      m: e.body.m,
      pivot: e.body.pivot,
      goal: e.body.goal.slice(),
      blockers: e.body.blockers.slice(),
      line: e.line,
    }));
  const targets = header.targets ?? [];

  const overlay = checkOverlay(
    header.overlay ?? (header.distances || header.path ? { distances: header.distances, path: header.path } : null),
    'header.overlay',
  );
  const module = moduleKindOf(header);
  return { header, module, events, duration, changeTimes, notes, refusals, motions, targets, overlay, end };
}

// The first change time strictly after t, or null.
export function nextChangeTime(changeTimes, t, epsilon = 1e-9) {
  let lo = 0;
  let hi = changeTimes.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (changeTimes[mid] <= t + epsilon) lo = mid + 1;
    else hi = mid;
  }
  return lo < changeTimes.length ? changeTimes[lo] : null;
}

// The last change time strictly before t, or null.
export function previousChangeTime(changeTimes, t, epsilon = 1e-9) {
  let lo = 0;
  let hi = changeTimes.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (changeTimes[mid] < t - epsilon) lo = mid + 1;
    else hi = mid;
  }
  return lo > 0 ? changeTimes[lo - 1] : null;
}
