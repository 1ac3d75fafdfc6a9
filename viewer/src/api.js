// What the end-to-end test and the console can drive (window.datomsimViewer): the App's state
// and actions, as plain values.
export function viewerApi(app) {
  return {
    ready: true,
    duration: app.duration,
    changeTimes: app.trace.changeTimes,
    moduleCount: app.trace.header.modules.length,
    moduleKind: app.moduleKind,
    // The instanced meshes drawn (their kind and instance count) and, for Catoms, the bodies'
    // centres as drawn.
    drawn: () => app.view.drawn(),
    time: () => app.time,
    seek: (t) => app.pauseAndSeek(t),
    step: () => app.step(),
    stepBack: () => app.stepBack(),
    play: () => app.play(),
    pause: () => app.pause(),
    setSpeed: (s) => {
      app.speed = s;
      app.speedSelect.value = String(s);
    },
    selectId: (id) => app.select(app.timeline.indexOfId.get(id) ?? -1),
    selectedInfo: () => (app.panel.hidden ? null : app.panel.innerText),
    screenPositionOf: (id) => app.view.screenPositionOf(app.timeline.indexOfId.get(id)),
    screenPositionOfCell: (cell) => app.view.screenPositionOfCell(cell),
    setLabels: (on) => app.setLabelsVisible(on),
    setOverlay: (on) => app.setOverlayVisible(on),
    setFocus: (on) => app.setFocus(on),
    setLatches: (on) => {
      app.latchesToggle.input.checked = on;
      app.view.showLatches = on;
      app.redraw();
    },
    fit: (view) => app.fit(view === 'front' ? '3d' : view),
    videoFrame: (t) => app.videoFrame(t),
    videoTurn: (degrees) => app.videoTurn(degrees),
    fragment: () => window.location.hash,
    distanceLegend: () => (app.distanceLine.hidden ? null : app.distanceLine.innerText.replace(/\s+/g, ' ').trim()),
    camera: (position, target) => {
      app.view.camera.position.set(...position);
      app.view.controls.target.set(...target);
      app.view.controls.update();
      app.view.render();
    },
    modulePose: (id) => {
      const m = app.frame.modules[app.timeline.indexOfId.get(id)];
      return { position: m.position.toArray(), piston: m.piston, fraction: m.fraction, cell: m.cell.slice() };
    },
    // Every module at the current time: id, cell (the one it holds), colour, position, piston.
    modules: () =>
      app.frame.modules.map((m) => ({
        id: m.id,
        cell: m.cell.slice(),
        rgb: m.rgb.slice(),
        position: m.position.toArray(),
        piston: m.piston,
        fraction: m.fraction,
        moving: m.moving,
      })),
    // The motions in flight now, and the strip's counts.
    motionsInFlight: () => app.frame.motions.map((m) => ({ ...m })),
    concurrency: () => ({
      max: app.timeline.motionIndex.max,
      maxAt: app.timeline.motionIndex.maxAt.map((a) => ({ from: a.from, to: Number.isFinite(a.to) ? a.to : app.duration })),
      steps: app.timeline.motionIndex.steps,
      strip: app.strip ? { label: app.strip.label.textContent, width: app.strip.inner.clientWidth } : null,
      refusals: app.trace.refusals.length,
    }),
    targets: () => ({
      shapes: app.targets.length,
      shown: app.targetShape,
      visible: app.targetsToggle.input.checked,
      cells: app.view.targetFill ? app.view.targetFill.cells : 0,
      filled: app.view.targetFill ? app.view.targetFill.filled : 0,
      legend: app.targetLine.hidden ? null : `${app.targetText.textContent} ${app.filledText.textContent}`,
    }),
    setTargets: (on) => app.setTargetsVisible(on),
    // The colourings: which the page has, the one shown, its legend and counts.
    colouring: () => app.colourings.state(),
    setColouring: (mode) => app.setColouring(mode),
    setTargetShape: (k) => app.setTargetShape(k),
  };
}
