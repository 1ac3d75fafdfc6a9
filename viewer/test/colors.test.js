import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { describe, it } from 'node:test';
import { fileURLToPath } from 'node:url';
import { CONNECTOR_RED, PAPER_DISTANCE_COLORS, distanceColor, distanceLegend, partColor, rgbToCss } from '../src/colors.js';
import { NEIGHBOUR_OFFSETS, cellToWorld, directionVector, nearestDirection } from '../src/lattice.js';
import { parseTrace } from '../src/trace.js';
import { fixtureText } from './fixtures/synthetic.js';

const repository = join(dirname(fileURLToPath(import.meta.url)), '..', '..');

describe('distance colours', () => {
  it('are the paper\'s ten, as docs/pictures.md lists them', () => {
    const doc = readFileSync(join(repository, 'docs', 'pictures.md'), 'utf8');
    const rows = [...doc.matchAll(/^\| (\d) \| [a-z]+ \| (\d+), (\d+), (\d+) \|$/gm)];
    assert.equal(rows.length, 10);
    for (const row of rows) {
      assert.deepEqual(distanceColor(Number(row[1])), [Number(row[2]), Number(row[3]), Number(row[4])]);
    }
  });

  it('are the table of src/render/colors.cpp', () => {
    const source = readFileSync(join(repository, 'src', 'render', 'colors.cpp'), 'utf8');
    const table = source.slice(source.indexOf('kPaperColors'), source.indexOf('}};'));
    const entries = [...table.matchAll(/\{(\d+), (\d+), (\d+)\}/g)].map((m) => m.slice(1).map(Number));
    assert.deepEqual(entries, PAPER_DISTANCE_COLORS);
  });

  it('continue past 9 with a dark ramp, and black for no distance', () => {
    assert.deepEqual(distanceColor(10), [150, 60, 200]);
    assert.deepEqual(distanceColor(25), [15, 15, 50]);
    assert.deepEqual(distanceColor(40), [15, 15, 50]);
    assert.deepEqual(distanceColor(-1), [0, 0, 0]);
  });
});

describe('part colours', () => {
  it('draw connectors red as in the paper, or as a dark tint of the module', () => {
    assert.deepEqual(partColor('connector', [100, 200, 50], 'paper'), CONNECTOR_RED);
    assert.deepEqual(partColor('connector', [100, 200, 50], 'module'), [55, 110, 28]);
    assert.deepEqual(partColor('core', [100, 200, 50]), [100, 200, 50]);
  });
});

describe('lattice', () => {
  it('puts cells where the simulator puts modules', () => {
    const trace = parseTrace(fixtureText());
    for (const m of trace.header.modules) {
      cellToWorld(m.cell, trace.header.spacing).forEach((x, k) => assert.ok(Math.abs(x - m.pos[k]) < 1e-5));
    }
  });

  it('has 12 unit directions, opposite in pairs', () => {
    for (let d = 0; d < 12; ++d) {
      assert.equal(nearestDirection(directionVector(d)), d);
      const opposite = NEIGHBOUR_OFFSETS[(d + 6) % 12];
      assert.deepEqual(NEIGHBOUR_OFFSETS[d].map((x) => 0 - x + 0), opposite.map((x) => x + 0));
      assert.ok(Math.abs(Math.hypot(...directionVector(d)) - 1) < 1e-12);
    }
  });
});

describe('distance legend', () => {
  it('has a swatch for each distance up to the largest, in the cubes\' colours', () => {
    const legend = distanceLegend(7);
    assert.deepEqual(legend.map((e) => e.label), ['0', '1', '2', '3', '4', '5', '6', '7']);
    legend.forEach((e, d) => assert.equal(e.background, rgbToCss(distanceColor(d))));
  });

  it('shows the dark ramp past 9 as one range, from its first colour to the largest distance\'s', () => {
    const legend = distanceLegend(31);
    assert.equal(legend.length, 11);
    assert.equal(legend[10].label, '10\u201331');
    assert.equal(
      legend[10].background,
      `linear-gradient(to right, ${rgbToCss(distanceColor(10))}, ${rgbToCss(distanceColor(31))})`,
    );
    assert.equal(distanceLegend(10)[10].label, '10');
    assert.deepEqual(distanceLegend(0).map((e) => e.label), ['0']);
  });
});
