// The parts of one module and their poses for a piston state, from the samples the C++ kinematics
// wrote into the trace header ("kinematics": rest parts, and for each own piston the parts it
// moves at fractions 0, 1/8, ..., 1). The viewer does not solve the mechanism: between two
// samples it interpolates each moved part, its centre linearly and its rotation spherically.
import { Matrix4, Quaternion, Vector3 } from 'three';

// A part's box in the module frame: it spans centre +- axis_k * size[k] / 2, where axis_k is the
// k-th column of the rotation `quaternion`.
function poseOfPart(part) {
  const [a0, a1, a2] = part.axes;
  const rotation = new Matrix4().set(
    a0[0], a1[0], a2[0], 0,
    a0[1], a1[1], a2[1], 0,
    a0[2], a1[2], a2[2], 0,
    0, 0, 0, 1,
  );
  return {
    centre: new Vector3(...part.centre),
    quaternion: new Quaternion().setFromRotationMatrix(rotation).normalize(),
    size: new Vector3(...part.size),
  };
}

export class Kinematics {
  constructor(header) {
    const k = header.kinematics;
    this.radius = header.dimensions.r;
    this.thickness = header.dimensions.t ?? 0;
    this.fractions = k.fractions.slice();
    this.parts = k.rest.map((part) => ({
      i: part.i,
      kind: part.kind,
      piston: part.piston,
      connector: part.connector,
      rest: poseOfPart(part),
    }));
    // samples[p][s]: Map part index -> pose; moved[p]: the part indices piston p moves.
    this.samples = k.pistons.map((perSample) =>
      perSample.map((parts) => new Map(parts.map((part) => [part.i, poseOfPart(part)]))),
    );
    this.moved = this.samples.map((perSample) => new Set(perSample[0].keys()));
  }

  get partCount() {
    return this.parts.length;
  }

  // The sample segment [s, s + 1] holding fraction f (clamped to [0, 1]) and the weight of s + 1.
  segment(fraction) {
    const f = Math.min(1, Math.max(0, fraction));
    const fr = this.fractions;
    let s = 0;
    while (s < fr.length - 2 && f > fr[s + 1]) ++s;
    return { s, alpha: (f - fr[s]) / (fr[s + 1] - fr[s]) };
  }

  // Pose of part i with own piston `piston` (-1: at rest) compressed to `fraction`, written into
  // `out` ({centre, quaternion, size}, three.js objects) and returned.
  partPose(i, piston, fraction, out = { centre: new Vector3(), quaternion: new Quaternion(), size: new Vector3() }) {
    if (piston < 0 || !this.moved[piston].has(i)) {
      const rest = this.parts[i].rest;
      out.centre.copy(rest.centre);
      out.quaternion.copy(rest.quaternion);
      out.size.copy(rest.size);
      return out;
    }
    const { s, alpha } = this.segment(fraction);
    const a = this.samples[piston][s].get(i);
    const b = this.samples[piston][s + 1].get(i);
    out.centre.lerpVectors(a.centre, b.centre, alpha);
    out.quaternion.slerpQuaternions(a.quaternion, b.quaternion, alpha);
    out.size.lerpVectors(a.size, b.size, alpha);
    return out;
  }

  // The poses of all parts.
  poses(piston, fraction) {
    return this.parts.map((part) => this.partPose(part.i, piston, fraction));
  }
}

// The box drawn for a part: parts thinner than `minThickness` (a trace of the thin model has
// t = 0) are thickened to it. A connector grows inwards, so that its contact face stays where it
// is; pistons and links grow on both sides of their thin plane. Modifies `pose` and returns it.
export function thickened(pose, kind, minThickness) {
  const size = pose.size;
  if (kind === 'connector' && size.x < minThickness) {
    const grow = minThickness - size.x;
    const normal = new Vector3(1, 0, 0).applyQuaternion(pose.quaternion);
    pose.centre.addScaledVector(normal, -grow / 2);
  }
  size.set(Math.max(size.x, minThickness), Math.max(size.y, minThickness), Math.max(size.z, minThickness));
  return pose;
}
