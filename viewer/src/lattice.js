// The skew FCC lattice of the simulator (docs/conventions.md, section 1; src/geometry/lattice.h):
// cell centres in world space, the 12 neighbour directions and the 6 piston axes. The viewer needs
// them for overlays (distance maps and paths are given as cells), to name the neighbour behind a
// latched connector, and to shape the 3D Catom (catom.js).

// Offsets of the neighbour cell faced by direction d = 0..11
// (docs/conventions.md, section 1 table).
export const NEIGHBOUR_OFFSETS = [
  [1, 0, 0],
  [0, 1, 0],
  [0, 0, 1],
  [-1, 0, 1],
  [-1, -1, 1],
  [0, -1, 1],
  [-1, 0, 0],
  [0, -1, 0],
  [0, 0, -1],
  [1, 0, -1],
  [1, 1, -1],
  [0, 1, -1],
];

// Twice the vector of piston axis a = 0..5, pointing at an octahedral hole, in skew cell units
// (docs/conventions.md, section 2 table; src/geometry/lattice.h). Axes 0, 1 and 4 are the cube
// frame's a, b and c, in which the 24 orientations are signed permutations.
export const DOUBLED_AXES = [
  [1, 1, 0],
  [-1, 1, 0],
  [-1, -1, 0],
  [1, -1, 0],
  [-1, -1, 2],
  [1, 1, -2],
];

// Centre of cell [x, y, z] for lattice spacing s:
// ((x + 0.5 + z/2) s, (y + 0.5 + z/2) s, (sqrt2/2)(z + 0.5) s).
export function cellToWorld(cell, spacing) {
  const [x, y, z] = cell;
  return [
    (x + 0.5 + z / 2) * spacing,
    (y + 0.5 + z / 2) * spacing,
    (Math.SQRT2 / 2) * (z + 0.5) * spacing,
  ];
}

// World vector of a cell offset (the linear part of cellToWorld).
export function offsetToWorld(offset, spacing) {
  const [x, y, z] = offset;
  return [(x + z / 2) * spacing, (y + z / 2) * spacing, (Math.SQRT2 / 2) * z * spacing];
}

// Unit world vector of direction d.
export function directionVector(direction) {
  const v = offsetToWorld(NEIGHBOUR_OFFSETS[direction], 1);
  const n = Math.hypot(v[0], v[1], v[2]);
  return [v[0] / n, v[1] / n, v[2] / n];
}

// Unit world vector of piston axis a.
export function axisVector(axis) {
  const v = offsetToWorld(DOUBLED_AXES[axis], 1);
  const n = Math.hypot(v[0], v[1], v[2]);
  return [v[0] / n, v[1] / n, v[2] / n];
}

// The direction d whose unit vector is closest to the unit vector v (largest dot product).
export function nearestDirection(v) {
  let best = 0;
  let bestDot = -Infinity;
  for (let d = 0; d < NEIGHBOUR_OFFSETS.length; ++d) {
    const u = directionVector(d);
    const dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    if (dot > bestDot) {
      bestDot = dot;
      best = d;
    }
  }
  return best;
}

export function cellKey(cell) {
  return `${cell[0]},${cell[1]},${cell[2]}`;
}

export function addCells(a, b) {
  return [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
}
