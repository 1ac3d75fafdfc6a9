// The 3D Catom (Piranda and Bourgeois, "Designing a quasi-spherical module for a huge modular robot
// to create programmable matter", Autonomous Robots, 2018): a rigid, quasi-spherical module in the
// same FCC cells as the Datom. Its body is a truncated cuboctahedron, 12 squares (the connectors),
// 8 hexagons and 6 octagons, whose vertices are the permutations of (+-1, +-(1 + sqrt2),
// +-(1 + 2 sqrt2)) in its own cube frame. Scaled so that the squares lie at r = spacing / 2 from the
// centre, two neighbours touch square to square. It has no pistons: it moves only by the trace's
// `turn` lines (a rotation of the whole body) and `place` lines, as the Datom's body does.
//
// The body is built in the module frame, the frame the header's orientation matrices map to the
// world: its cube frame is that of the piston axes (axes 0, 1 and 4 are a, b, c), so the squares'
// normals are the 12 lattice directions (connector d faces direction d at orientation 0), the
// octagons face the 6 octahedral holes (the Datom's piston axes) and the hexagons the 8
// tetrahedral holes. A module at orientation o is this rest body turned by the header's matrix o.
import { BufferGeometry, Float32BufferAttribute, Matrix4, Vector3 } from 'three';
import { axisVector, directionVector } from './lattice.js';

const SQRT2 = Math.SQRT2;
// Distances of the faces from the centre, in the polyhedron's own units (edge 2): the squares are
// the farthest, so the body stays inside the sphere of radius r but for its vertices.
export const SQUARE_DISTANCE = 3 + SQRT2;
export const OCTAGON_DISTANCE = 1 + 2 * SQRT2;
export const HEXAGON_DISTANCE = Math.sqrt(3) * (1 + SQRT2);
// A connector plate's thickness, in radii. Its outer face is the square face itself: the body
// leaves the squares open and the plates close it, so no two faces fight for the same pixels.
export const PLATE_THICKNESS = 0.05;

const FACE_SIDES = { square: 4, hexagon: 6, octagon: 8 };

// The body's cube frame in the module frame: the piston axes 0, 1 and 4.
function cubeFrame() {
  return [0, 1, 4].map((a) => new Vector3(...axisVector(a)));
}

// The 48 vertices for a body whose squares lie at `radius`, in the module frame.
export function catomVertices(radius) {
  const scale = radius / SQUARE_DISTANCE;
  const [a, b, c] = cubeFrame();
  const values = [1, 1 + SQRT2, 1 + 2 * SQRT2];
  const permutations = [[0, 1, 2], [0, 2, 1], [1, 0, 2], [1, 2, 0], [2, 0, 1], [2, 1, 0]];
  const vertices = [];
  for (const [i, j, k] of permutations) {
    for (let signs = 0; signs < 8; ++signs) {
      const x = values[i] * (signs & 1 ? -1 : 1);
      const y = values[j] * (signs & 2 ? -1 : 1);
      const z = values[k] * (signs & 4 ? -1 : 1);
      vertices.push(new Vector3().addScaledVector(a, x).addScaledVector(b, y).addScaledVector(c, z).multiplyScalar(scale));
    }
  }
  return vertices;
}

// The outward unit normals of the faces, with their kinds: square d faces direction d (and is
// connector d), octagon a faces piston axis a, the hexagons the sums of three orthogonal axes.
function faceNormals() {
  const normals = [];
  for (let d = 0; d < 12; ++d) normals.push({ kind: 'square', connector: d, normal: new Vector3(...directionVector(d)) });
  for (let axis = 0; axis < 6; ++axis) normals.push({ kind: 'octagon', connector: -1, normal: new Vector3(...axisVector(axis)) });
  const [a, b, c] = cubeFrame();
  for (let signs = 0; signs < 8; ++signs) {
    const normal = new Vector3()
      .addScaledVector(a, signs & 1 ? -1 : 1)
      .addScaledVector(b, signs & 2 ? -1 : 1)
      .addScaledVector(c, signs & 4 ? -1 : 1)
      .normalize();
    normals.push({ kind: 'hexagon', connector: -1, normal });
  }
  return normals;
}

// The 26 faces of a body whose squares lie at `radius`, in the module frame: {kind, connector (d
// for a square, else -1), normal, centre, vertices}, vertices counter-clockwise seen from outside.
// A face is the set of vertices farthest along its normal.
export function catomFaces(radius) {
  const vertices = catomVertices(radius);
  const tolerance = 1e-9 * radius;
  return faceNormals().map(({ kind, connector, normal }) => {
    const farthest = Math.max(...vertices.map((v) => v.dot(normal)));
    const corners = vertices.filter((v) => v.dot(normal) > farthest - tolerance);
    if (corners.length !== FACE_SIDES[kind]) {
      throw new Error(`a Catom ${kind} has ${corners.length} vertices`);
    }
    const centre = corners.reduce((sum, v) => sum.add(v), new Vector3()).multiplyScalar(1 / corners.length);
    // Around the normal: u, w = normal x u and normal are right-handed, so increasing angles turn
    // counter-clockwise seen from outside.
    const u = corners[0].clone().sub(centre).normalize();
    const w = new Vector3().crossVectors(normal, u);
    const angle = (v) => {
      const r = v.clone().sub(centre);
      return Math.atan2(r.dot(w), r.dot(u));
    };
    corners.sort((p, q) => angle(p) - angle(q));
    return { kind, connector, normal: normal.clone(), centre, vertices: corners };
  });
}

// The body without its squares (the connector plates close it): the 8 hexagons and 6 octagons as
// triangle fans, flat normals, unindexed so that every face keeps its own normal.
export function catomBodyGeometry(radius) {
  const positions = [];
  const normals = [];
  for (const face of catomFaces(radius)) {
    if (face.kind === 'square') continue;
    const v = face.vertices;
    for (let k = 1; k + 1 < v.length; ++k) {
      for (const p of [v[0], v[k], v[k + 1]]) {
        positions.push(p.x, p.y, p.z);
        normals.push(face.normal.x, face.normal.y, face.normal.z);
      }
    }
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute(positions, 3));
  geometry.setAttribute('normal', new Float32BufferAttribute(normals, 3));
  geometry.computeBoundingSphere();
  return geometry;
}

// For each connector d = 0..11, the matrix (module frame) that turns the unit box centred on the
// origin into its plate: the box's x along the square's normal, from the square inwards by the
// plate's thickness, y and z along the square's edges. The box's +x face is the square face.
export function connectorPlateMatrices(radius) {
  const thickness = PLATE_THICKNESS * radius;
  const plates = new Array(12);
  for (const face of catomFaces(radius)) {
    if (face.kind !== 'square') continue;
    const [p0, p1, p2] = face.vertices;
    const side = p0.distanceTo(p1);
    const along = p1.clone().sub(p0).normalize();
    const across = p2.clone().sub(p1).normalize();
    const n = face.normal;
    const centre = face.centre.clone().addScaledVector(n, -thickness / 2);
    plates[face.connector] = new Matrix4().set(
      n.x * thickness, along.x * side, across.x * side, centre.x,
      n.y * thickness, along.y * side, across.y * side, centre.y,
      n.z * thickness, along.z * side, across.z * side, centre.z,
      0, 0, 0, 1,
    );
  }
  return plates;
}

// How far below its centre a Catom at rest reaches: an octagon faces straight down (axis 5) in
// every one of the 24 orientations.
export function catomDepthBelowCentre(radius) {
  return (radius * OCTAGON_DISTANCE) / SQUARE_DISTANCE;
}

// The model of one Catom for drawing: body geometry, and the plates' matrices in the module frame.
export class CatomModel {
  constructor(radius) {
    this.radius = radius;
    this.plates = connectorPlateMatrices(radius);
    this.one = new Vector3(1, 1, 1);
  }

  bodyGeometry() {
    return catomBodyGeometry(this.radius);
  }

  // The instance matrices of a module whose body is at `position`, turned by `quaternion` (from
  // the timeline's frame): its body's, and its 12 connector plates', written into `out`.
  matrices(position, quaternion, out = { body: new Matrix4(), connectors: this.plates.map(() => new Matrix4()) }) {
    out.body.compose(position, quaternion, this.one);
    for (let d = 0; d < 12; ++d) out.connectors[d].multiplyMatrices(out.body, this.plates[d]);
    return out;
  }
}
