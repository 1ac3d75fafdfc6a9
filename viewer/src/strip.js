// The concurrency strip under the timeline: the number of motions in flight over time as a
// filled step plot (from the trace's "motion" lines), its maximum labelled at the right, the
// refused motion requests as ticks along its top, and a marker at the current time. A click seeks.
import { formatSeconds } from './format.js';

export const STRIP_HEIGHT = 22; // CSS pixels
const TICK_BAND = 4; // the refusal ticks' band at the top
const FILL = '#4f79b5';
const TICK = '#e07b1a';
const BACKGROUND = '#e6eaf0';

// x in [0, width] of time t on a strip of `width` pixels for a trace of `duration`.
export function stripX(t, duration, width) {
  return duration > 0 ? (Math.min(Math.max(t, 0), duration) / duration) * width : 0;
}

export class ConcurrencyStrip {
  // index: a MotionIndex (steps, max); refusals: [{t, text}]; onSeek(t) when clicked.
  constructor(index, refusals, duration, onSeek) {
    this.index = index;
    this.refusals = refusals;
    this.duration = duration;
    this.time = 0;
    const doc = document;
    this.canvas = doc.createElement('canvas');
    this.canvas.className = 'dv-strip-canvas';
    this.cursor = doc.createElement('div');
    this.cursor.className = 'dv-strip-cursor';
    this.inner = doc.createElement('div');
    this.inner.className = 'dv-strip-inner';
    this.inner.append(this.canvas, this.cursor);
    this.element = doc.createElement('div');
    this.element.className = 'dv-strip';
    this.element.appendChild(this.inner);
    this.label = doc.createElement('span');
    this.label.className = 'dv-strip-label';
    this.label.textContent = `max ${index.max}`;
    this.label.title = `At most ${index.max} motion${index.max === 1 ? '' : 's'} in flight at once`;
    this.element.title = 'Motions in flight over time (orange ticks: refused requests); click to seek';

    this.inner.addEventListener('mousemove', (event) => {
      const t = this.timeAtClientX(event.clientX);
      const count = index.countAt(t);
      const near = this.refusalNear(event.clientX);
      this.element.title =
        `${formatSeconds(t)}: ${count} motion${count === 1 ? '' : 's'} in flight` +
        (near ? `\n${formatSeconds(near.t)}: ${near.text}` : '');
    });
    this.inner.addEventListener('click', (event) => onSeek(this.timeAtClientX(event.clientX)));
    if (typeof ResizeObserver !== 'undefined') {
      new ResizeObserver(() => this.draw()).observe(this.inner);
    }
  }

  timeAtClientX(clientX) {
    const rect = this.inner.getBoundingClientRect();
    const u = rect.width > 0 ? (clientX - rect.left) / rect.width : 0;
    return Math.min(1, Math.max(0, u)) * this.duration;
  }

  // The refusal drawn within 3 pixels of a point, if any.
  refusalNear(clientX) {
    const rect = this.inner.getBoundingClientRect();
    let best = null;
    let bestDistance = 3;
    for (const r of this.refusals) {
      const x = rect.left + stripX(r.t, this.duration, rect.width);
      const distance = Math.abs(x - clientX);
      if (distance <= bestDistance) {
        best = r;
        bestDistance = distance;
      }
    }
    return best;
  }

  draw() {
    const width = this.inner.clientWidth;
    const height = STRIP_HEIGHT;
    if (width <= 0) return;
    const ratio = window.devicePixelRatio || 1;
    this.canvas.width = Math.round(width * ratio);
    this.canvas.height = Math.round(height * ratio);
    this.canvas.style.width = `${width}px`;
    this.canvas.style.height = `${height}px`;
    const g = this.canvas.getContext('2d');
    g.setTransform(ratio, 0, 0, ratio, 0, 0);
    g.fillStyle = BACKGROUND;
    g.fillRect(0, 0, width, height);
    const { steps, max } = this.index;
    const plot = height - TICK_BAND - 1;
    if (max > 0) {
      g.fillStyle = FILL;
      steps.forEach((step, k) => {
        if (step.count <= 0) return;
        const x0 = stripX(step.t, this.duration, width);
        const x1 = stripX(k + 1 < steps.length ? steps[k + 1].t : this.duration, this.duration, width);
        const h = (plot * step.count) / max;
        // At least a pixel wide, so that a short motion shows.
        g.fillRect(x0, height - h, Math.max(x1 - x0, 1), h);
      });
    }
    g.fillStyle = TICK;
    for (const r of this.refusals) {
      g.fillRect(Math.min(width - 1, stripX(r.t, this.duration, width)) - 0.5, 0, 1, TICK_BAND - 1);
    }
    this.setTime(this.time);
  }

  setTime(t) {
    this.time = t;
    const width = this.inner.clientWidth;
    this.cursor.style.left = `${stripX(t, this.duration, width)}px`;
  }
}
