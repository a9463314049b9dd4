"use strict";
// The run's metrics over time, beside the arena: one small panel per figure
// (the kind's metrics and the safety figures every run has), its line up to
// the step shown, a cursor at that step, and the line the figure is judged
// against (the goal's tolerance, the collision distance) dashed in red.
// Live, the page keeps each figure's values as the frames bring them, at most
// CAPACITY points a figure (every other one dropped when full); a replay has
// them all from /run.json (already bounded by dream).
const DreamMetrics = (() => {
  const CAPACITY = 1024;
  const PANEL_H = 58;     // CSS pixels per figure
  const PAD = { left: 6, right: 6, top: 16, bottom: 6 };
  const LINE = "#1f77b4", LATER = "#c5cbd3", THRESHOLD = "#d62728", CURSOR = "#20252c";

  function create() {
    return { series: new Map(), stride: 1, offered: 0, first: null, last: null, latest: null };
  }

  function newSeries(name) {
    return { name, steps: new Float64Array(CAPACITY), values: new Float64Array(CAPACITY), n: 0,
             threshold: null, label: "", latest: null };
  }

  function halve(m) {
    for (const s of m.series.values()) {
      let kept = 0;
      for (let i = 0; i < s.n; i += 2, kept++) { s.steps[kept] = s.steps[i]; s.values[kept] = s.values[i]; }
      s.n = kept;
    }
    m.stride *= 2;
  }

  // Live: a frame's readings, each at its own step (a figure computed later, a Python controller's
  // metrics(), says an earlier one) or the frame's; a step not after the series' newest is skipped.
  function addLive(m, step, readings) {
    if (!readings || readings.length === 0 || step < 0) return;
    const due = m.offered++ % m.stride === 0;
    let full = false;
    for (const r of readings) {  // a figure first seen now has its panel now
      const at = r.step === undefined ? step : r.step;
      if (!m.series.has(r.name)) m.series.set(r.name, newSeries(r.name));
      const s = m.series.get(r.name);
      s.threshold = r.threshold === undefined ? null : r.threshold;
      s.label = r.label || "";
      if (at < 0 || (s.latest && at <= s.latest[0])) continue;
      s.latest = [at, r.value];
      if (m.first === null || at < m.first) m.first = at;
      if (m.latest === null || at > m.latest.step) m.latest = { step: at };
      if (!due && s.n > 0 || r.value === null) continue;
      s.steps[s.n] = at;
      s.values[s.n] = r.value;
      s.n += 1;
      m.last = Math.max(m.last === null ? at : m.last, at);
      full = full || s.n >= CAPACITY;
    }
    if (full) halve(m);
  }

  // A replay: run.json's "metrics" ({stride, series: [{name, steps, values, threshold, label}]}).
  function fromReplay(metrics, firstStep, lastStep) {
    const m = create();
    m.first = firstStep;
    m.last = lastStep;
    if (!metrics) return m;
    m.stride = metrics.stride || 1;
    for (const s of metrics.series || []) {
      m.series.set(s.name, { name: s.name, steps: Float64Array.from(s.steps),
        values: Float64Array.from(s.values, (v) => (v === null ? NaN : v)), n: s.steps.length,
        threshold: s.threshold === undefined ? null : s.threshold, label: s.label || "" });
    }
    return m;
  }

  // Index of the last point at or before `step`, -1 when none.
  function indexAt(s, step) {
    let lo = 0, hi = s.n - 1, found = -1;
    while (lo <= hi) {
      const mid = (lo + hi) >> 1;
      if (s.steps[mid] <= step) { found = mid; lo = mid + 1; } else { hi = mid - 1; }
    }
    return found;
  }

  // Live, a figure's newest reading (the stride may have left it out of the series): [step, value] or null.
  function latestOf(m, s, step) {
    if (!s.latest || s.latest[0] > step) return null;
    return s.latest[1] === null ? null : s.latest;
  }

  // What the plots show at `step`, machine-readable (window.dreamView.state.metrics).
  function summary(m, step) {
    return [...m.series.values()].map((s) => {
      const i = indexAt(s, step);
      const newest = latestOf(m, s, step);
      const [at, value] = newest || (i >= 0 ? [s.steps[i], s.values[i]] : [null, null]);
      return { name: s.name, step: at, value, threshold: s.threshold, label: s.label, points: s.n };
    });
  }

  function rangeOf(s, step, live, newest) {
    let lo = Infinity, hi = -Infinity;
    if (newest && Number.isFinite(newest[1])) lo = hi = newest[1];
    const end = live ? indexAt(s, step) : s.n - 1;
    for (let i = 0; i <= end; i++) {
      const v = s.values[i];
      if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
    }
    if (s.threshold !== null) { lo = Math.min(lo, s.threshold); hi = Math.max(hi, s.threshold); }
    if (!Number.isFinite(lo)) return [0, 1];
    const pad = hi > lo ? (hi - lo) * 0.08 : Math.max(Math.abs(hi) * 0.1, 1e-9);
    return [lo - pad, hi + pad];
  }

  function text(value) {
    if (value === null || !Number.isFinite(value)) return "-";
    const a = Math.abs(value);
    return a !== 0 && (a < 1e-3 || a >= 1e5) ? value.toExponential(3) : String(Number(value.toPrecision(4)));
  }

  // One figure's panel at `top` (device pixels); returns where its threshold is drawn.
  function drawPanel(g, s, top, width, ratio, m, step, live) {
    const x0 = PAD.left * ratio, x1 = width - PAD.right * ratio;
    const y0 = top + PAD.top * ratio, y1 = top + (PANEL_H - PAD.bottom) * ratio;
    const first = m.first === null ? 0 : m.first;
    const lastStep = Math.max(first + 1, live ? step : m.last);
    const newest = live ? latestOf(m, s, step) : null;
    const [lo, hi] = rangeOf(s, step, live, newest);
    const X = (k) => x0 + ((k - first) / (lastStep - first)) * (x1 - x0);
    const Y = (v) => y1 - ((v - lo) / (hi - lo)) * (y1 - y0);
    g.strokeStyle = "#dde1e6";
    g.lineWidth = ratio;
    g.strokeRect(x0, y0, x1 - x0, y1 - y0);
    let thresholdY = null;
    if (s.threshold !== null) {
      thresholdY = Math.round(Y(s.threshold));
      g.save();
      g.strokeStyle = THRESHOLD;
      g.lineWidth = 1.5 * ratio;
      g.setLineDash([5 * ratio, 3 * ratio]);
      g.beginPath(); g.moveTo(x0, thresholdY); g.lineTo(x1, thresholdY); g.stroke();
      g.restore();
    }
    const at = indexAt(s, step);
    const stroke = (from, to, colour) => {
      if (to < from) return;
      g.strokeStyle = colour;
      g.lineWidth = 1.5 * ratio;
      g.beginPath();
      let pen = false, lastPx = -Infinity;
      for (let i = from; i <= to; i++) {
        const v = s.values[i];
        if (!Number.isFinite(v)) { pen = false; continue; }
        const px = X(s.steps[i]);
        if (pen && px - lastPx < 1 && i !== to) continue;  // points closer than a pixel: one is enough
        if (pen) g.lineTo(px, Y(v)); else g.moveTo(px, Y(v));
        pen = true;
        lastPx = px;
      }
      g.stroke();
    };
    if (!live) stroke(Math.max(at, 0), s.n - 1, LATER);  // the rest of the run, faint
    stroke(0, at, LINE);
    if (newest && at >= 0 && newest[0] > s.steps[at] && Number.isFinite(s.values[at])) {
      g.beginPath(); g.moveTo(X(s.steps[at]), Y(s.values[at])); g.lineTo(X(newest[0]), Y(newest[1])); g.stroke();
    }
    const cx = X(Math.min(Math.max(step, first), lastStep));
    g.strokeStyle = CURSOR;
    g.lineWidth = ratio;
    g.beginPath(); g.moveTo(cx, y0); g.lineTo(cx, y1); g.stroke();
    g.fillStyle = "#222";
    g.font = `${11 * ratio}px system-ui, sans-serif`;
    g.textBaseline = "top";
    const value = newest ? newest[1] : at >= 0 ? s.values[at] : null;
    g.fillText(`${s.name} ${text(value)}`, x0, top + 2 * ratio);
    if (s.threshold !== null) {  // its label inside the plot, at its right end, on the side with room
      const label = s.label || text(s.threshold);
      g.font = `${10 * ratio}px system-ui, sans-serif`;
      const w = g.measureText(label).width + 4 * ratio, h = 12 * ratio;
      const above = thresholdY - h - ratio >= y0;
      const ly = above ? thresholdY - h - ratio : Math.min(thresholdY + 2 * ratio, y1 - h);
      g.fillStyle = "rgba(255, 255, 255, 0.85)";
      g.fillRect(x1 - w - ratio, ly, w, h);
      g.fillStyle = THRESHOLD;
      g.textAlign = "right";
      g.fillText(label, x1 - 3 * ratio, ly + ratio);
      g.textAlign = "left";
    }
    return thresholdY;
  }

  // All panels at `step` (live: the newest; replay: the timeline's); returns
  // what was drawn: {step, panels: [{name, top, thresholdY}]} in device pixels.
  function draw(canvas, m, step, live) {
    const ratio = window.devicePixelRatio || 1;
    const count = m.series.size;
    const width = Math.max(100, Math.round(canvas.clientWidth * ratio));
    const height = Math.round(count * PANEL_H * ratio);
    if (canvas.width !== width) canvas.width = width;
    if (canvas.height !== height) {
      canvas.height = height;
      canvas.style.height = `${count * PANEL_H}px`;
    }
    const g = canvas.getContext("2d");
    g.fillStyle = "#fff";
    g.fillRect(0, 0, canvas.width, canvas.height);
    const panels = [];
    let k = 0;
    for (const s of m.series.values()) {
      const top = Math.round(k * PANEL_H * ratio);
      panels.push({ name: s.name, top, thresholdY: drawPanel(g, s, top, width, ratio, m, step, live) });
      k += 1;
    }
    return { step, panels };
  }

  return { create, addLive, fromReplay, summary, draw, CAPACITY };
})();
