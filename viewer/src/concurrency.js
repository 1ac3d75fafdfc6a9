// Motions in flight over time, from the trace's "motion" lines, and the target shapes' filled
// cells: what the concurrency strip and the target legend show. Pure functions of the trace (and
// of a frame), so that they are the same however the viewer got to a time.
//
// A motion is in flight from its start t to its end, end excluded: a motion that ends at T and
// one that starts at T are never counted together, and a motion of no duration never counts.

// The number of motions in flight as a step function: [{t, count}], sorted by t, the first at
// t = 0; count holds from t until the next step. At equal times the ends are taken before the
// starts, and one step gives the count after every change at its time.
export function concurrencySteps(motions) {
  const changes = [];
  for (const m of motions) {
    if (!(m.end > m.t)) continue;
    changes.push([m.t, 1], [m.end, -1]);
  }
  changes.sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  const steps = [{ t: 0, count: 0 }];
  let count = 0;
  for (const [t, delta] of changes) {
    count += delta;
    const last = steps[steps.length - 1];
    if (last.t === t) last.count = count;
    else steps.push({ t, count });
  }
  // Steps that do not change the count are dropped.
  return steps.filter((s, k) => k === 0 || s.count !== steps[k - 1].count);
}

// The count of a step function at time t.
export function countAt(steps, t) {
  let lo = 0;
  let hi = steps.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (steps[mid].t <= t) lo = mid + 1;
    else hi = mid;
  }
  return lo > 0 ? steps[lo - 1].count : 0;
}

// The largest count and the intervals [from, to) that reach it (to = Infinity for the last step).
export function maxConcurrency(steps) {
  let max = 0;
  for (const s of steps) max = Math.max(max, s.count);
  const at = [];
  steps.forEach((s, k) => {
    if (s.count === max && max > 0) at.push({ from: s.t, to: k + 1 < steps.length ? steps[k + 1].t : Infinity });
  });
  return { max, at };
}

// The motions in flight at time t (start <= t < end), in start order. `motions` sorted by start.
export class MotionIndex {
  constructor(motions) {
    this.motions = motions.slice().sort((a, b) => a.t - b.t);
    this.longest = 0;
    for (const m of this.motions) this.longest = Math.max(this.longest, m.end - m.t);
    this.steps = concurrencySteps(this.motions);
    const { max, at } = maxConcurrency(this.steps);
    this.max = max;
    this.maxAt = at;
  }

  inFlightAt(t) {
    // The last motion starting at or before t, then back while a motion could still be running.
    let lo = 0;
    let hi = this.motions.length;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (this.motions[mid].t <= t) lo = mid + 1;
      else hi = mid;
    }
    const result = [];
    for (let k = lo - 1; k >= 0 && this.motions[k].t >= t - this.longest; --k) {
      const m = this.motions[k];
      if (t < m.end) result.push(m);
    }
    return result.reverse();
  }

  countAt(t) {
    return countAt(this.steps, t);
  }
}

function key(cell) {
  return `${cell[0]},${cell[1]},${cell[2]}`;
}

// The cells of a target shape that hold a module in a frame: a module fills the cell it holds
// (its cell changes when a "place" line moves it, at the end of its motion). Returns
// {cells: N, filled: M, isFilled: [bool per cell of the shape]}; a cell listed twice counts once.
export function targetFill(shape, modules) {
  const occupied = new Set(modules.map((m) => key(m.cell)));
  const seen = new Set();
  let filled = 0;
  const isFilled = shape.map((cell) => {
    const k = key(cell);
    const full = occupied.has(k);
    if (!seen.has(k)) {
      seen.add(k);
      if (full) ++filled;
    }
    return full;
  });
  return { cells: seen.size, filled, isFilled };
}
