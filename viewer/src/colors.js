// The viewer's colours: distances (a copy of src/render/colors.cpp, checked by a unit test against
// docs/pictures.md) and the colours of a module's parts.

// Paper, figure "gradient" caption; docs/conventions.md, section 7. Green and pink as in
// src/render/colors.cpp.
export const PAPER_DISTANCE_COLORS = [
  [255, 0, 0], // 0 red
  [255, 165, 0], // 1 orange
  [255, 255, 0], // 2 yellow
  [0, 200, 0], // 3 green
  [0, 0, 255], // 4 blue
  [0, 255, 255], // 5 cyan
  [255, 105, 180], // 6 pink
  [128, 128, 128], // 7 grey
  [250, 128, 114], // 8 salmon
  [255, 255, 255], // 9 white
];

export const DARK_RAMP_END = 25;
const RAMP_START = [150, 60, 200];
const RAMP_END = [15, 15, 50];

// Colour of the path line (render::kPathColor).
export const PATH_COLOR = [220, 0, 0];

// Target cells (translucent balls): a cell no module holds yet, and a cell a module holds.
export const TARGET_EMPTY = [40, 170, 235];
export const TARGET_FILLED = [150, 90, 225];

function mixChannel(from, to, t) {
  return Math.round(from + (to - from) * t);
}

export function mixRgb(from, to, t) {
  return [mixChannel(from[0], to[0], t), mixChannel(from[1], to[1], t), mixChannel(from[2], to[2], t)];
}

// The colour of a cell at `distance` motions from the goal, as render::distanceColor: the paper's
// ten colours for 0..9, then a violet-to-navy ramp up to 25, black for negative distances.
export function distanceColor(distance) {
  if (distance < 0) return [0, 0, 0];
  if (distance < PAPER_DISTANCE_COLORS.length) return PAPER_DISTANCE_COLORS[distance];
  const t =
    (Math.min(distance, DARK_RAMP_END) - PAPER_DISTANCE_COLORS.length) /
    (DARK_RAMP_END - PAPER_DISTANCE_COLORS.length);
  return mixRgb(RAMP_START, RAMP_END, t);
}

// Connectors are drawn red, as in every figure of the paper ("large connectors (drawn in red in
// all following figures)", section I); the body (core, pistons, links) in the module's colour,
// links a little darker so that the mechanism reads. The "module" scheme draws connectors as a
// dark tint of the module colour instead, for scenes where red would be confused with distance 0.
export const CONNECTOR_RED = [200, 30, 30];
export const LATCHED_CONNECTOR = [255, 200, 40];
export const PART_SCHEMES = ['paper', 'module'];

export function partColor(kind, rgb, scheme = 'paper') {
  switch (kind) {
    case 'connector':
      return scheme === 'paper' ? CONNECTOR_RED : mixRgb(rgb, [0, 0, 0], 0.45);
    case 'link':
      return mixRgb(rgb, [0, 0, 0], 0.25);
    case 'piston':
      return mixRgb(rgb, [255, 255, 255], 0.15);
    default:
      return rgb;
  }
}

// A 3D Catom's body is in the module's colour and its 12 square connectors a darker shade of it:
// the squares are where it latches, and the shade tells them apart under any light.
export const CATOM_CONNECTOR_SHADE = 0.4;

export function catomPartColor(kind, rgb) {
  return kind === 'connector' ? mixRgb(rgb, [0, 0, 0], CATOM_CONNECTOR_SHADE) : rgb;
}

export function rgbToCss(rgb) {
  return `rgb(${rgb[0]}, ${rgb[1]}, ${rgb[2]})`;
}

// The legend of the distance cubes up to `max`: one swatch for each of the paper's ten colours
// used, then one for the dark ramp's range (10 to max), drawn as the ramp it is.
export function distanceLegend(max) {
  const entries = [];
  const named = Math.min(max, PAPER_DISTANCE_COLORS.length - 1);
  for (let d = 0; d <= named; ++d) {
    const rgb = distanceColor(d);
    entries.push({ label: String(d), title: `${d} motion${d === 1 ? '' : 's'} to the goal`, background: rgbToCss(rgb), dark: d === 4 });
  }
  if (max >= PAPER_DISTANCE_COLORS.length) {
    const from = PAPER_DISTANCE_COLORS.length;
    const label = max === from ? String(from) : `${from}\u2013${max}`;
    const end = distanceColor(max);
    entries.push({
      label,
      title: `${label} motions to the goal: violet to navy${max > DARK_RAMP_END ? `, navy from ${DARK_RAMP_END}` : ''}`,
      background: `linear-gradient(to right, ${rgbToCss(distanceColor(from))}, ${rgbToCss(end)})`,
      dark: true,
    });
  }
  return entries;
}
