// Marks on the overloaded latches while latches are coloured by load: a red ball at the centre
// of each such latch, drawn over the modules (no depth test), since a latch lies between two
// modules where the camera rarely sees it.
import * as THREE from 'three';

export const MARK_COLOR = 0xe00000;

export class OverloadMarks {
  constructor(scene, spacing, capacity) {
    const geometry = new THREE.SphereGeometry(0.16 * spacing, 16, 12);
    const material = new THREE.MeshBasicMaterial({ color: MARK_COLOR, depthTest: false, transparent: true, opacity: 0.9 });
    this.mesh = new THREE.InstancedMesh(geometry, material, Math.max(1, capacity));
    this.mesh.renderOrder = 10;
    this.mesh.count = 0;
    this.mesh.frustumCulled = false;
    scene.add(this.mesh);
    this.matrix = new THREE.Matrix4();
  }

  // Puts a mark at each point ([x, y, z], world), none when the list is empty.
  update(points) {
    const count = Math.min(points.length, this.mesh.instanceMatrix.count);
    points.slice(0, count).forEach((p, k) => this.mesh.setMatrixAt(k, this.matrix.makeTranslation(p[0], p[1], p[2])));
    this.mesh.count = count;
    this.mesh.instanceMatrix.needsUpdate = true;
  }
}
