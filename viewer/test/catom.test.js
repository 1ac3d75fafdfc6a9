import assert from 'node:assert/strict';
import { describe, it } from 'node:test';
import { Matrix4, Quaternion, Vector3 } from 'three';
import {
  CatomModel,
  catomBodyGeometry,
  catomDepthBelowCentre,
  catomFaces,
  catomVertices,
  connectorPlateMatrices,
} from '../src/catom.js';
import { catomPartColor } from '../src/colors.js';
import { axisVector, cellToWorld, directionVector } from '../src/lattice.js';
import { Timeline } from '../src/timeline.js';
import { parseTrace } from '../src/trace.js';
import { fixtureHeader, module, syntheticTrace } from './fixtures/synthetic.js';

const header = fixtureHeader();
const spacing = header.spacing;
const r = spacing / 2;

function near(a, b, tolerance = 1e-9) {
  assert.ok(Math.abs(a - b) <= tolerance, `${a} != ${b}`);
}

function nearVector(v, expected, tolerance = 1e-9, what = '') {
  const e = Array.isArray(expected) ? expected : expected.toArray();
  const d = Math.hypot(v.x - e[0], v.y - e[1], v.z - e[2]);
  assert.ok(d <= tolerance, `${what} (${v.toArray()}) != (${e}): ${d} apart`);
}

// The world centre and outward normal of connector d's square face, from the instance matrix of
// its plate: the unit box's +x face.
function squareFace(plateMatrix) {
  const centre = new Vector3(0.5, 0, 0).applyMatrix4(plateMatrix);
  const normal = new Vector3(1, 0, 0).transformDirection(plateMatrix);
  return { centre, normal };
}

// The orientation whose header matrix turns a by 90 degrees about world z.
function quarterTurnAboutZ() {
  return header.orientations.findIndex((rows) => {
    const [x, y, z] = rows;
    return [x[0], x[1], x[2], y[0], y[1], y[2], z[0], z[1], z[2]].every((value, k) => Math.abs(value - [0, -1, 0, 1, 0, 0, 0, 0, 1][k]) < 1e-5);
  });
}

describe('the 3D Catom body', () => {
  const faces = catomFaces(r);
  const of = (kind) => faces.filter((f) => f.kind === kind);

  it('is a truncated cuboctahedron: 12 squares, 8 hexagons, 6 octagons, 48 vertices, all edges alike', () => {
    assert.equal(of('square').length, 12);
    assert.equal(of('hexagon').length, 8);
    assert.equal(of('octagon').length, 6);
    assert.equal(catomVertices(r).length, 48);
    const edge = (2 * r) / (3 + Math.SQRT2);
    for (const face of faces) {
      const v = face.vertices;
      for (let k = 0; k < v.length; ++k) near(v[k].distanceTo(v[(k + 1) % v.length]), edge, 1e-12);
    }
  });

  it('has its 12 squares at r along the 12 lattice directions, square d facing direction d', () => {
    for (const face of of('square')) {
      const d = face.connector;
      nearVector(face.centre, directionVector(d).map((x) => x * r), 1e-12, `square ${d}`);
      nearVector(face.normal, directionVector(d), 1e-12, `normal of square ${d}`);
    }
    assert.deepEqual(of('square').map((f) => f.connector).sort((a, b) => a - b), [...Array(12).keys()]);
  });

  it('faces the octahedral holes (piston axes) with its octagons and the tetrahedral holes with its hexagons', () => {
    const depth = catomDepthBelowCentre(r);
    near(depth, (r * (1 + 2 * Math.SQRT2)) / (3 + Math.SQRT2));
    of('octagon').forEach((face, axis) => {
      nearVector(face.centre, axisVector(axis).map((x) => x * depth), 1e-12, `octagon ${axis}`);
    });
    // A tetrahedral hole lies between 3 mutually touching neighbours (and the module): the hexagon
    // faces the sum of their 3 directions.
    for (const face of of('hexagon')) {
      const touching = [...Array(12).keys()].filter((d) => new Vector3(...directionVector(d)).dot(face.normal) > 0.8);
      assert.equal(touching.length, 3, `hexagon facing ${face.normal.toArray()}`);
      const sum = touching.reduce((s, d) => s.add(new Vector3(...directionVector(d))), new Vector3()).normalize();
      nearVector(face.normal, sum, 1e-12, 'hexagon normal');
      near(face.centre.length(), (r * Math.sqrt(3) * (1 + Math.SQRT2)) / (3 + Math.SQRT2), 1e-12);
    }
  });

  it('is drawn as the hexagons and octagons, counter-clockwise from outside, the squares left to the plates', () => {
    const geometry = catomBodyGeometry(r);
    const position = geometry.attributes.position;
    const normal = geometry.attributes.normal;
    assert.equal(position.count / 3, 8 * 4 + 6 * 6, 'triangles');
    for (let t = 0; t < position.count; t += 3) {
      const [a, b, c] = [t, t + 1, t + 2].map((k) => new Vector3().fromBufferAttribute(position, k));
      const n = new Vector3().fromBufferAttribute(normal, t);
      const winding = new Vector3().crossVectors(b.clone().sub(a), c.clone().sub(a)).normalize();
      nearVector(winding, n, 1e-5, `triangle ${t / 3}`);
      assert.ok(a.dot(n) > 0.8 * r, 'a face of the body faces outwards');
    }
  });

  it('has connector plates whose outer faces are the squares, right-handed, a square side wide', () => {
    const plates = connectorPlateMatrices(r);
    const side = (2 * r) / (3 + Math.SQRT2);
    plates.forEach((plate, d) => {
      assert.ok(plate.determinant() > 0, `plate ${d} is mirrored`);
      const { centre, normal } = squareFace(plate);
      nearVector(centre, directionVector(d).map((x) => x * r), 1e-12, `plate ${d}`);
      nearVector(normal, directionVector(d), 1e-12, `plate ${d} normal`);
      const edge = new Vector3(0, 1, 0).applyMatrix4(plate).sub(new Vector3(0, 0, 0).applyMatrix4(plate));
      near(edge.length(), side, 1e-12);
    });
  });

  it('touches a neighbour square to square', () => {
    const model = new CatomModel(r);
    const a = model.matrices(new Vector3(...cellToWorld([0, 0, 0], spacing)), new Quaternion());
    for (let d = 0; d < 12; ++d) {
      const offset = new Vector3(...directionVector(d)).multiplyScalar(spacing);
      const b = model.matrices(new Vector3(...cellToWorld([0, 0, 0], spacing)).add(offset), new Quaternion());
      const mine = squareFace(a.connectors[d]);
      const theirs = squareFace(b.connectors[(d + 6) % 12]);
      nearVector(mine.centre, theirs.centre, 1e-12, `direction ${d}`);
      near(mine.normal.dot(theirs.normal), -1, 1e-12);
    }
  });

  it('colours its connectors a darker shade of the module colour', () => {
    assert.deepEqual(catomPartColor('body', [200, 100, 50]), [200, 100, 50]);
    const connector = catomPartColor('connector', [200, 100, 50]);
    connector.forEach((channel, k) => assert.ok(channel < [200, 100, 50][k] * 0.8, `channel ${k}: ${channel}`));
  });
});

describe('a 3D Catom follows turn and place lines', () => {
  // Module 2, east of module 1, turns a quarter about world z through module 1's centre, to the
  // cell north of it, in 1 s, then is placed there turned by that quarter.
  const o = quarterTurnAboutZ();
  const a = module(1, [0, 0, 0]);
  const b = module(2, [1, 0, 0]);
  const goal = [0, 1, 0];
  const trace = parseTrace(
    syntheticTrace({
      modules: [a, b],
      header: { module: 'catom3d' },
      events: [
        { t: 1, turn: { m: 2, axis: [0, 0, 1], centre: a.pos, deg: 90, d: 1 } },
        { t: 2, place: { m: 2, cell: goal, pos: cellToWorld(goal, spacing), o } },
      ],
    }),
  );
  const timeline = new Timeline(trace);
  const model = new CatomModel(r);
  const facesAt = (t) => {
    const m = timeline.frameAt(t).modules[1];
    return model.matrices(m.position, m.quaternion).connectors.map(squareFace);
  };

  it('reads as a trace of Catoms', () => {
    assert.equal(trace.module, 'catom3d');
    assert.ok(o > 0, 'a quarter turn about z is one of the 24 orientations');
  });

  it('turns its whole body about the turn axis through the centre: halfway at mid-turn', () => {
    const rest = facesAt(1);
    const middle = facesAt(1.5);
    const rotation = new Matrix4().makeRotationAxis(new Vector3(0, 0, 1), Math.PI / 4);
    const centre = new Vector3(...a.pos);
    for (let d = 0; d < 12; ++d) {
      nearVector(rest[d].centre, new Vector3(...b.pos).addScaledVector(new Vector3(...directionVector(d)), r), 1e-9, `rest ${d}`);
      const expected = rest[d].centre.clone().sub(centre).applyMatrix4(rotation).add(centre);
      nearVector(middle[d].centre, expected, 1e-9, `connector ${d} at mid-turn`);
      nearVector(middle[d].normal, rest[d].normal.clone().applyMatrix4(rotation), 1e-9, `normal ${d} at mid-turn`);
    }
    // Turned about module 1's centre, its own centre stays 2r away from it.
    near(timeline.frameAt(1.5).modules[1].position.distanceTo(centre), spacing, 1e-9);
  });

  it('after its place, sits in the goal cell with its squares on the 12 directions, turned by o', () => {
    const placed = facesAt(2.5);
    const goalCentre = new Vector3(...cellToWorld(goal, spacing));
    const rows = header.orientations[o];
    for (let d = 0; d < 12; ++d) {
      const v = directionVector(d);
      const turned = rows.map((row) => row[0] * v[0] + row[1] * v[1] + row[2] * v[2]);
      nearVector(placed[d].normal, turned, 1e-5, `normal ${d}`);
      nearVector(placed[d].centre, goalCentre.clone().addScaledVector(new Vector3(...turned), r), 1e-5, `connector ${d}`);
    }
    // Its connectors face the 12 lattice directions, each once; the one towards module 1 touches
    // module 1's square facing back.
    const facing = placed.map((f) => [...Array(12).keys()].find((d) => f.normal.dot(new Vector3(...directionVector(d))) > 1 - 1e-6));
    assert.deepEqual([...facing].sort((x, y) => x - y), [...Array(12).keys()]);
    const pivot = timeline.frameAt(2.5).modules[0];
    const pivotFaces = model.matrices(pivot.position, pivot.quaternion).connectors.map(squareFace);
    const towards = facing.indexOf(7); // the goal is north of module 1: module 1 is south (direction 7) of it
    nearVector(placed[towards].centre, pivotFaces[1].centre, 1e-5, 'the touching squares');
  });

  it('is where the turn left it at the place: no jump', () => {
    const before = facesAt(2 - 1e-9);
    const after = facesAt(2);
    for (let d = 0; d < 12; ++d) {
      nearVector(after[d].centre, before[d].centre, 1e-5, `square ${d} at the place`);
      nearVector(after[d].normal, before[d].normal, 1e-5, `normal ${d} at the place`);
    }
  });
});
