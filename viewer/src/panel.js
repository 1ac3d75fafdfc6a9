// The module panel: what a click on a module shows (docs/viewer.md, "Controls"): its id, cell,
// orientation, position, pistons (Datoms only), its part in the motions in flight, its latches,
// and the rows of the colouring shown (its latches' loads, its energy).
import { rgbToCss } from './colors.js';
import { formatSeconds } from './format.js';

export function element(tag, attributes = {}, children = []) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) {
    if (key === 'text') node.textContent = value;
    else if (key === 'className') node.className = value;
    else node.setAttribute(key, value);
  }
  for (const child of children) node.appendChild(child);
  return node;
}

// What a module does in the motions in flight: mobile, pivot, or a blocking module making way.
export function motionRoles(motions, id) {
  const roles = [];
  for (const m of motions) {
    const to = `(${m.goal.join(', ')}), ${formatSeconds(m.t)} \u2013 ${formatSeconds(m.end)}`;
    if (m.m === id) roles.push(`mobile, about pivot ${m.pivot} to ${to}`);
    if (m.pivot === id) roles.push(`pivot of ${m.m} (to ${to})`);
    if (m.blockers.includes(id)) roles.push(`makes way for ${m.m} (to ${to})`);
  }
  return roles;
}

function formatVector(v) {
  return `(${v.map((x) => Number(x.toFixed(3))).join(', ')})`;
}

// The rows of module `index` in `frame`: [key, value] pairs.
export function panelRows({ frame, index, catoms, timeline, extraRows = [] }) {
  const m = frame.modules[index];
  const rows = [
    ['module', String(m.id)],
    ['cell', m.inTransit ? `${m.cell.join(', ')} (moving)` : m.cell.join(', ')],
    ['orientation', String(m.o)],
    ['position', formatVector(m.position.toArray())],
  ];
  if (!catoms) {
    rows.push(['piston', m.piston < 0 ? 'all at rest' : `${m.piston} at ${(100 * m.fraction).toFixed(0)} %`]);
    for (const other of m.otherPistons) {
      rows.push(['also', `piston ${other.p} at ${(100 * other.fraction).toFixed(0)} %`]);
    }
  }
  for (const role of motionRoles(frame.motions, m.id)) rows.push(['motion', role]);
  const latched = [];
  for (let c = 0; c < 12; ++c) {
    if (!(m.latches & (1 << c))) continue;
    const partner = timeline.latchPartner(frame, index, c);
    latched.push(partner ? `${c} \u2192 ${partner.m}:${partner.c}` : String(c));
  }
  rows.push(['latches', latched.length ? latched.join(', ') : 'none']);
  rows.push(['', 'own connector \u2192 module:its connector']);
  rows.push(...extraRows);
  return rows;
}

// Fills `panel` with the rows of module `index`, under its title, and a close button.
export function fillPanel(panel, { frame, index, catoms, timeline, extraRows, closeButton }) {
  const m = frame.modules[index];
  const swatch = element('span', { className: 'dv-swatch' });
  swatch.style.background = rgbToCss(m.rgb);
  const rows = panelRows({ frame, index, catoms, timeline, extraRows });
  panel.replaceChildren(
    element('div', { className: 'dv-panel-title' }, [swatch, document.createTextNode(`${catoms ? '3D Catom' : 'Datom'} ${m.id}`)]),
    element(
      'table',
      {},
      rows.map(([key, value]) => element('tr', {}, [element('th', { text: key }), element('td', { text: value })])),
    ),
    closeButton,
  );
}
