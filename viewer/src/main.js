// Entry point of the bundle (dist/viewer.bundle.js). The page `datomsim view` writes carries the
// trace in <script type="application/x-ndjson" id="datomsim-trace"> and, optionally, a distance
// map in <script type="application/json" id="datomsim-overlay">; this script reads them and starts
// the viewer. A page without a trace offers to open a trace file instead; the studio's page
// (datomsim-studio) starts the studio (studio.js).
import { App } from './app.js';
import { LoadsError } from './colouring.js';
import { STYLE } from './style.js';
import { startStudio } from './studio.js';
import { TraceError, checkOverlay, parseTrace } from './trace.js';

function embedded(id) {
  const node = document.getElementById(id);
  return node ? node.textContent : null;
}

function showError(root, message) {
  console.error(`datomsim viewer: ${message}`);
  const box = document.createElement('div');
  box.className = 'dv-error';
  box.textContent = message;
  root.appendChild(box);
}

function start(root, traceText, overlayText, loadsText = null) {
  root.replaceChildren();
  try {
    const trace = parseTrace(traceText);
    let overlay = trace.overlay;
    if (overlayText && overlayText.trim()) {
      let parsed;
      try {
        parsed = JSON.parse(overlayText);
      } catch (error) {
        throw new TraceError(`the distance map is not JSON: ${error.message}`);
      }
      overlay = checkOverlay(parsed, 'distance map') ?? overlay;
    }
    let loads = null;
    if (loadsText && loadsText.trim()) {
      try {
        loads = JSON.parse(loadsText);
      } catch (error) {
        throw new TraceError(`the latch loads are not JSON: ${error.message}`);
      }
    }
    const app = new App(root, trace, overlay, loads);
    window.datomsimViewer = app.api();
  } catch (error) {
    const message =
      error instanceof TraceError
        ? `cannot read the trace: ${error.message}`
        : error instanceof LoadsError
          ? `cannot colour the latches by load: ${error.message}`
          : String(error.stack || error);
    showError(root, message);
  }
}

function offerFile(root) {
  const box = document.createElement('div');
  box.className = 'dv-open';
  const input = document.createElement('input');
  input.type = 'file';
  input.accept = '.jsonl,.json,.txt';
  box.append('Open a datomsim trace (datomsim run --trace): ', input, ' or drop it here.');
  root.appendChild(box);
  const load = (file) => file.text().then((text) => start(root, text, null));
  input.addEventListener('change', () => input.files[0] && load(input.files[0]));
  window.addEventListener('dragover', (event) => event.preventDefault());
  window.addEventListener('drop', (event) => {
    event.preventDefault();
    const file = event.dataTransfer.files[0];
    if (file) load(file);
  });
}

function main() {
  const style = document.createElement('style');
  style.textContent = STYLE;
  document.head.appendChild(style);
  // The studio's page (datomsim studio): the scene and its run come from the server.
  const studio = document.getElementById('datomsim-studio');
  if (studio) return startStudio(studio);
  let root = document.getElementById('datomsim-viewer');
  if (!root) {
    root = document.createElement('div');
    root.id = 'datomsim-viewer';
    document.body.appendChild(root);
  }
  const traceText = embedded('datomsim-trace');
  if (traceText && traceText.trim()) start(root, traceText, embedded('datomsim-overlay'), embedded('datomsim-loads'));
  else offerFile(root);
}

if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', main);
else main();
