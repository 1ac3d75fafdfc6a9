// Entry point of the bundle (dist/viewer.bundle.js). The page `datomsim view` writes carries the
// trace in <script type="application/x-ndjson" id="datomsim-trace"> and, optionally, a distance
// map in <script type="application/json" id="datomsim-overlay">; this script reads them and starts
// the viewer. A page without a trace offers to open a trace file instead.
import { App } from './app.js';
import { STYLE } from './style.js';
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

function start(root, traceText, overlayText) {
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
    const app = new App(root, trace, overlay);
    window.datomsimViewer = app.api();
  } catch (error) {
    showError(root, error instanceof TraceError ? `cannot read the trace: ${error.message}` : String(error.stack || error));
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
  let root = document.getElementById('datomsim-viewer');
  if (!root) {
    root = document.createElement('div');
    root.id = 'datomsim-viewer';
    document.body.appendChild(root);
  }
  const traceText = embedded('datomsim-trace');
  if (traceText && traceText.trim()) start(root, traceText, embedded('datomsim-overlay'));
  else offerFile(root);
}

if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', main);
else main();
