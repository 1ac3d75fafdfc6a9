// The viewer's input: a click on a module selects it (and tells the studio, App.onPick), and the
// keys of the help line. Every listener on the window ends with the app (App.dispose).

export function installAppInput(app) {
  const canvas = app.view.renderer.domElement;
  let down = null;
  canvas.addEventListener('pointerdown', (event) => {
    down = { x: event.clientX, y: event.clientY };
  });
  canvas.addEventListener('pointerup', (event) => {
    if (!down) return;
    const moved = Math.hypot(event.clientX - down.x, event.clientY - down.y);
    down = null;
    if (moved > 4) return; // a drag of the camera, not a click
    const picked = app.view.pickPoint(event.clientX, event.clientY);
    app.select(picked.index);
    // The studio's: a click names a cell (a module's, or the ground's), a shift-click a face or a
    // ground cell to add a module on.
    if (app.onPick) app.onPick(picked.index, picked.point, event, picked.groundCell);
  });
  const signal = app.listening.signal;
  window.addEventListener(
    'resize',
    () => {
      app.view.resize();
      if (app.strip) app.strip.draw();
    },
    { signal },
  );
  window.addEventListener('keydown', (event) => {
    if (event.target instanceof HTMLInputElement && event.target.type !== 'range' && event.target.type !== 'checkbox') return;
    if (event.target instanceof HTMLSelectElement) return;
    switch (event.key) {
      case ' ':
        app.togglePlay();
        break;
      case 'ArrowRight':
        app.step();
        break;
      case 'ArrowLeft':
        app.stepBack();
        break;
      case 'Home':
        app.pauseAndSeek(0);
        break;
      case 'End':
        app.pauseAndSeek(app.duration);
        break;
      case 'f':
      case 'F':
        app.fit('3d');
        return;
      case 't':
      case 'T':
        app.fit('top');
        return;
      case 'l':
      case 'L':
        app.setLabelsVisible(!app.labelsToggle.input.checked);
        return;
      case 'x':
      case 'X':
        app.setFocus(!app.view.focus);
        return;
      case 'g':
      case 'G':
        if (app.targets.length) app.setTargetsVisible(!app.targetsToggle.input.checked);
        return;
      case 'c':
      case 'C':
        app.setColouring(app.colourings.modes[(app.colourings.modes.indexOf(app.colourings.mode) + 1) % app.colourings.modes.length]);
        return;
      case 'Escape':
        app.select(-1);
        return;
      default:
        return;
    }
    event.preventDefault();
  }, { signal });
}
