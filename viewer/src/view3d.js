// The 3D picture: every part of every Datom as an instanced box (or every 3D Catom as a body and 12
// connector plates, catom.js), the distance map and path overlay, labels, picking and the camera.
// It draws frames that the timeline computed; it keeps no simulation state of its own.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { CSS2DObject, CSS2DRenderer } from 'three/addons/renderers/CSS2DRenderer.js';
import { CatomModel, catomDepthBelowCentre } from './catom.js';
import {
  LATCHED_CONNECTOR,
  PATH_COLOR,
  TARGET_EMPTY,
  TARGET_FILLED,
  catomPartColor,
  distanceColor,
  mixRgb,
  partColor,
} from './colors.js';
import { targetFill } from './concurrency.js';
import { thickened } from './kinematics.js';
import { cellToWorld } from './lattice.js';
import { CATOM3D, DATOM } from './trace.js';

// Parts thinner than this fraction of the radius are drawn this thick (a trace of the thin model
// has t = 0: its plates would be invisible).
export const MIN_THICKNESS = 0.06;
// Side of a distance square, and radius of the path line, in lattice spacings.
export const DISTANCE_CUBE_SIDE = 0.24;
export const PATH_RADIUS = 0.035;
// Radius of a target cell's ball, in lattice spacings (neighbour cells are 1 apart: balls never
// meet), and its opacity.
export const TARGET_RADIUS = 0.4;
export const TARGET_OPACITY = 0.38;

const BACKGROUND = 0xe9edf2;

function colorOf(rgb) {
  return new THREE.Color().setRGB(rgb[0] / 255, rgb[1] / 255, rgb[2] / 255, THREE.SRGBColorSpace);
}

export class View3D {
  constructor(container, timeline, kinematics, overlay, { shadows = true } = {}) {
    this.container = container;
    this.timeline = timeline;
    this.kinematics = kinematics;
    this.header = timeline.header;
    this.spacing = this.header.spacing;
    this.radius = this.header.dimensions.r;
    // What the modules are: Datoms drawn from their parts, or 3D Catoms, rigid bodies.
    this.moduleKind = timeline.trace.module ?? DATOM;
    this.catoms = this.moduleKind === CATOM3D;
    this.scheme = 'paper';
    this.showLatches = false;
    // Another colouring of the modules and their connectors (colourings.js), or null.
    this.colouring = null;
    this.selected = -1;

    // Renderer, camera (z up, as the lattice) and orbit controls.
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.shadowMap.enabled = shadows;
    this.renderer.shadowMap.type = THREE.PCFShadowMap;
    container.appendChild(this.renderer.domElement);
    this.labelRenderer = new CSS2DRenderer();
    this.labelRenderer.domElement.className = 'dv-labels';
    container.appendChild(this.labelRenderer.domElement);

    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(BACKGROUND);
    this.camera = new THREE.PerspectiveCamera(35, 1, 0.05, 1000);
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.enableDamping = false;
    this.controls.screenSpacePanning = true;
    this.controls.addEventListener('change', () => this.render());

    this.buildLights();
    if (this.catoms) this.buildCatoms();
    else this.buildModules();
    this.buildGround();
    this.buildOverlay(overlay);
    this.buildTargets(timeline.trace.targets ?? []);
    this.buildLabels();
    this.resize();
    this.fit();
  }

  buildLights() {
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8f99, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.8);
    sun.castShadow = true;
    sun.shadow.mapSize.set(2048, 2048);
    sun.shadow.bias = -0.0005;
    sun.shadow.normalBias = 0.02;
    this.sun = sun;
    this.scene.add(sun);
    this.scene.add(sun.target);
    const fill = new THREE.DirectionalLight(0xffffff, 0.5);
    fill.position.set(1, 1, -0.3);
    this.scene.add(fill);
  }

  // An instanced mesh of `count` instances, drawn solid (with shadows) or, for focus mode, as a
  // faded ghost: an instance is drawn by the solid mesh or its ghost and collapsed to nothing in
  // the other.
  instanced(geometry, material, count, { ghost = false } = {}) {
    const mesh = new THREE.InstancedMesh(geometry, material, Math.max(1, count));
    mesh.count = count;
    mesh.castShadow = !ghost;
    mesh.receiveShadow = !ghost;
    mesh.instanceMatrix.setUsage(THREE.DynamicDrawUsage);
    mesh.frustumCulled = false;
    const white = new THREE.Color(1, 1, 1);
    for (let i = 0; i < count; ++i) mesh.setColorAt(i, white);
    this.scene.add(mesh);
    return mesh;
  }

  ghostMaterial() {
    return new THREE.MeshLambertMaterial({ transparent: true, opacity: 0.07, depthWrite: false });
  }

  // One instance per part per module, in header order: instance = module * parts + part.
  buildModules() {
    const count = this.header.modules.length * this.kinematics.partCount;
    const geometry = new THREE.BoxGeometry(1, 1, 1);
    const material = new THREE.MeshStandardMaterial({ roughness: 0.55, metalness: 0.05 });
    this.mesh = this.instanced(geometry, material, count);
    this.ghostMesh = this.instanced(geometry, this.ghostMaterial(), count, { ghost: true });
    this.solidMeshes = [this.mesh];
    this.ghostMeshes = [this.ghostMesh];
    this.focus = false;
    this.collapsed = new THREE.Matrix4().makeScale(0, 0, 0);
    this.partPose = { centre: new THREE.Vector3(), quaternion: new THREE.Quaternion(), size: new THREE.Vector3() };
  }

  // 3D Catoms: one body per module (instance = module) and 12 connector plates per module
  // (instance = module * 12 + connector), each with its ghost for focus mode. Flat-shaded: the
  // faces of the polyhedron read as faces.
  buildCatoms() {
    const n = this.header.modules.length;
    this.catomModel = new CatomModel(this.spacing / 2);
    const material = () => new THREE.MeshStandardMaterial({ roughness: 0.55, metalness: 0.05, flatShading: true });
    const body = this.catomModel.bodyGeometry();
    const plate = new THREE.BoxGeometry(1, 1, 1);
    this.bodyMesh = this.instanced(body, material(), n);
    this.connectorMesh = this.instanced(plate, material(), 12 * n);
    this.ghostBodyMesh = this.instanced(body, this.ghostMaterial(), n, { ghost: true });
    this.ghostConnectorMesh = this.instanced(plate, this.ghostMaterial(), 12 * n, { ghost: true });
    this.solidMeshes = [this.bodyMesh, this.connectorMesh];
    this.ghostMeshes = [this.ghostBodyMesh, this.ghostConnectorMesh];
    this.focus = false;
    this.collapsed = new THREE.Matrix4().makeScale(0, 0, 0);
    this.catomMatrices = this.catomModel.matrices(new THREE.Vector3(), new THREE.Quaternion());
  }

  // What is drawn, for tests and the console: the module kind, the instances of each solid mesh,
  // and for Catoms the centre of every body as drawn.
  drawn() {
    const matrix = new THREE.Matrix4();
    const centre = new THREE.Vector3();
    const bodies = [];
    if (this.catoms) {
      for (let i = 0; i < this.bodyMesh.count; ++i) {
        this.bodyMesh.getMatrixAt(i, matrix);
        bodies.push(centre.setFromMatrixPosition(matrix).toArray());
      }
    }
    return {
      module: this.moduleKind,
      meshes: this.solidMeshes.map((mesh) => ({
        kind: mesh === this.bodyMesh ? 'catom body' : mesh === this.connectorMesh ? 'catom connector' : 'datom part',
        instances: mesh.count,
        triangles: (mesh.geometry.index ?? mesh.geometry.attributes.position).count / 3,
      })),
      bodies,
    };
  }

  // The scene's extent from the initial module centres (and overlay cells), padded by a module.
  bounds() {
    const box = new THREE.Box3();
    for (const m of this.header.modules) box.expandByPoint(new THREE.Vector3(...m.pos));
    if (this.overlayCells) for (const p of this.overlayCells) box.expandByPoint(p);
    if (this.targetCells) for (const p of this.targetCells) box.expandByPoint(p);
    if (box.isEmpty()) box.expandByPoint(new THREE.Vector3());
    box.expandByScalar(this.radius);
    return box;
  }

  buildGround() {
    const box = this.bounds();
    const size = box.getSize(new THREE.Vector3());
    const centre = box.getCenter(new THREE.Vector3());
    // The lowest point of a Datom at rest lies (r + c/2) / sqrt2 below its centre (a piston
    // plate), a Catom's lowest point is an octagon; the ground plane touches the lowest modules
    // there.
    const c = this.header.dimensions.c ?? 0.61678 * this.radius;
    const below = this.catoms ? catomDepthBelowCentre(this.spacing / 2) : (this.radius + c / 2) / Math.SQRT2;
    const groundZ = box.min.z + this.radius - below - 0.01 * this.radius;
    const extent = Math.max(size.x, size.y) * 1.6 + 4 * this.spacing;
    const ground = new THREE.Mesh(
      new THREE.PlaneGeometry(extent, extent),
      new THREE.ShadowMaterial({ opacity: 0.18 }),
    );
    ground.position.set(centre.x, centre.y, groundZ);
    ground.receiveShadow = true;
    this.scene.add(ground);
    const divisions = Math.max(2, Math.round(extent / this.spacing));
    const grid = new THREE.GridHelper(extent, divisions, 0xb4bcc8, 0xcdd3dc);
    grid.rotation.x = Math.PI / 2;
    grid.position.set(centre.x, centre.y, groundZ - 0.001);
    this.scene.add(grid);

    // The sun's shadow camera covers the scene.
    const span = Math.max(size.x, size.y, size.z) * 0.9 + 2 * this.spacing;
    this.sun.position.set(centre.x - span * 0.6, centre.y - span * 0.9, centre.z + span * 1.6);
    this.sun.target.position.copy(centre);
    const cam = this.sun.shadow.camera;
    cam.left = -span;
    cam.right = span;
    cam.top = span;
    cam.bottom = -span;
    cam.near = 0.1;
    cam.far = span * 5;
    cam.updateProjectionMatrix();
  }

  buildOverlay(overlay) {
    this.overlayGroup = new THREE.Group();
    this.scene.add(this.overlayGroup);
    this.overlayCells = [];
    if (!overlay) return;
    const s = this.spacing;

    // Distances: a small cube at the centre of every reachable cell, in the paper's colours, with
    // dark edges so that white and yellow cubes stand out.
    const distances = overlay.distances;
    if (distances.length > 0) {
      const side = DISTANCE_CUBE_SIDE * s;
      const cubes = new THREE.InstancedMesh(
        new THREE.BoxGeometry(side, side, side),
        new THREE.MeshBasicMaterial(),
        distances.length,
      );
      const matrix = new THREE.Matrix4();
      const edgePositions = [];
      const edges = new THREE.EdgesGeometry(new THREE.BoxGeometry(side, side, side));
      const edgeArray = edges.attributes.position.array;
      distances.forEach(([x, y, z, d], k) => {
        const p = cellToWorld([x, y, z], s);
        this.overlayCells.push(new THREE.Vector3(...p));
        matrix.makeTranslation(p[0], p[1], p[2]);
        cubes.setMatrixAt(k, matrix);
        cubes.setColorAt(k, colorOf(distanceColor(d)));
        for (let e = 0; e < edgeArray.length; e += 3) {
          edgePositions.push(edgeArray[e] + p[0], edgeArray[e + 1] + p[1], edgeArray[e + 2] + p[2]);
        }
      });
      this.overlayGroup.add(cubes);
      const edgeGeometry = new THREE.BufferGeometry();
      edgeGeometry.setAttribute('position', new THREE.Float32BufferAttribute(edgePositions, 3));
      this.overlayGroup.add(
        new THREE.LineSegments(edgeGeometry, new THREE.LineBasicMaterial({ color: 0x202020 })),
      );
      this.distanceCubes = cubes;
      this.distanceCells = distances;
    }

    // Path: a red tube through the centres of its cells, a ball at each cell, larger at the ends.
    const path = overlay.path;
    if (path.length > 0) {
      const red = colorOf(PATH_COLOR);
      const material = new THREE.MeshBasicMaterial({ color: red });
      const points = path.map((cell) => new THREE.Vector3(...cellToWorld(cell, s)));
      for (const p of points) this.overlayCells.push(p);
      const up = new THREE.Vector3(0, 1, 0);
      for (let k = 0; k + 1 < points.length; ++k) {
        const a = points[k];
        const b = points[k + 1];
        const length = a.distanceTo(b);
        const segment = new THREE.Mesh(
          new THREE.CylinderGeometry(PATH_RADIUS * s, PATH_RADIUS * s, length, 12),
          material,
        );
        segment.position.copy(a).add(b).multiplyScalar(0.5);
        segment.quaternion.setFromUnitVectors(up, b.clone().sub(a).normalize());
        this.overlayGroup.add(segment);
      }
      points.forEach((p, k) => {
        const end = k === 0 || k === points.length - 1;
        const ball = new THREE.Mesh(new THREE.SphereGeometry((end ? 2.6 : 1.7) * PATH_RADIUS * s, 16, 12), material);
        ball.position.copy(p);
        this.overlayGroup.add(ball);
      });
    }
  }

  // Target shapes: a translucent ball at the centre of every cell of each shape, one instanced mesh
  // per shape, only the chosen shape shown. The balls do not write depth, so a module in or behind
  // a target cell stays visible through it; empty cells and filled cells have their own colours.
  buildTargets(targets) {
    this.targets = targets;
    this.targetGroup = new THREE.Group();
    this.targetGroup.visible = true;
    this.scene.add(this.targetGroup);
    this.targetMeshes = [];
    this.targetCells = [];
    this.targetShape = 0;
    const s = this.spacing;
    const geometry = new THREE.SphereGeometry(TARGET_RADIUS * s, 24, 16);
    const material = new THREE.MeshLambertMaterial({
      transparent: true,
      opacity: TARGET_OPACITY,
      depthWrite: false,
    });
    const matrix = new THREE.Matrix4();
    targets.forEach((shape, k) => {
      const mesh = new THREE.InstancedMesh(geometry, material, Math.max(1, shape.length));
      mesh.count = shape.length;
      mesh.renderOrder = 2;
      mesh.frustumCulled = false;
      shape.forEach((cell, i) => {
        const p = cellToWorld(cell, s);
        this.targetCells.push(new THREE.Vector3(...p));
        mesh.setMatrixAt(i, matrix.makeTranslation(p[0], p[1], p[2]));
        mesh.setColorAt(i, colorOf(TARGET_EMPTY));
      });
      mesh.visible = k === this.targetShape;
      this.targetGroup.add(mesh);
      this.targetMeshes.push(mesh);
    });
    this.targetFill = null;
  }

  setTargetsVisible(visible) {
    this.targetGroup.visible = visible;
  }

  setTargetShape(k) {
    this.targetShape = k;
    this.targetMeshes.forEach((mesh, j) => {
      mesh.visible = j === k;
    });
    if (this.frame) this.updateTargets(this.frame);
  }

  // Colours the chosen shape's cells by whether a module holds them in the frame; returns
  // {cells, filled, isFilled} (null without targets).
  updateTargets(frame) {
    const shape = this.targets[this.targetShape];
    if (!shape) return null;
    const fill = targetFill(shape, frame.modules);
    const mesh = this.targetMeshes[this.targetShape];
    const empty = colorOf(TARGET_EMPTY);
    const filled = colorOf(TARGET_FILLED);
    fill.isFilled.forEach((full, i) => mesh.setColorAt(i, full ? filled : empty));
    if (mesh.instanceColor) mesh.instanceColor.needsUpdate = true;
    this.targetFill = fill;
    return fill;
  }

  buildLabels() {
    this.labels = this.header.modules.map((m) => {
      const div = document.createElement('div');
      div.className = 'dv-label';
      div.textContent = String(m.id);
      const label = new CSS2DObject(div);
      label.center.set(0.5, 0.5);
      this.scene.add(label);
      return label;
    });
    this.setLabelsVisible(false);
  }

  setLabelsVisible(visible) {
    this.labelsVisible = visible;
    this.labels.forEach((label, index) => {
      label.visible = visible || index === this.selected;
    });
  }

  setOverlayVisible(visible) {
    this.overlayGroup.visible = visible;
  }

  // Puts every module where the frame says.
  update(frame) {
    if (this.catoms) this.updateCatoms(frame);
    else this.updateDatoms(frame);
    for (const m of frame.modules) this.labels[m.index].position.copy(m.position);
    // Out of focus mode the ghosts are all collapsed: not drawing them halves a software
    // renderer's work (headless Chromium's, which makes the videos).
    for (const ghost of this.ghostMeshes) ghost.visible = this.focus;
    for (const mesh of [...this.solidMeshes, ...this.ghostMeshes]) {
      mesh.instanceMatrix.needsUpdate = true;
      if (mesh.instanceColor) mesh.instanceColor.needsUpdate = true;
      mesh.computeBoundingSphere();
    }
    this.frame = frame;
    this.updateTargets(frame);
  }

  // Every part of every Datom.
  updateDatoms(frame) {
    const kin = this.kinematics;
    const parts = kin.partCount;
    const minThickness = MIN_THICKNESS * this.radius;
    const moduleMatrix = new THREE.Matrix4();
    const partMatrix = new THREE.Matrix4();
    const one = new THREE.Vector3(1, 1, 1);
    const color = new THREE.Color();
    const pose = this.partPose;
    for (const m of frame.modules) {
      moduleMatrix.compose(m.position, m.quaternion, one);
      const selected = m.index === this.selected;
      // In focus mode only the selected module and the modules deforming or moving stay solid.
      const solid = !this.focus || selected || m.piston >= 0 || m.inTransit;
      const body = this.colouring ? this.colouring.moduleRgb(m) : m.rgb;
      const [shown, hidden] = solid ? [this.mesh, this.ghostMesh] : [this.ghostMesh, this.mesh];
      for (let i = 0; i < parts; ++i) {
        const part = kin.parts[i];
        kin.partPose(i, m.piston, m.fraction, pose);
        thickened(pose, part.kind, minThickness);
        partMatrix.compose(pose.centre, pose.quaternion, pose.size);
        partMatrix.premultiply(moduleMatrix);
        const instance = m.index * parts + i;
        shown.setMatrixAt(instance, partMatrix);
        hidden.setMatrixAt(instance, this.collapsed);
        let rgb = partColor(part.kind, body, this.scheme);
        if (part.kind === 'connector') rgb = this.connectorColor(m, part.connector, rgb);
        if (selected) rgb = mixRgb(rgb, [255, 255, 255], 0.45);
        shown.setColorAt(instance, color.copy(colorOf(rgb)));
      }
    }
  }

  // Every Catom: its body turned as the frame says, its connector plates with it. A Catom has no
  // pistons: in focus mode only the selected module and those moving stay solid.
  updateCatoms(frame) {
    const matrices = this.catomMatrices;
    const color = new THREE.Color();
    for (const m of frame.modules) {
      this.catomModel.matrices(m.position, m.quaternion, matrices);
      const selected = m.index === this.selected;
      const solid = !this.focus || selected || m.inTransit;
      const [body, ghostBody] = solid ? [this.bodyMesh, this.ghostBodyMesh] : [this.ghostBodyMesh, this.bodyMesh];
      const [plates, ghostPlates] = solid
        ? [this.connectorMesh, this.ghostConnectorMesh]
        : [this.ghostConnectorMesh, this.connectorMesh];
      const shade = (rgb) => colorOf(selected ? mixRgb(rgb, [255, 255, 255], 0.45) : rgb);
      body.setMatrixAt(m.index, matrices.body);
      ghostBody.setMatrixAt(m.index, this.collapsed);
      const own = this.colouring ? this.colouring.moduleRgb(m) : m.rgb;
      body.setColorAt(m.index, color.copy(shade(catomPartColor('body', own))));
      for (let d = 0; d < 12; ++d) {
        const instance = m.index * 12 + d;
        plates.setMatrixAt(instance, matrices.connectors[d]);
        ghostPlates.setMatrixAt(instance, this.collapsed);
        plates.setColorAt(instance, color.copy(shade(this.connectorColor(m, d, catomPartColor('connector', own)))));
      }
    }
  }

  // A connector's colour: the colouring's (latches by load), else yellow when latched and latches
  // are shown, else `rgb`.
  connectorColor(m, connector, rgb) {
    const coloured = this.colouring?.connectorRgb?.(m, connector);
    if (coloured) return coloured;
    return this.showLatches && m.latches & (1 << connector) ? LATCHED_CONNECTOR : rgb;
  }

  render() {
    this.renderer.render(this.scene, this.camera);
    this.labelRenderer.render(this.scene, this.camera);
  }

  resize() {
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(width, height);
    this.labelRenderer.setSize(width, height);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  // Frames the whole scene: from the front left and above, as the paper's figures look at it, or
  // from the top (view = 'top'), as its distance maps do. The distance is the smallest at which
  // every corner of the scene's box is inside the field of view.
  // `reservedTop` pixels at the top of the canvas are kept clear of the scene (the captions).
  fit(view = 'front', { reservedTop = 0 } = {}) {
    this.lastFit = { view, reservedTop };
    const box = this.bounds();
    const centre = box.getCenter(new THREE.Vector3());
    // Straight down would leave the orbit controls (z up) without a heading: tilt a little.
    const forward =
      view === 'top' ? new THREE.Vector3(0, 0.02, -1).normalize() : new THREE.Vector3(0.45, 1.0, -0.85).normalize();
    const up = new THREE.Vector3(0, 0, 1);
    const right = new THREE.Vector3().crossVectors(forward, up).normalize();
    const trueUp = new THREE.Vector3().crossVectors(right, forward);
    // The scene fits the canvas below the reserved band: a view of that band's height, centred
    // lower by half the band (at the target's depth; exact for the flat top view).
    const height = Math.max(1, this.container.clientHeight);
    const reserved = Math.min(0.5, Math.max(0, reservedTop / height));
    const tanFull = Math.tan(THREE.MathUtils.degToRad(this.camera.fov) / 2);
    const tanV = tanFull * (1 - reserved);
    const tanH = tanFull * this.camera.aspect;
    // Every module centre and overlay cell, with a module's radius around it, must be in view.
    // For the eye at target - D forward with target = centre + a right + b up, a point at
    // (x, y, z) in the camera frame is in view when |x - a| + r <= (z + D) tanH (and likewise for
    // y): the smallest D and its a, b are closed forms of the extreme points.
    const points = this.header.modules
      .map((m) => new THREE.Vector3(...m.pos))
      .concat(this.overlayCells, this.targetCells ?? []);
    if (points.length === 0) points.push(centre.clone());
    let [plusX, minusX, plusY, minusY] = [-Infinity, -Infinity, -Infinity, -Infinity];
    for (const point of points) {
      const p = point.clone().sub(centre);
      const x = p.dot(right);
      const y = p.dot(trueUp);
      const z = p.dot(forward);
      plusX = Math.max(plusX, (x + this.radius) / tanH - z);
      minusX = Math.max(minusX, (-x + this.radius) / tanH - z);
      plusY = Math.max(plusY, (y + this.radius) / tanV - z);
      minusY = Math.max(minusY, (-y + this.radius) / tanV - z);
    }
    const distance = 1.04 * Math.max((plusX + minusX) / 2, (plusY + minusY) / 2);
    const target = centre
      .clone()
      .addScaledVector(right, (tanH * (plusX - minusX)) / 2)
      .addScaledVector(trueUp, (tanV * (plusY - minusY)) / 2);
    target.addScaledVector(trueUp, tanFull * reserved * distance);
    this.camera.position.copy(target).addScaledVector(forward, -distance);
    this.camera.near = Math.max(0.01, distance / 200);
    this.camera.far = distance * 10;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(target);
    this.controls.update();
    this.render();
  }

  // The module under a point of the canvas (client coordinates), or -1.
  pick(clientX, clientY) {
    return this.pickPoint(clientX, clientY).index;
  }

  // The module under a point of the screen and where the ray meets it (world coordinates); or
  // index -1 and the cell of the ground layer under the point (the nearest cell whose centre's
  // plane the ray crosses), null when the ray misses that plane.
  pickPoint(clientX, clientY) {
    const rect = this.renderer.domElement.getBoundingClientRect();
    const pointer = new THREE.Vector2(
      ((clientX - rect.left) / rect.width) * 2 - 1,
      -((clientY - rect.top) / rect.height) * 2 + 1,
    );
    const raycaster = new THREE.Raycaster();
    raycaster.setFromCamera(pointer, this.camera);
    const hits = raycaster.intersectObjects(this.solidMeshes, false);
    if (hits.length === 0 || hits[0].instanceId === undefined) {
      const layerZero = new THREE.Plane(new THREE.Vector3(0, 0, 1), -(Math.SQRT2 / 4) * this.spacing);
      const at = raycaster.ray.intersectPlane(layerZero, new THREE.Vector3());
      const groundCell = at
        ? [Math.round(at.x / this.spacing - 0.5), Math.round(at.y / this.spacing - 0.5), 0]
        : null;
      return { index: -1, point: null, groundCell };
    }
    const hit = hits[0];
    let index = Math.floor(hit.instanceId / this.kinematics.partCount);
    if (hit.object === this.bodyMesh) index = hit.instanceId;
    else if (hit.object === this.connectorMesh) index = Math.floor(hit.instanceId / 12);
    return { index, point: hit.point.toArray() };
  }

  // Screen position (client coordinates) of a cell's centre.
  screenPositionOfCell(cell) {
    const p = new THREE.Vector3(...cellToWorld(cell, this.spacing)).project(this.camera);
    const rect = this.renderer.domElement.getBoundingClientRect();
    return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
  }

  // Screen position (client coordinates) of a module's centre in the current frame.
  screenPositionOf(index) {
    const m = this.frame.modules[index];
    const p = m.position.clone().project(this.camera);
    const rect = this.renderer.domElement.getBoundingClientRect();
    return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
  }

  select(index) {
    this.selected = index;
    this.setLabelsVisible(this.labelsVisible);
  }
}
