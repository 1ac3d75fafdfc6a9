import assert from 'node:assert/strict';
import { describe, it } from 'node:test';
import { Quaternion, Vector3 } from 'three';
import { Kinematics, thickened } from '../src/kinematics.js';
import { fixtureHeader } from './fixtures/synthetic.js';

const header = fixtureHeader();
const kin = new Kinematics(header);

function near(a, b, tolerance = 1e-5) {
  assert.ok(Math.abs(a - b) <= tolerance, `${a} != ${b}`);
}

function nearVector(v, expected, tolerance = 1e-5) {
  near(v.x, expected[0], tolerance);
  near(v.y, expected[1], tolerance);
  near(v.z, expected[2], tolerance);
}

// The k-th axis of a pose.
function axis(pose, k) {
  const unit = [new Vector3(1, 0, 0), new Vector3(0, 1, 0), new Vector3(0, 0, 1)][k];
  return unit.applyQuaternion(pose.quaternion);
}

describe('Kinematics', () => {
  it('has the 43 parts of the model: core, 6 pistons, 24 links, 12 connectors', () => {
    const count = (kind) => kin.parts.filter((p) => p.kind === kind).length;
    assert.equal(kin.partCount, 43);
    assert.deepEqual([count('core'), count('piston'), count('link'), count('connector')], [1, 6, 24, 12]);
  });

  it('puts every part at rest where the header says, axes included', () => {
    for (const part of header.kinematics.rest) {
      const pose = kin.partPose(part.i, -1, 0);
      nearVector(pose.centre, part.centre);
      for (let k = 0; k < 3; ++k) nearVector(axis(pose, k), part.axes[k], 2e-5);
      nearVector(pose.size, part.size);
    }
  });

  it('gives the C++ samples exactly at the sampled fractions', () => {
    for (let p = 0; p < 6; ++p) {
      header.kinematics.fractions.forEach((f, s) => {
        for (const part of header.kinematics.pistons[p][s]) {
          const pose = kin.partPose(part.i, p, f);
          nearVector(pose.centre, part.centre);
          for (let k = 0; k < 3; ++k) nearVector(axis(pose, k), part.axes[k], 2e-5);
        }
      });
    }
  });

  it('interpolates between two samples: centres linearly, rotations on the shortest arc', () => {
    const [a, b] = [header.kinematics.pistons[0][2], header.kinematics.pistons[0][3]];
    const f = (header.kinematics.fractions[2] + header.kinematics.fractions[3]) / 2;
    a.forEach((partA, index) => {
      const partB = b[index];
      const pose = kin.partPose(partA.i, 0, f);
      nearVector(pose.centre, partA.centre.map((x, k) => (x + partB.centre[k]) / 2));
      // Half-way in angle: the rotation from A to the pose equals the one from the pose to B.
      const qa = kin.partPose(partA.i, 0, header.kinematics.fractions[2]).quaternion;
      const qb = kin.partPose(partA.i, 0, header.kinematics.fractions[3]).quaternion;
      near(pose.quaternion.angleTo(qa), pose.quaternion.angleTo(qb), 1e-6);
    });
  });

  it('compresses piston 0 fully: plate on the core, its connectors facing along the piston', () => {
    const u = new Vector3(1, 1, 0).normalize();
    const c = header.dimensions.c;
    const plate = kin.parts.find((p) => p.kind === 'piston' && p.piston === 0);
    near(kin.partPose(plate.i, 0, 1).centre.dot(u), c / 2);
    for (const connector of [0, 1, 2, 10]) {
      const part = kin.parts.find((p) => p.kind === 'connector' && p.connector === connector);
      nearVector(axis(kin.partPose(part.i, 0, 1), 0), u.toArray(), 2e-5);
    }
  });

  it('leaves the parts a piston does not move at rest', () => {
    const moved = kin.moved[4];
    assert.equal(moved.size, 9, 'a plate, 4 links and 4 connectors');
    for (const part of kin.parts) {
      if (moved.has(part.i)) continue;
      const pose = kin.partPose(part.i, 4, 0.6);
      nearVector(pose.centre, kin.parts[part.i].rest.centre.toArray());
    }
  });

  it('clamps fractions outside [0, 1]', () => {
    const part = kin.parts.find((p) => p.kind === 'connector' && p.connector === 2);
    nearVector(kin.partPose(part.i, 0, 1.5).centre, kin.partPose(part.i, 0, 1).centre.toArray());
    nearVector(kin.partPose(part.i, 0, -1).centre, kin.partPose(part.i, 0, 0).centre.toArray());
  });
});

describe('thickened', () => {
  it('thickens a thin connector inwards, keeping its contact face', () => {
    const pose = {
      centre: new Vector3(1, 0, 0),
      quaternion: new Quaternion(),
      size: new Vector3(0, 0.6, 0.6),
    };
    thickened(pose, 'connector', 0.1);
    nearVector(pose.size, [0.1, 0.6, 0.6]);
    nearVector(pose.centre, [0.95, 0, 0]);
    near(pose.centre.x + pose.size.x / 2, 1);
  });

  it('thickens links and pistons on both sides and leaves thick parts alone', () => {
    const link = { centre: new Vector3(0, 0, 1), quaternion: new Quaternion(), size: new Vector3(0.18, 0.6, 0) };
    thickened(link, 'link', 0.05);
    nearVector(link.centre, [0, 0, 1]);
    nearVector(link.size, [0.18, 0.6, 0.05]);
    const core = { centre: new Vector3(), quaternion: new Quaternion(), size: new Vector3(0.5, 0.5, 0.5) };
    thickened(core, 'core', 0.05);
    nearVector(core.size, [0.5, 0.5, 0.5]);
  });
});
