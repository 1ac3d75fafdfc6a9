// The page's URL fragment: the moment and the view a link opens at, e.g.
// "viewer.html#t=12.5&view=top&select=7". `datomsim video` adds "video", which drops the controls
// so that a frame holds the scene and its captions only.
//
//   t=SECONDS        the trace time to open at (clamped to the trace)
//   view=3d|top      the camera: from the front left and above, or from the top
//   select=ID        the module whose panel is open
//   labels           module numbers shown
//   shadows=on|off   the sun's shadows (on unless off: drawing them takes a software renderer,
//                    such as the one videos are drawn with, about 1.7 times as long)
//   video            no controls, no help line
//   colours=loads|energy  the latches coloured by load, or the modules by energy spent, when the
//                    page has them (colourings.js)
export const VIEWS = ['3d', 'top'];
export const COLOURINGS = ['own', 'loads', 'energy'];

// The settings a fragment names ("#..." or without '#'); unknown or malformed keys are ignored.
export function parseFragment(hash) {
  const settings = {};
  const text = (hash || '').replace(/^#/, '');
  if (!text) return settings;
  for (const part of text.split('&')) {
    const equals = part.indexOf('=');
    const key = decodeURIComponent(equals < 0 ? part : part.slice(0, equals));
    const value = equals < 0 ? null : decodeURIComponent(part.slice(equals + 1));
    if (key === 't' && value !== null && value.trim() !== '' && Number.isFinite(Number(value))) {
      settings.t = Number(value);
    } else if (key === 'view' && VIEWS.includes(value)) {
      settings.view = value;
    } else if (key === 'select' && /^\d+$/.test(value ?? '')) {
      settings.select = Number(value);
    } else if (key === 'shadows' && (value === 'on' || value === 'off')) {
      settings.shadows = value === 'on';
    } else if (key === 'labels' && value === null) {
      settings.labels = true;
    } else if (key === 'colours' && COLOURINGS.includes(value)) {
      settings.colours = value;
    } else if (key === 'video' && value === null) {
      settings.video = true;
    }
  }
  return settings;
}

// The fragment of a moment: time to the millisecond, the view, the selected module, labels,
// shadows when off and video mode when on; "#t=0&view=3d" at the start.
export function formatFragment({ t = 0, view = '3d', select = null, labels = false, shadows = true, video = false, colours = 'own' }) {
  const parts = [`t=${Number(t.toFixed(3))}`, `view=${view}`];
  if (select !== null && select !== undefined) parts.push(`select=${select}`);
  if (labels) parts.push('labels');
  if (!shadows) parts.push('shadows=off');
  if (colours !== 'own') parts.push(`colours=${colours}`);
  if (video) parts.push('video');
  return `#${parts.join('&')}`;
}
