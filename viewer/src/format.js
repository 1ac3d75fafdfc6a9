// Formatting shared by the controls.

export function formatSeconds(t) {
  return `${t.toFixed(2)} s`;
}
