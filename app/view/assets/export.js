"use strict";
// "Export video": the replay as the page shows it (the viewport after zoom
// and pan, the layers a video can draw, the steps chosen) drawn by the view's
// server with dream render's code (/export/start), its progress polled
// (/export/status), the video downloaded (/export/video). The page prints
// the `dream render` command that gives the same video.
// window.dreamView.export is its state, machine-readable: the tests read it.
(() => {
  const $ = (id) => document.getElementById(id);
  const POLL_MS = 400;
  const MARGIN = { left: 52, right: 14, top: 14, bottom: 40 };  // arena.js's plot area in the canvas
  const MIN_SPAN_M = 0.1, MAX_OUTSIDE_M = 2;                     // render::Viewport's bounds
  const view = window.dreamView;
  view.export = { state: "idle" };

  const round = (v) => Math.round(v * 1000) / 1000;

  // The world the canvas's plot area shows, as the server's viewport bounds allow; null when the
  // page shows the whole arena (fitted, no zoom or pan): the video's default.
  function viewport() {
    const c = view.camera, canvas = $("arena"), T = view.T, setup = view.setup;
    if (!T || !setup || (c.zoom === 1 && c.panX === 0 && c.panY === 0)) return null;
    const [ax0, ax1, ay0, ay1] = setup.arena;
    let x0 = T.wx(MARGIN.left), x1 = T.wx(canvas.width - MARGIN.right);
    let y0 = T.wy(canvas.height - MARGIN.bottom), y1 = T.wy(MARGIN.top);
    x0 = Math.max(x0, ax0 - MAX_OUTSIDE_M); x1 = Math.min(x1, ax1 + MAX_OUTSIDE_M);
    y0 = Math.max(y0, ay0 - MAX_OUTSIDE_M); y1 = Math.min(y1, ay1 + MAX_OUTSIDE_M);
    const widen = (lo, hi) => {
      const mid = (lo + hi) / 2, half = Math.max(hi - lo, MIN_SPAN_M + 0.002) / 2;
      return [mid - half, mid + half];
    };
    [x0, x1] = widen(x0, x1); [y0, y1] = widen(y0, y1);
    return [x0, y0, x1, y1].map(round);
  }

  // The query of /export/start: only names and numbers (the server's filter allows no more).
  function query() {
    const r = view.replay, steps = r.run.steps, setup = view.setup;
    const from = Math.max(steps[0], Math.min(Number($("export-from").value), steps[steps.length - 1]));
    const to = Math.max(from, Math.min(Number($("export-to").value), steps[steps.length - 1]));
    const p = {
      format: $("export-format").value, width: $("export-width").value, speed: $("export-speed").value,
      trail: $("show-trails").checked ? 10 : 0,
      goals: +$("show-goals").checked, ids: +$("show-ids").checked, violations: +$("show-violations").checked,
      drawings: +$("show-drawings").checked,
      radio: +($("show-radio").checked && !!setup.hears_known),
      sensors: +($("show-sensors").checked && (setup.sensors || []).length > 0),
    };
    if (p.format === "gif") p.fps = 15;
    if (from !== steps[0] || to !== steps[steps.length - 1]) Object.assign(p, { from, to });
    const v = viewport();
    if (v) Object.assign(p, { x0: v[0], y0: v[1], x1: v[2], y1: v[3] });
    return Object.entries(p).map(([k, value]) => `${k}=${value}`).join("&");
  }

  function show(status) {
    view.export = status;
    const running = status.state === "running";
    $("export-start").disabled = running;
    $("export-progress").hidden = !running;
    if (running) { $("export-progress").max = status.total || 1; $("export-progress").value = status.drawn || 0; }
    $("export-status").textContent =
      running ? `drawing frame ${status.drawn} of ${status.total}`
      : status.state === "done" ? `${status.file} (${(status.bytes / 1e6).toFixed(2)} MB)`
      : status.error ? status.error : "";
    $("export-command").textContent = status.command || "";
    $("export-command").hidden = !status.command;
    const link = $("export-download");
    link.hidden = status.state !== "done";
    if (status.state === "done") { link.href = `/export/video?job=${status.job}`; link.download = status.file; }
  }

  async function poll(job) {
    const response = await fetch("/export/status", { cache: "no-store" });
    const status = await response.json();
    show(status);
    if (status.state === "running" && status.job === job) setTimeout(() => poll(job).catch(failed), POLL_MS);
    else if (status.state === "done" && status.job === job) $("export-download").click();
  }

  function failed(error) { show({ state: "failed", error: String(error) }); }

  async function start() {
    if (!view.replay) {
      show({ state: "failed", error: "live: a video is exported from the replay, once the run is over " +
                                      "(dream run --view turns into it; or dream view RUN)" });
      return;
    }
    const response = await fetch(`/export/start?${query()}`, { headers: { "X-Dream-Export": "1" }, cache: "no-store" });
    const text = await response.text();
    let status;
    try { status = JSON.parse(text); } catch (e) { status = { error: text.trim() }; }
    if (response.status !== 202) { show({ state: "failed", error: status.error || text.trim(), refused: response.status }); return; }
    show(status);
    await poll(status.job);
  }

  // The step range: the whole run, or from / to the step shown.
  function stepShown() { return view.scene ? view.scene.step : 0; }
  function resetRange() {
    const steps = view.replay.run.steps;
    $("export-from").value = steps[0];
    $("export-to").value = steps[steps.length - 1];
  }
  $("export-start").onclick = () => start().catch(failed);
  $("export-from-here").onclick = () => { $("export-from").value = stepShown(); };
  $("export-to-here").onclick = () => { $("export-to").value = stepShown(); };
  $("export-whole").onclick = () => { if (view.replay) resetRange(); };
  $("export-format").onchange = () => { $("export-width").value = $("export-format").value === "gif" ? "480" : "720"; };
  // The replay arrives after this script runs: the range is filled once it is there.
  const waitForReplay = setInterval(() => {
    if (!view.replay) return;
    clearInterval(waitForReplay);
    resetRange();
  }, 250);
})();
