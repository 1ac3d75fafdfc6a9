// The viewer's style sheet, injected by main.js so that the page needs nothing but the bundle.
export const STYLE = `
html, body { margin: 0; height: 100%; overflow: hidden; background: #e9edf2;
  font: 13px/1.35 system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif; color: #1d2430; }
#datomsim-viewer { position: fixed; inset: 0; --dv-bar: 52px; }
#datomsim-viewer.dv-has-strip { --dv-bar: 96px; }
#datomsim-viewer.dv-video { --dv-bar: 0px; }
#datomsim-viewer.dv-video .dv-bar, #datomsim-viewer.dv-video .dv-help { display: none; }
.dv-clock { font-variant-numeric: tabular-nums; color: #1d2430; font-weight: 600; }
.dv-video .dv-top { max-width: calc(100% - 24px); }
#datomsim-viewer [hidden] { display: none !important; }
.dv-canvas { position: absolute; inset: 0 0 var(--dv-bar) 0; }
.dv-canvas canvas { display: block; }
.dv-labels { position: absolute; top: 0; left: 0; pointer-events: none; }
.dv-label { font-size: 11px; font-weight: 600; color: #fff; background: rgba(20, 28, 40, 0.72);
  padding: 0 4px; border-radius: 3px; }
.dv-top { position: absolute; top: 6px; left: 8px; max-width: calc(100% - 310px); pointer-events: none;
  text-shadow: 0 0 3px #fff, 0 0 3px #fff; background: rgba(251, 252, 253, 0.72); border-radius: 5px;
  padding: 3px 7px; }
.dv-title { font-weight: 600; font-size: 14px; white-space: nowrap; overflow: hidden; text-overflow: ellipsis; }
.dv-subtitle { color: #4a5566; }
.dv-note { margin-top: 2px; color: #8a1c1c; min-height: 1.35em; }
.dv-motions { margin-top: 2px; color: #2c4a7a; }
.dv-distances { margin-top: 3px; display: flex; align-items: center; gap: 3px; flex-wrap: wrap; }
.dv-distances > span:first-child { margin-right: 2px; }
.dv-distance { min-width: 14px; padding: 0 3px; text-align: center; font-size: 11px; font-weight: 600;
  line-height: 15px; border: 1px solid #202020; border-radius: 2px; text-shadow: none; }
.dv-path { white-space: nowrap; margin-left: 8px; display: inline-flex; align-items: center; gap: 4px; }
.dv-path-swatch { display: inline-block; width: 16px; height: 4px; border-radius: 2px; }
.dv-target { margin-top: 2px; display: flex; align-items: center; gap: 4px; }
.dv-target-swatch { opacity: 0.8; border-radius: 50%; border-color: #667; width: 11px; height: 11px; }
.dv-target-swatch + span { margin-right: 4px; }
.dv-help { position: absolute; right: 10px; bottom: calc(var(--dv-bar) + 6px); color: #5a6474; font-size: 11px;
  pointer-events: none; text-shadow: 0 0 3px #fff; }
.dv-bar { position: absolute; left: 0; right: 0; bottom: 0; height: var(--dv-bar); display: flex;
  align-items: center; gap: 10px; padding: 0 10px; box-sizing: border-box;
  background: #fbfcfd; border-top: 1px solid #c9d0da; }
.dv-bar button, .dv-bar select { font: inherit; height: 28px; border: 1px solid #b9c1cc;
  background: #fff; border-radius: 4px; padding: 0 8px; cursor: pointer; }
.dv-bar button:disabled { opacity: 0.4; cursor: default; }
.dv-transport { display: flex; gap: 3px; }
.dv-transport button { width: 34px; padding: 0; display: flex; align-items: center; justify-content: center; }
.dv-transport svg { width: 14px; height: 14px; fill: #2a3340; }
.dv-slider-box { flex: 1; min-width: 120px; display: grid; grid-template-columns: 1fr auto;
  column-gap: 6px; row-gap: 3px; align-items: center; }
.dv-slider-cell { position: relative; }
.dv-has-strip .dv-bar { display: grid; grid-template-columns: auto auto auto 1fr auto;
  grid-template-rows: 30px auto; grid-template-areas: "transport time speed . toggles" "slider slider slider slider slider";
  align-content: center; align-items: center; row-gap: 10px; column-gap: 10px; padding: 0 10px 4px; }
.dv-has-strip .dv-transport { grid-area: transport; }
.dv-has-strip .dv-time { grid-area: time; min-width: 0; }
.dv-has-strip .dv-speed { grid-area: speed; }
.dv-has-strip .dv-toggles { grid-area: toggles; }
.dv-has-strip .dv-slider-box { grid-area: slider; }
.dv-strip { padding: 0 7px; cursor: pointer; }
.dv-strip-inner { position: relative; height: 22px; }
.dv-strip-canvas { display: block; position: absolute; left: 0; top: 0; border-radius: 2px; }
.dv-strip-cursor { position: absolute; top: -2px; bottom: -2px; width: 2px; margin-left: -1px;
  background: #1d2430; pointer-events: none; }
.dv-strip-label { font-size: 11px; color: #2c4a7a; font-weight: 600; white-space: nowrap;
  font-variant-numeric: tabular-nums; }
.dv-slider { width: 100%; margin: 0; }
.dv-markers { position: absolute; left: 7px; right: 7px; top: -7px; height: 6px; pointer-events: none; }
.dv-marker { position: absolute; width: 2px; height: 6px; background: #b33; margin-left: -1px; }
.dv-time { font-variant-numeric: tabular-nums; min-width: 120px; text-align: right; white-space: nowrap; }
.dv-toggles { display: flex; align-items: center; gap: 8px; }
.dv-toggle { display: flex; align-items: center; gap: 3px; cursor: pointer; user-select: none; }
.dv-panel { position: absolute; top: 8px; right: 10px; width: 270px; background: rgba(255, 255, 255, 0.94);
  border: 1px solid #c9d0da; border-radius: 6px; padding: 8px 10px; box-shadow: 0 2px 8px rgba(0,0,0,0.12); }
.dv-panel-title { font-weight: 600; font-size: 14px; margin-bottom: 4px; display: flex; align-items: center; gap: 6px; }
.dv-swatch { display: inline-block; width: 14px; height: 14px; border: 1px solid #333; border-radius: 2px; }
.dv-panel table { border-collapse: collapse; width: 100%; margin-bottom: 6px; }
.dv-panel th { text-align: left; font-weight: normal; color: #5a6474; padding: 1px 8px 1px 0; vertical-align: top; white-space: nowrap; }
.dv-panel td { padding: 1px 0; word-break: break-word; }
.dv-panel button { font: inherit; border: 1px solid #b9c1cc; background: #fff; border-radius: 4px; cursor: pointer; }
.dv-error { position: absolute; top: 20px; left: 20px; right: 20px; padding: 12px 16px; background: #fff0f0;
  border: 1px solid #d33; color: #800; border-radius: 6px; white-space: pre-wrap; font-family: monospace; }
.dv-colour-legend { margin-top: 3px; display: flex; align-items: center; gap: 4px 8px; flex-wrap: wrap; font-size: 12px; }
.dv-legend-item { display: inline-flex; align-items: center; gap: 3px; }
.dv-overloaded { font-weight: 700; color: #fff; background: #c80000; padding: 0 5px; border-radius: 3px; }
.dv-ok { color: #2a6a3a; }
.dv-energy-bar { display: inline-block; width: 140px; height: 12px; border: 1px solid #333; border-radius: 2px; }
.dv-energy-total { margin-left: 6px; }
.dv-open { position: absolute; top: 40%; left: 0; right: 0; text-align: center; font-size: 15px; }
`;
