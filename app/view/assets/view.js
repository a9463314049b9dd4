"use strict";
// dream view's page. Live: frames pushed by the server on its WebSocket (the
// newest state of the run on the bus). Replay: the whole run from /run.json,
// played on this page's own timeline (play, pause, step, scrub, speed).
// window.dreamView.state is what is drawn, machine-readable: the tests read it.
(() => {
  const $ = (id) => document.getElementById(id);
  const canvas = $("arena");
  const TRAIL_SECONDS = 10;   // of simulated time behind each robot
  const FLASH_MS = 2500;      // a new violation flashes this long (live, wall time)
  const FLASH_SIM_S = 2;      // and this long in simulated time (replay)
  const LINK_MS = 1000;       // a radio link stays drawn this long after its message
  const STATE_NAMES = ["waiting for agents", "running", "finished", "aborted"];
  const PANEL_MS = 250;       // the side panel's text changes at most this often (each change is layout work)

  const view = {
    setup: null, scene: null, paths: [], run: null, replay: null, frames: 0, drawn: 0,
    marks: new Map(), links: new Map(), steps: [], counts: null,
    camera: { zoom: 1, panX: 0, panY: 0 }, T: null, selected: null, hover: null, goalProgress: [],
    metrics: DreamMetrics.create(), metricPlot: null,
    state: { mode: null, connected: false, step: -1, robots: [], violations: [], verdict: "unknown" },
  };
  window.dreamView = view;

  const layers = () => ({
    trails: $("show-trails").checked, goals: $("show-goals").checked, ids: $("show-ids").checked,
    radio: $("show-radio").checked, sensors: $("show-sensors").checked, measured: $("show-measured").checked,
    violations: $("show-violations").checked, velocities: $("show-velocities").checked,
    commands: $("show-commands").checked, drawings: $("show-drawings").checked,
    measuredScale: Number($("measured-scale").value) || 1,
  });

  // The Robotarium's judgement of the counts so far (docs/run-outputs.md's verdicts).
  function verdictOf(c) {
    if (!c) return "unknown";
    if (c.boundary > 0 || c.collision > 0) return "rejected";
    if (c.obstacle > 0 || (c.lost && c.lost.length > 0) || c.rejected > 0 || c.conflicts > 0) return "not_ready";
    if (c.actuator > 0) return "warning";
    return "clean";
  }

  // The verdict shown: at a judged run's end, summary.json's (the one judge's,
  // goal included: the world's DREAM_VERDICT live, the run folder's summary.json
  // in a replay); before it, the counts' so far.
  function shownVerdict(c) {
    return c && c.judged ? c.judged.verdict : verdictOf(c);
  }

  function resize() {
    const ratio = window.devicePixelRatio || 1;
    const box = $("stage").getBoundingClientRect();
    canvas.width = Math.max(200, Math.round(box.width * ratio));
    canvas.height = Math.max(150, Math.round(box.height * ratio));
  }

  function sceneMarks(now) {
    return [...view.marks.values()].map((m) => ({ ...m, flash: Math.max(0, 1 - (now - m.seen) / FLASH_MS) }));
  }

  // Drawn when something changed, not on every display frame, and at most
  // as often as the server sends frames (setup.fps): a page left open beside
  // a run should not take a core from it.
  function draw() {
    view.dirty = false;
    view.drawn += 1;
    view.lastDraw = performance.now();
    view.T = DreamArena.draw(canvas, view.setup, view.scene, layers(), view.paths, view.camera);
  }

  // One display frame is asked for only when there is something to draw:
  // an idle page asks for none.
  function schedule() {
    if (view.frameAsked) return;
    view.frameAsked = true;
    requestAnimationFrame(loop);
  }

  function animating() {
    const s = view.scene;
    return !!(s && ((s.marks && s.marks.some((m) => m.flash > 0)) || (s.links && s.links.length > 0)));
  }

  // The side panel and <body>'s data- attributes: at most every PANEL_MS.
  // Live, in the frame being drawn (a write of its own would make the browser
  // lay out and present one more frame), the latest values written anyway
  // when no frame comes for another PANEL_MS (the run ended); in a replay, as
  // soon as PANEL_MS allow (the user stepped or scrubbed).
  function showPanel(step, t, counts, stateName) {
    view.panel = [step, t, counts, stateName];
    const wait = (view.panelShown || 0) + PANEL_MS - performance.now();
    if (wait > 0) {
      if (!view.panelTimer) {
        const trailing = wait + (view.replay ? 0 : PANEL_MS);
        view.panelTimer = setTimeout(() => { view.panelTimer = null; showPanel(...view.panel); }, trailing);
      }
      return;
    }
    clearTimeout(view.panelTimer);
    view.panelTimer = null;
    view.panelShown = performance.now();
    writePanel(step, t, counts, stateName);
    if (!view.replay) showOtherWorld(view.state.otherWorld);
    document.body.dataset.step = String(view.state.step);
    document.body.dataset.robots = String(view.state.robots.length);
    document.body.dataset.violations = String(view.state.violations.length);
    document.body.dataset.verdict = view.state.verdict;
  }

  function writePanel(step, t, counts, stateName) {
    const dt = view.setup ? view.setup.time_step : 0.033;
    const rate = view.steps.length > 1 ? stepRate() : null;
    const show = (id, value) => {
      const text = value === undefined || value === null ? "-" : String(value);
      if ($(id).textContent !== text) $(id).textContent = text;  // unchanged text: no layout for the page
    };
    show("step", step < 0 ? null : step);
    show("sim-time", step < 0 ? null : `${t.toFixed(2)} s`);
    show("rate", rate === null ? null : `${rate.toFixed(0)} steps/s (${(rate * dt).toFixed(2)}x real time)`);
    show("state", stateName);
    show("count-boundary", counts && counts.boundary);
    show("count-collision", counts && counts.collision);
    show("count-obstacle", counts && counts.obstacle);
    show("count-actuator", counts && counts.actuator);
    show("count-rejected", counts && counts.rejected);
    show("count-lost", counts && counts.lost ? (counts.lost.length ? counts.lost.join(", ") : "none") : null);
    const verdict = shownVerdict(counts);
    show("verdict", verdict.replace("_", " "));
    if ($("verdict").className !== `verdict ${verdict}`) $("verdict").className = `verdict ${verdict}`;
    const judged = counts && counts.judged;
    show("verdict-label", judged ? "verdict" : "verdict so far");
    if ($("goal-line").hidden === !!judged) $("goal-line").hidden = !judged;
    if (judged) {
      show("goal", judged.goal);
      $("verdict").title = judged.reasons.join("\n");
    }
    showMetrics(judged ? judged.metrics || [] : []);
    writeInspector(view.scene && view.scene.selected);
    drawMetricPlots(step);
  }

  // The metrics over time, at the panel's pace (a canvas of its own: no layout but its height).
  function drawMetricPlots(step) {
    const shown = view.metrics.series.size > 0 && $("show-metrics").checked;
    if ($("metric-section").hidden === shown) $("metric-section").hidden = !shown;
    if (!shown) { view.metricPlot = null; return; }
    view.metricPlot = DreamMetrics.draw($("metric-plot"), view.metrics, step, !view.replay);
    view.state.metricPlot = view.metricPlot;
  }

  // The experiment's metrics as summary.json holds them, at a judged run's end.
  function showMetrics(metrics) {
    const block = $("metrics-block");
    if (block.hidden !== (metrics.length === 0)) block.hidden = metrics.length === 0;
    const key = metrics.map(([name, value]) => `${name}=${value}`).join(";");
    if ($("metrics").dataset.shown === key) return;  // unchanged: no layout for the page
    $("metrics").dataset.shown = key;
    fillTable($("metrics"), metrics);
  }

  // A two-column table's rows, [name, value] each.
  function fillTable(table, rows) {
    table.replaceChildren(...rows.map(([name, value]) => {
      const row = document.createElement("tr");
      for (const text of [name, value]) {
        const cell = document.createElement("td");
        cell.textContent = text;
        row.appendChild(cell);
      }
      return row;
    }));
  }

  // A run id as logs and summary.json print it: 16 hex digits (the frame
  // sends it as a decimal string: 64 bits do not fit a JavaScript number).
  function runIdText(decimal) {
    try {
      return BigInt.asUintN(64, BigInt(decimal)).toString(16).padStart(16, "0");
    } catch (error) {
      return String(decimal);
    }
  }

  // The status line saying that another world is on the bus: the server
  // draws one run (the one it follows) and names the others it hears.
  function otherWorldOf(f) {
    const o = f && f.other_world;
    if (!o) return null;
    const state = o.state === null ? null : STATE_NAMES[o.state] || String(o.state);
    return { run: runIdText(o.run), id: o.run, step: o.step, state, runs: o.runs };
  }

  function showOtherWorld(other) {
    const line = $("other-world"), shown = $("other-world-text");
    let text = "";
    if (other) {
      const at = other.step >= 0 ? ` at step ${other.step}` : "";
      const where = `run ${other.run}${at}${other.state ? `, ${other.state}` : ""}`;
      text = (other.runs > 1 ? `${other.runs} other runs are on this bus (the latest: ${where}); not drawn.`
                             : `Another world is on this bus (${where}); not drawn.`) +
             " This page stays on its run; a run that starts after it ends is drawn.";
    }
    if (shown.textContent !== text) shown.textContent = text;  // unchanged text: no layout for the page
    if (line.hidden !== !other) line.hidden = !other;
    document.body.dataset.otherWorld = other ? other.run : "";
  }

  // A violation held over many steps is one episode (kind, robots, first and last step), as
  // summary.json's violations_located lists it: one line per episode, not per step.
  function episodesOf(marks) {
    const open = new Map();
    const episodes = [];
    for (const m of [...marks].sort((a, b) => a.step - b.step)) {
      const key = `${m.kind}/${m.robot}/${m.other}`;
      const going = open.get(key);
      if (going && m.step <= going.last + 1) {
        going.last = Math.max(going.last, m.step);
        if (worse(m.kind, m.worst, going.worst)) going.worst = m.worst;
        continue;
      }
      const episode = { kind: m.kind, robot: m.robot, other: m.other, first: m.step, last: m.step, x: m.x, y: m.y,
                        worst: m.worst };
      open.set(key, episode);
      episodes.push(episode);
    }
    return episodes;
  }

  // The worst of an episode: the farthest outside or deepest overlap, the closest pair.
  function worse(kind, value, worst) {
    if (typeof value !== "number") return false;
    if (typeof worst !== "number") return true;
    return kind === "collision" ? value < worst : value > worst;
  }

  function describeEpisode(e) {
    const steps = e.first === e.last ? `step ${e.first}` : `steps ${e.first}-${e.last}`;
    const worst = typeof e.worst !== "number" ? ""
      : e.kind === "collision" ? `, closest ${(e.worst * 100).toFixed(1)} cm`
        : e.kind === "obstacle" ? `, ${(e.worst * 100).toFixed(1)} cm in at worst`
          : `, ${(e.worst * 100).toFixed(1)} cm out at worst`;
    return DreamArena.describe({ ...e, step: e.first }).replace(/step \d+$/, steps) + worst;
  }

  // The episodes of `marks`, worked out again only when the marks changed.
  function episodesCached(marks) {
    const last = marks[marks.length - 1];
    const key = `${marks.length}/${last ? last.step : -1}`;
    if (!view.episodeCache || view.episodeCache.key !== key) view.episodeCache = { key, episodes: episodesOf(marks) };
    return view.episodeCache.episodes;
  }

  function showViolationList(marks) {
    const list = $("violation-list");
    const last = marks[marks.length - 1];
    const key = `${marks.length}/${last ? last.step : -1}`;
    if (list.dataset.shown === key) return;  // unchanged: no work for the page's layout
    list.dataset.shown = key;
    const episodes = episodesCached(marks);
    const latest = episodes.slice().sort((a, b) => b.last - a.last || b.first - a.first).slice(0, 50);
    list.replaceChildren(...latest.map((e) => {
      const item = document.createElement("li");
      item.textContent = `${describeEpisode(e)}, first at (${e.x.toFixed(2)}, ${e.y.toFixed(2)})`;
      return item;
    }));
  }

  // What the controllers drew in the scene: shapes by kind, robots that drew, what their agents clipped.
  const DRAWN_KINDS = ["", "line", "circle", "polygon", "arrow", "text"];
  function drawingSummary(s) {
    const summary = { shown: $("show-drawings").checked, robots: [], shapes: 0, clipped: 0, kinds: {}, texts: [] };
    for (const [, robot, clipped, shapes] of (s && s.drawings) || []) {
      summary.robots.push(robot);
      summary.clipped += clipped;
      summary.shapes += shapes.length;
      for (const shape of shapes) {
        const kind = DRAWN_KINDS[shape[0]] || String(shape[0]);
        summary.kinds[kind] = (summary.kinds[kind] || 0) + 1;
        if (shape[0] === 5 && summary.texts.length < 20) summary.texts.push(shape[7]);
      }
    }
    const note = $("drawings-note"), text = summary.clipped > 0 ? ` (${summary.clipped} clipped)` : "";
    if (note && note.textContent !== text) note.textContent = text;  // unchanged text: no layout for the page
    return summary;
  }

  function publishState(extra) {
    const s = view.scene;
    const robots = s ? s.x.map((x, id) => ({ id, x, y: s.y[id], theta: s.th[id], v: s.v ? s.v[id] : null,
                                             w: s.w ? s.w[id] : null, cv: s.cv ? s.cv[id] : null,
                                             cw: s.cw ? s.cw[id] : null })) : [];
    const marks = [...view.marks.values()].map(({ kind, step, robot, other, x, y, worst }) =>
      ({ kind, step, robot, other, x, y, worst }));
    view.state = {
      mode: view.setup ? view.setup.mode : null, connected: view.connected === true, run: view.run,
      step: s ? s.step : -1, t: s ? s.t : 0, frames: view.frames, robots, counts: view.counts,
      verdict: shownVerdict(view.counts), violations: marks, episodes: episodesCached(marks),
      flashing: s && s.marks ? s.marks.filter((m) => m.flash > 0).length : 0,
      links: s && s.links ? s.links.length : 0, measured: !!(s && s.mx), otherWorld: null,
      drawings: drawingSummary(s),
      camera: { ...view.camera }, selected: s && s.selected ? s.selected : null,
      goalProgress: s && s.goalProgress ? s.goalProgress.slice() : [],
      metrics: DreamMetrics.summary(view.metrics, s ? s.step : -1), metricPlot: view.metricPlot, ...extra,
    };
  }

  // ---- looking at one robot: its details, neighbours and goals ----
  const GOAL_REACHED_M = 0.05;  // a goal counts as reached within this (rps's at_position default)

  function wrapAngle(a) { return Math.atan2(Math.sin(a), Math.cos(a)); }

  // The robots robot `id` hears (radio links drawn now, either way) and sees (within a sensor's
  // range and field of view, as the config's sensors say).
  function neighboursOf(id, s) {
    const radio = new Set(), seen = new Set();
    for (const [a, b] of s.links || []) {
      if (a === id) radio.add(b);
      if (b === id) radio.add(a);
    }
    for (let j = 0; j < s.x.length; j++) {
      if (j === id || s.x[j] === null || s.x[id] === null) continue;
      const dx = s.x[j] - s.x[id], dy = s.y[j] - s.y[id], d = Math.hypot(dx, dy);
      for (const [range, dir, fov] of view.setup.sensors || []) {
        if (d <= range && Math.abs(wrapAngle(Math.atan2(dy, dx) - s.th[id] - dir)) <= fov / 2 + 1e-9) seen.add(j);
      }
    }
    return { radio: [...radio].sort((a, b) => a - b), seen: [...seen].sort((a, b) => a - b) };
  }

  function detailsOf(id, s) {
    if (!s || id === null || id < 0 || id >= s.x.length) return null;
    const near = neighboursOf(id, s);
    const d = { id, x: s.x[id], y: s.y[id], theta: s.th[id], v: s.v ? s.v[id] : null, w: s.w ? s.w[id] : null,
                command: s.cv && s.cv[id] !== null ? { v: s.cv[id], w: s.cw[id] } : null,
                radio: near.radio, seen: near.seen, neighbours: [...new Set([...near.radio, ...near.seen])],
                lost: !!(s.lost && s.lost.includes(id)) };
    if (s.mx && s.mx[id] !== null) {
      d.measured = { x: s.mx[id], y: s.my[id], theta: s.mth[id],
                     error_m: Math.hypot(s.mx[id] - s.x[id], s.my[id] - s.y[id]),
                     heading_error_rad: wrapAngle(s.mth[id] - s.th[id]) };
    }
    const goals = (view.setup.goals || [])[id] || [];
    const done = s.goalProgress ? s.goalProgress[id] || 0 : 0;
    d.goals = { count: goals.length, reached: done };
    if (done < goals.length) {
      const [gx, gy] = goals[done];
      d.goals.current = [gx, gy];
      d.goals.distance_m = Math.hypot(gx - s.x[id], gy - s.y[id]);
    }
    d.episodes = episodesCached([...view.marks.values()]).filter((e) => e.robot === id || e.other === id).length;
    return d;
  }

  function writeInspector(d) {
    const block = $("inspect");
    if (block.hidden !== !d) block.hidden = !d;
    if (!d) return;
    const f = (value, digits) => (value === null || value === undefined ? "-" : value.toFixed(digits));
    const deg = (rad) => (rad === null || rad === undefined ? "-" : `${(rad * 180 / Math.PI).toFixed(1)}°`);
    const rows = [
      ["robot", `${d.id}${d.lost ? " (lost)" : ""}${view.selected === d.id ? "" : " (hover; click to keep)"}`],
      ["pose", `(${f(d.x, 3)}, ${f(d.y, 3)}) m, ${deg(d.theta)}`],
      ["measured", d.measured ? `(${f(d.measured.x, 3)}, ${f(d.measured.y, 3)}) m, ${deg(d.measured.theta)}; off by ` +
        `${f(d.measured.error_m * 1000, 1)} mm, ${deg(d.measured.heading_error_rad)}` : "-"],
      ["drove", `v ${f(d.v, 3)} m/s, w ${f(d.w, 2)} rad/s`],
      ["commanded", d.command ? `v ${f(d.command.v, 3)} m/s, w ${f(d.command.w, 2)} rad/s` : "-"],
      ["goal", d.goals.count === 0 ? "-" : d.goals.current
        ? `${d.goals.reached} of ${d.goals.count} reached; now (${f(d.goals.current[0], 2)}, ${f(d.goals.current[1], 2)}),` +
          ` ${f(d.goals.distance_m, 3)} m away` : `all ${d.goals.count} reached`],
      ["hears (radio)", d.radio.length ? d.radio.join(", ") : "-"],
      ["sees (sensors)", d.seen.length ? d.seen.join(", ") : "-"],
      ["violations", String(d.episodes)],
    ];
    const key = JSON.stringify(rows);
    if ($("inspect-table").dataset.shown === key) return;  // unchanged: no layout for the page
    $("inspect-table").dataset.shown = key;
    $("inspect-swatch").style.background = DreamArena.colour(d.id);
    fillTable($("inspect-table"), rows);
  }

  // Marks the current goal and the reached ones, and the robot looked at, on a scene.
  function decorate(s, progress) {
    s.goalProgress = progress;
    const id = view.selected !== null ? view.selected : view.hover;
    s.selected = id !== null ? detailsOf(id, s) : null;
  }

  // Live: each robot's goals are reached in order; a goal counts once the robot came within
  // GOAL_REACHED_M of it.
  function advanceGoals(f) {
    (view.setup && view.setup.goals || []).forEach((list, id) => {
      let k = view.goalProgress[id] || 0;
      while (k < list.length && f.x[id] !== null && Math.hypot(list[k][0] - f.x[id], list[k][1] - f.y[id]) <= GOAL_REACHED_M) k++;
      view.goalProgress[id] = k;
    });
  }

  // Replay: the frame at which each robot reached each of its goals, in order (Infinity: never).
  function goalTimeline(run) {
    return (view.setup.goals || []).map((list, id) => {
      const at = [];
      let k = 0;
      for (let i = 0; i < run.poses.length && k < list.length; i++) {
        const x = run.poses[i][3 * id], y = run.poses[i][3 * id + 1];
        while (k < list.length && x !== null && Math.hypot(list[k][0] - x, list[k][1] - y) <= GOAL_REACHED_M) at[k++] = i;
      }
      while (at.length < list.length) at.push(Infinity);
      return at;
    });
  }

  function stepRate() {
    const first = view.steps[0], last = view.steps[view.steps.length - 1];
    const seconds = (last[0] - first[0]) / 1000;
    return seconds > 0 ? (last[1] - first[1]) / seconds : null;
  }

  // ---- live: one frame at a time from the server ----
  function startRun(run) {
    view.run = run;
    view.paths = [];
    view.marks.clear();
    view.links.clear();
    view.steps = [];
    view.goalProgress = [];
    view.metrics = DreamMetrics.create();
  }

  function onFrame(f) {
    const now = performance.now();
    const last = view.live ? view.live.step : -1;
    if (f.run !== view.run || f.step + 1 < last) startRun(f.run);  // another run, or this one played again
    view.frames += 1;
    if (f.step >= 0) {
      view.steps.push([now, f.step]);
      while (view.steps.length > 2 && now - view.steps[0][0] > 2000) view.steps.shift();
      f.x.forEach((x, id) => {
        const path = view.paths[id] || (view.paths[id] = []);
        const last = path[path.length - 1];
        if (x !== null && f.y[id] !== null && (!last || last[2] !== f.step)) path.push([x, f.y[id], f.step, f.t]);
        while (path.length > 2 && path[0][3] < f.t - TRAIL_SECONDS) path.shift();
      });
    }
    for (const m of f.violations) {
      const key = `${m.kind}/${m.step}/${m.robot}/${m.other}`;
      if (!view.marks.has(key)) view.marks.set(key, { ...m, seen: now });
    }
    for (const [s, r] of f.links) view.links.set(`${s}/${r}`, { s, r, seen: now });
    view.live = f;
    DreamMetrics.addLive(view.metrics, f.step, f.metrics);
    if (f.step >= 0) advanceGoals(f);
    // Once the world judged the run (DREAM_VERDICT, after its summary.json), its verdict and goal.
    view.counts = f.status ? { ...f.status, judged: f.judged || null } : null;
  }

  function liveScene(now) {
    const f = view.live;
    if (!f) return;
    const links = [];
    for (const [key, link] of view.links) {
      const age = now - link.seen;
      if (age > LINK_MS) view.links.delete(key);
      else links.push([link.s, link.r, 1 - age / LINK_MS]);
    }
    view.scene = {
      step: f.step, t: f.t, x: f.x, y: f.y, th: f.th, v: f.v, w: f.w, cv: f.cv, cw: f.cw, mx: f.mx, my: f.my, mth: f.mth,
      obstacles: f.obstacles, links, marks: sceneMarks(now), lost: f.status ? f.status.lost : [],
      drawings: f.drawings || [],
    };
    decorate(view.scene, view.goalProgress.slice());
    const stateName = f.status ? STATE_NAMES[f.status.state] || String(f.status.state) : "-";
    publishState({ state: stateName, detail: f.status ? f.status.detail : "", otherWorld: otherWorldOf(f) });
    showPanel(f.step, f.t, view.counts, stateName);
  }

  // ---- replay: the whole run, on this page's timeline ----
  function lastAtOrBefore(list, value, keyOf) {
    let lo = 0, hi = list.length - 1, found = -1;
    while (lo <= hi) {
      const mid = (lo + hi) >> 1;
      if (keyOf(list[mid]) <= value) { found = mid; lo = mid + 1; } else { hi = mid - 1; }
    }
    return found;
  }

  function splitPoses(poses) {
    const x = [], y = [], th = [];
    for (let k = 0; k + 2 < poses.length; k += 3) { x.push(poses[k]); y.push(poses[k + 1]); th.push(poses[k + 2]); }
    return { x, y, th };
  }

  // Each robot's latest drawing at or before `step` ([step, robot, clipped, shapes], by step), with shapes.
  function drawingsAt(list, step) {
    const latest = new Map();
    for (let k = 0, last = lastAtOrBefore(list || [], step, (d) => d[0]); k <= last; k++) latest.set(list[k][1], list[k]);
    return [...latest.values()].filter((d) => d[3].length > 0 || d[2] > 0);
  }

  function replayScene(i) {
    const run = view.replay.run;
    const step = run.steps[i], t = run.t[i];
    const at = splitPoses(run.poses[i]);
    const measured = run.measured && run.measured[i] ? splitPoses(run.measured[i]) : null;
    const o = lastAtOrBefore(run.obstacles, i, (entry) => entry[0]);
    const linkSteps = LINK_MS / 1000 / view.setup.time_step;
    const links = [];
    for (let k = lastAtOrBefore(run.links, step, (l) => l[0]); k >= 0 && run.links[k][0] > step - linkSteps; k--) {
      links.push([run.links[k][1], run.links[k][2], 1 - (step - run.links[k][0]) / linkSteps]);
    }
    view.marks.clear();
    const flashSteps = FLASH_SIM_S / view.setup.time_step;
    const marks = [];
    for (const m of run.violations) {
      if (m.step > step) break;
      view.marks.set(`${m.kind}/${m.step}/${m.robot}/${m.other}`, m);
      marks.push({ ...m, flash: Math.max(0, 1 - (step - m.step) / flashSteps) });
    }
    showViolationList(marks);
    const c = run.counts[lastAtOrBefore(run.counts, step, (entry) => entry[0])];
    const atEnd = i === run.steps.length - 1;
    const fin = run.final || {};
    view.counts = {
      boundary: c ? c[1] : 0, collision: c ? c[2] : 0, obstacle: c ? c[3] : 0,
      // Only the run's last status says these (the log keeps no per-step status here).
      actuator: atEnd ? fin.actuator : null, rejected: atEnd ? fin.rejected : null, conflicts: atEnd ? fin.conflicts : 0,
      lost: atEnd ? fin.lost : null,
      judged: atEnd && view.setup.judged ? view.setup.judged : null,
    };
    const trailFrames = Math.ceil(TRAIL_SECONDS / view.setup.time_step / run.stride);
    view.paths = at.x.map((_, id) => {
      const path = [];
      for (let k = Math.max(0, i - trailFrames); k <= i; k++) path.push([run.poses[k][3 * id], run.poses[k][3 * id + 1]]);
      return path;
    });
    const vel = run.velocities && run.velocities[i] ? run.velocities[i] : null;
    const cmd = run.commands && run.commands[i] ? run.commands[i] : null;
    view.scene = { step, t, ...at, mx: measured && measured.x, my: measured && measured.y, mth: measured && measured.th,
      v: vel && vel.filter((_, k) => k % 2 === 0), w: vel && vel.filter((_, k) => k % 2 === 1),
      cv: cmd && cmd.filter((_, k) => k % 2 === 0), cw: cmd && cmd.filter((_, k) => k % 2 === 1),
      obstacles: o >= 0 ? run.obstacles[o][1] : [], links, marks, lost: view.counts.lost || [],
      drawings: drawingsAt(run.drawings, step) };
    decorate(view.scene, view.replay.goalsAt.map((at) => at.filter((frame) => frame <= i).length));
    const stateName = atEnd && run.final ? STATE_NAMES[run.final.state] || "-" : "replaying";
    view.dirty = true;
    schedule();
    publishState({ state: stateName,
      replay: { index: i, frames: run.steps.length, playing: view.replay.playing, speed: view.replay.speed } });
    showPanel(step, t, view.counts, stateName);
  }

  function seek(i) {
    const r = view.replay;
    r.index = Math.min(Math.max(0, i), r.run.steps.length - 1);
    r.simTime = r.run.t[r.index];
    $("scrub").value = String(r.index);
    replayScene(r.index);
    draw();
  }

  function setPlaying(playing) {
    const r = view.replay;
    if (playing && r.index >= r.run.steps.length - 1) seek(0);  // play again from the start
    r.playing = playing;
    r.lastWall = performance.now();
    $("play").textContent = playing ? "pause" : "play";
    replayScene(r.index);
  }

  function startReplay(run) {
    view.replay = { run, index: 0, playing: false, speed: 1, simTime: 0, lastWall: performance.now() };
    view.replay.goalsAt = goalTimeline(run);
    view.metrics = DreamMetrics.fromReplay(run.metrics, run.steps[0], run.steps[run.steps.length - 1]);
    view.run = run.run;
    if (run.flaw) $("source").textContent += ` (not a whole run: ${run.flaw})`;
    if (run.stride > 1) $("source").textContent += ` (every ${run.stride}th step)`;
    $("timeline").hidden = false;
    $("scrub").max = String(run.steps.length - 1);
    $("play").onclick = () => setPlaying(!view.replay.playing);
    $("step-forward").onclick = () => { setPlaying(false); seek(view.replay.index + 1); };
    $("step-back").onclick = () => { setPlaying(false); seek(view.replay.index - 1); };
    $("scrub").oninput = () => seek(Number($("scrub").value));
    $("speed").onchange = () => { view.replay.speed = Number($("speed").value); replayScene(view.replay.index); };
    resize();
    // A run that was watched live and is over: the replay opens on its last step, where its verdict is.
    seek(view.live ? run.steps.length - 1 : 0);
  }

  function advanceReplay(now) {
    const r = view.replay;
    if (!r || !r.playing) return;
    r.simTime += ((now - r.lastWall) / 1000) * r.speed;
    r.lastWall = now;
    let i = r.index;
    while (i + 1 < r.run.t.length && r.run.t[i + 1] <= r.simTime) i++;
    if (i === r.run.t.length - 1) r.playing = false, $("play").textContent = "play";
    if (i !== r.index || !r.playing) {
      r.index = i;
      $("scrub").value = String(i);
      replayScene(i);
    }
  }

  // ---- connection and the drawing loop ----
  function onSetup(setup) {
    view.setup = setup;
    view.dirty = true;
    schedule();
    $("source").textContent = `${setup.mode}: ${setup.source}`;
    $("run-name").textContent = setup.run_name || "-";
    if (setup.mode === "replay" && !view.replay) {
      fetch("/run.json").then((response) => {
        if (!response.ok) throw new Error(`/run.json: ${response.status}`);
        return response.json();
      }).then(startReplay).catch((error) => { $("connection").textContent = String(error); });
    }
    publishState({});
  }

  // `dream view` receives the robots' commands (most of a udpm run's datagrams) only once a page shows them.
  function askForCommands() {
    if ($("show-commands").checked && view.socket && view.socket.readyState === WebSocket.OPEN) view.socket.send("commands");
  }

  function connect() {
    const socket = new WebSocket(`ws://${location.host}/ws`);
    view.socket = socket;
    socket.onopen = () => {
      view.connected = true; document.body.dataset.connected = "true"; $("connection").textContent = "connected";
      askForCommands();
    };
    socket.onclose = () => {
      view.connected = false;
      document.body.dataset.connected = "false";
      if (view.replay) {
        // The page holds the whole run: nothing to reconnect for.
        $("connection").textContent = `dream stopped serving; the replay stays here (again: dream view ${view.setup.source})`;
        return;
      }
      $("connection").textContent = "disconnected: retrying";
      setTimeout(connect, 1000);
    };
    socket.onmessage = (event) => {
      let message;
      try { message = JSON.parse(event.data); } catch (error) { return; }
      if (message.type === "setup") onSetup(message);
      else if (message.type === "frame" && !view.replay) {
        onFrame(message);
        showViolationList([...view.marks.values()]);
        view.dirty = true;
        if (!view.liveTimer) liveTick();
      }
    };
  }

  // Live, a frame is drawn in the task that brought it or in a timer's, not
  // in a display frame asked for: asking for one costs a software-rendering
  // browser about as much again as drawing (docs/performance.md#dream-view).
  // A frame is drawn no sooner than 1/fps after the one before (the server's
  // rate: more frames than it sends would only redraw the same); flashes
  // fade and links age between frames too, at the same rate. A hidden page
  // draws nothing until it is shown again.
  function liveTick() {
    view.liveTimer = null;
    if (document.hidden || view.replay || !(view.dirty || animating())) return;
    const now = performance.now();
    const period = 1000 / ((view.setup && view.setup.fps) || 30);
    const wait = (view.lastDraw || 0) + period - 2 - now;
    if (wait > 0) {
      view.liveTimer = setTimeout(liveTick, wait);
      return;
    }
    liveScene(now);
    draw();
    if (animating()) view.liveTimer = setTimeout(liveTick, period);
  }

  // Replay (and the page's first picture): drawn in display frames.
  function loop(now) {
    view.frameAsked = false;
    advanceReplay(now);
    if (view.dirty) draw();
    if (view.replay && view.replay.playing) schedule();
  }

  for (const box of document.querySelectorAll("#layers input, #layers select")) box.onchange = draw;
  $("show-metrics").onchange = () => drawMetricPlots(view.state.step);
  $("show-commands").addEventListener("change", askForCommands);

  // ---- mouse and keyboard: pick, zoom, pan, fit, play ----
  function canvasPoint(event) {
    const box = canvas.getBoundingClientRect();
    return [(event.clientX - box.left) * (canvas.width / box.width), (event.clientY - box.top) * (canvas.height / box.height)];
  }

  function robotAt([px, py]) {
    const s = view.scene, T = view.T;
    if (!s || !T) return null;
    const radius = Math.max(3, (T.s * view.setup.robot_diameter) / 2) + 4;
    let best = null, bestDistance = radius;
    for (let i = 0; i < s.x.length; i++) {
      if (s.x[i] === null) continue;
      const d = Math.hypot(T.px(s.x[i]) - px, T.py(s.y[i]) - py);
      if (d <= bestDistance) { best = i; bestDistance = d; }
    }
    return best;
  }

  // Where robot `id` is drawn, in CSS pixels of the page (for tests and tooltips).
  view.pixelOf = (id) => {
    const s = view.scene, T = view.T, box = canvas.getBoundingClientRect();
    if (!s || !T || s.x[id] === null || s.x[id] === undefined) return null;
    return [box.left + T.px(s.x[id]) * box.width / canvas.width, box.top + T.py(s.y[id]) * box.height / canvas.height];
  };

  function refresh() {
    if (view.scene) decorate(view.scene, view.scene.goalProgress);
    publishState({ state: view.state.state, replay: view.state.replay, otherWorld: view.state.otherWorld });
    writeInspector(view.scene && view.scene.selected);
    draw();
  }

  function select(id) {
    view.selected = id;
    refresh();
  }

  function zoomAt([px, py], factor) {
    const c = view.camera, zoom = Math.min(40, Math.max(0.25, c.zoom * factor));
    // Keeps the world point under (px, py) where it is.
    const qx = (px - canvas.width / 2 - c.panX) / c.zoom, qy = (py - canvas.height / 2 - c.panY) / c.zoom;
    view.camera = { zoom, panX: px - canvas.width / 2 - zoom * qx, panY: py - canvas.height / 2 - zoom * qy };
    refresh();
  }

  function fit() {
    view.camera = { zoom: 1, panX: 0, panY: 0 };
    refresh();
  }

  let drag = null;
  canvas.addEventListener("mousedown", (event) => {
    drag = { start: canvasPoint(event), pan: [view.camera.panX, view.camera.panY], moved: false };
  });
  canvas.addEventListener("mousemove", (event) => {
    const p = canvasPoint(event);
    if (drag) {
      const dx = p[0] - drag.start[0], dy = p[1] - drag.start[1];
      if (drag.moved || Math.hypot(dx, dy) > 4) {
        drag.moved = true;
        view.camera = { ...view.camera, panX: drag.pan[0] + dx, panY: drag.pan[1] + dy };
        draw();
      }
      return;
    }
    const id = robotAt(p);
    if (id !== view.hover) {
      view.hover = id;
      if (view.selected === null) refresh();
    }
    canvas.style.cursor = id !== null ? "pointer" : "grab";
  });
  window.addEventListener("mouseup", (event) => {
    if (drag && !drag.moved && event.target === canvas) select(robotAt(canvasPoint(event)));
    drag = null;
  });
  canvas.addEventListener("mouseleave", () => { if (view.hover !== null) { view.hover = null; refresh(); } });
  canvas.addEventListener("wheel", (event) => {
    event.preventDefault();
    zoomAt(canvasPoint(event), Math.pow(1.2, -Math.sign(event.deltaY)));
  }, { passive: false });
  $("fit").onclick = fit;
  document.addEventListener("keydown", (event) => {
    if (event.target && ["INPUT", "SELECT", "BUTTON", "TEXTAREA"].includes(event.target.tagName)) return;
    const centre = [canvas.width / 2, canvas.height / 2];
    const r = view.replay;
    if (event.key === " " && r) setPlaying(!r.playing);
    else if (event.key === "ArrowRight" && r) { setPlaying(false); seek(r.index + 1); }
    else if (event.key === "ArrowLeft" && r) { setPlaying(false); seek(r.index - 1); }
    else if (event.key === "+" || event.key === "=") zoomAt(centre, 1.25);
    else if (event.key === "-") zoomAt(centre, 1 / 1.25);
    else if (event.key === "f" || event.key === "0") fit();
    else if (event.key === "Escape") select(null);
    else if (event.key === "v") { $("show-velocities").checked = !$("show-velocities").checked; draw(); }
    else if (event.key === "c") { $("show-commands").checked = !$("show-commands").checked; askForCommands(); draw(); }
    else return;
    event.preventDefault();
  });
  // The user's choice: the server draws the other run from its next step (for every page).
  $("follow-other").onclick = () => {
    const other = view.state.otherWorld;
    if (other && view.socket && view.socket.readyState === WebSocket.OPEN) view.socket.send(`follow ${other.id}`);
  };
  document.addEventListener("visibilitychange", () => { if (!document.hidden && !view.liveTimer) liveTick(); });
  window.addEventListener("resize", () => { resize(); draw(); });
  resize();
  connect();
})();
