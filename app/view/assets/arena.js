"use strict";
// Draws one scene of a DREAM run on a canvas: the arena to scale in the world
// frame (x right, y up, metres on the axes), obstacles, goals, trails, radio
// links, sensor ranges, what the controllers drew, robots as oriented discs
// with their ids, measured poses, and violations where they happened (flashing while new).
const DreamArena = (() => {
  // 50 colours, one per robot up to the Robotarium's caps: the ten familiar ones first, then hues
  // a golden angle apart in three lightnesses, so neighbours in id never look alike.
  const PALETTE_SIZE = 50;
  const familiar = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
                    "#7f7f7f", "#bcbd22", "#17becf"];
  const palette = familiar.concat(Array.from({ length: PALETTE_SIZE - familiar.length }, (_, k) =>
    `hsl(${((k * 137.508 + 20) % 360).toFixed(1)}, ${[70, 55, 80][k % 3]}%, ${[38, 52, 30][k % 3]}%)`));
  const colour = (id) => palette[id % PALETTE_SIZE];
  const finite = (...values) => values.every((v) => typeof v === "number" && Number.isFinite(v));

  // World metres -> canvas pixels, fitting the arena (and a margin) in the canvas.
  // Robots outside the arena widen the view (up to 1 m beyond it), so one
  // that left is still drawn where it is.
  // camera: {zoom, panX, panY} (canvas pixels) on top of the fitted view; zoom 1, no pan: fitted.
  function transform(canvas, setup, scene, camera) {
    let [xmin, xmax, ymin, ymax] = setup.arena;
    const [ax0, ax1, ay0, ay1] = setup.arena;
    const r = (setup.robot_diameter || 0.11) / 2;
    for (let i = 0; scene && i < scene.x.length; i++) {
      if (!finite(scene.x[i], scene.y[i])) continue;
      xmin = Math.min(xmin, Math.max(ax0 - 1, scene.x[i] - r));
      xmax = Math.max(xmax, Math.min(ax1 + 1, scene.x[i] + r));
      ymin = Math.min(ymin, Math.max(ay0 - 1, scene.y[i] - r));
      ymax = Math.max(ymax, Math.min(ay1 + 1, scene.y[i] + r));
    }
    const pad = 0.12;
    const m = { left: 52, right: 14, top: 14, bottom: 40 };
    const w = canvas.width - m.left - m.right;
    const h = canvas.height - m.top - m.bottom;
    const s = Math.max(1e-6, Math.min(w / (xmax - xmin + 2 * pad), h / (ymax - ymin + 2 * pad)));
    const ox = m.left + (w - s * (xmax - xmin + 2 * pad)) / 2 - s * (xmin - pad);
    const oy = m.top + (h - s * (ymax - ymin + 2 * pad)) / 2 + s * (ymax + pad);
    const zoom = camera ? camera.zoom : 1;
    const cx = canvas.width / 2 + (camera ? camera.panX : 0), cy = canvas.height / 2 + (camera ? camera.panY : 0);
    const zx = cx + zoom * (ox - canvas.width / 2), zy = cy + zoom * (oy - canvas.height / 2);
    const zs = s * zoom;
    return { s: zs, px: (x) => zx + zs * x, py: (y) => zy - zs * y, wx: (px) => (px - zx) / zs, wy: (py) => (zy - py) / zs };
  }

  function axes(ctx, T, setup) {
    const [xmin, xmax, ymin, ymax] = setup.arena;
    const span = Math.max(xmax - xmin, ymax - ymin);
    const tick = span > 8 ? 1 : span > 4 ? 0.5 : 0.2;
    ctx.strokeStyle = "#e6e8eb";
    ctx.fillStyle = "#556";
    ctx.lineWidth = 1;
    ctx.font = "11px system-ui, sans-serif";
    ctx.textAlign = "center";
    ctx.textBaseline = "top";
    for (let x = Math.ceil(xmin / tick) * tick; x <= xmax + 1e-9; x += tick) {
      ctx.beginPath(); ctx.moveTo(T.px(x), T.py(ymin)); ctx.lineTo(T.px(x), T.py(ymax)); ctx.stroke();
      ctx.fillText((Math.abs(x) < 1e-9 ? 0 : x).toFixed(1), T.px(x), T.py(ymin) + 14);
    }
    ctx.textAlign = "right";
    ctx.textBaseline = "middle";
    for (let y = Math.ceil(ymin / tick) * tick; y <= ymax + 1e-9; y += tick) {
      ctx.beginPath(); ctx.moveTo(T.px(xmin), T.py(y)); ctx.lineTo(T.px(xmax), T.py(y)); ctx.stroke();
      ctx.fillText((Math.abs(y) < 1e-9 ? 0 : y).toFixed(1), T.px(xmin) - 16, T.py(y));
    }
    ctx.textAlign = "left";
    ctx.fillText("x (m)", T.px(xmax) - 30, T.py(ymin) + 32);
    ctx.save(); ctx.translate(T.px(xmin) - 44, T.py(ymax) + 20); ctx.fillText("y (m)", 0, 0); ctx.restore();
    ctx.strokeStyle = "#333";
    ctx.lineWidth = 2;
    ctx.strokeRect(T.px(xmin), T.py(ymax), T.s * (xmax - xmin), T.s * (ymax - ymin));
  }

  function obstacles(ctx, T, list) {
    for (const o of list || []) {
      const [, cx, cy, w, h, vx, vy] = o;
      if (!finite(cx, cy, w, h)) continue;
      const moving = finite(vx, vy) && (vx !== 0 || vy !== 0);
      ctx.fillStyle = moving ? "rgba(120,90,40,0.45)" : "rgba(80,80,80,0.4)";
      ctx.fillRect(T.px(cx - w / 2), T.py(cy + h / 2), T.s * w, T.s * h);
      if (moving) {  // where it heads: a second of travel
        ctx.strokeStyle = "#7a5a28";
        ctx.beginPath(); ctx.moveTo(T.px(cx), T.py(cy)); ctx.lineTo(T.px(cx + vx), T.py(cy + vy)); ctx.stroke();
      }
    }
  }

  // A diamond in the robot's colour (an X is a violation): its current goal larger and filled,
  // goals it reached faint. progress[id]: how many of its goals it has reached, in order.
  function goals(ctx, T, setup, progress) {
    (setup.goals || []).forEach((list, id) => {
      ctx.strokeStyle = colour(id);
      ctx.fillStyle = colour(id);
      ctx.lineWidth = 2;
      const reached = progress && progress[id] !== undefined ? progress[id] : -1;
      list.forEach(([gx, gy], k) => {
        if (!finite(gx, gy)) return;
        const current = k === reached, done = reached >= 0 && k < reached;
        const r = current ? 9 : 6, x = T.px(gx), y = T.py(gy);
        ctx.globalAlpha = done ? 0.3 : 1;
        ctx.beginPath();
        ctx.moveTo(x, y - r); ctx.lineTo(x + r, y); ctx.lineTo(x, y + r); ctx.lineTo(x - r, y); ctx.closePath();
        if (current) { ctx.globalAlpha = 0.35; ctx.fill(); ctx.globalAlpha = 1; }
        ctx.stroke();
      });
      ctx.globalAlpha = 1;
    });
  }

  // What each robot drove with: an arrow along its heading, one second of travel long (backwards
  // when v < 0), and an arc at its tip for the turn rate (half a second of turning). The commands
  // (what each controller asked, before the wheels' saturation) alike, dashed in orange.
  function velocities(ctx, T, scene, vs = scene.v, ws = scene.w, colour = "#111", arc = "#c2185b", dash = []) {
    if (!vs) return;
    ctx.lineWidth = 2;
    ctx.setLineDash(dash);
    for (let i = 0; i < scene.x.length; i++) {
      const v = vs[i], w = ws ? ws[i] : 0;
      if (!finite(scene.x[i], scene.y[i], scene.th[i], v)) continue;
      const x0 = T.px(scene.x[i]), y0 = T.py(scene.y[i]);
      const x1 = T.px(scene.x[i] + v * Math.cos(scene.th[i])), y1 = T.py(scene.y[i] + v * Math.sin(scene.th[i]));
      ctx.strokeStyle = colour;
      ctx.beginPath(); ctx.moveTo(x0, y0); ctx.lineTo(x1, y1);
      const a = Math.atan2(y1 - y0, x1 - x0), head = Math.min(8, Math.hypot(x1 - x0, y1 - y0) / 2);
      ctx.moveTo(x1, y1); ctx.lineTo(x1 - head * Math.cos(a - 0.4), y1 - head * Math.sin(a - 0.4));
      ctx.moveTo(x1, y1); ctx.lineTo(x1 - head * Math.cos(a + 0.4), y1 - head * Math.sin(a + 0.4));
      ctx.stroke();
      if (finite(w) && Math.abs(w) > 1e-3) {  // canvas angles run clockwise: negate the world's
        ctx.strokeStyle = arc;
        ctx.beginPath();
        ctx.arc(x0, y0, 14, -scene.th[i], -scene.th[i] - w * 0.5, w > 0);
        ctx.stroke();
      }
    }
    ctx.setLineDash([]);
  }

  // Points closer than 2 pixels to the last one drawn add nothing to a
  // trail but work: they are skipped (the trail's newest point is always drawn).
  function trails(ctx, T, paths) {
    ctx.globalAlpha = 0.55;
    ctx.lineWidth = 1;
    (paths || []).forEach((path, id) => {
      if (!path || path.length < 2) return;
      ctx.strokeStyle = colour(id);
      ctx.beginPath();
      let lx = T.px(path[0][0]), ly = T.py(path[0][1]);
      ctx.moveTo(lx, ly);
      for (let k = 1; k < path.length; k++) {
        const x = T.px(path[k][0]), y = T.py(path[k][1]);
        if (k < path.length - 1 && Math.abs(x - lx) < 2 && Math.abs(y - ly) < 2) continue;
        ctx.lineTo(x, y);
        lx = x;
        ly = y;
      }
      ctx.stroke();
    });
    ctx.globalAlpha = 1;
  }

  function sensors(ctx, T, setup, scene) {
    for (let i = 0; i < scene.x.length; i++) {
      if (!finite(scene.x[i], scene.y[i], scene.th[i])) continue;
      for (const [range, dir, fov] of setup.sensors || []) {
        ctx.strokeStyle = colour(i);
        ctx.globalAlpha = 0.3;
        ctx.beginPath();
        if (fov >= 2 * Math.PI - 1e-6) {
          ctx.arc(T.px(scene.x[i]), T.py(scene.y[i]), T.s * range, 0, 2 * Math.PI);
        } else {  // canvas angles run clockwise: negate the world's
          const mid = -(scene.th[i] + dir);
          ctx.moveTo(T.px(scene.x[i]), T.py(scene.y[i]));
          ctx.arc(T.px(scene.x[i]), T.py(scene.y[i]), T.s * range, mid - fov / 2, mid + fov / 2);
          ctx.closePath();
        }
        ctx.stroke();
        ctx.globalAlpha = 1;
      }
    }
  }

  function links(ctx, T, scene) {
    for (const [s, r, fade] of scene.links || []) {
      if (!finite(scene.x[s], scene.y[s], scene.x[r], scene.y[r])) continue;
      ctx.strokeStyle = `rgba(40,110,200,${0.15 + 0.6 * (fade === undefined ? 1 : fade)})`;
      ctx.lineWidth = 1;
      ctx.beginPath(); ctx.moveTo(T.px(scene.x[s]), T.py(scene.y[s])); ctx.lineTo(T.px(scene.x[r]), T.py(scene.y[r]));
      ctx.stroke();
    }
  }

  function disc(ctx, T, x, y, th, radius, fill, stroke, dashed) {
    ctx.beginPath();
    ctx.arc(T.px(x), T.py(y), radius, 0, 2 * Math.PI);
    if (fill) { ctx.fillStyle = fill; ctx.fill(); }
    ctx.setLineDash(dashed ? [3, 3] : []);
    ctx.strokeStyle = stroke;
    ctx.lineWidth = 1.5;
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.beginPath();  // the heading
    ctx.moveTo(T.px(x), T.py(y));
    ctx.lineTo(T.px(x + Math.cos(th) * radius / T.s), T.py(y + Math.sin(th) * radius / T.s));
    ctx.stroke();
  }

  function robots(ctx, T, setup, scene, layers) {
    const radius = Math.max(3, (T.s * setup.robot_diameter) / 2);
    if (layers.measured && scene.mx) {
      // The measurement's error times layers.measuredScale (1: as measured), so noise of a few
      // millimetres shows.
      const k = layers.measuredScale || 1;
      for (let i = 0; i < scene.mx.length; i++) {
        if (finite(scene.mx[i], scene.my[i], scene.mth[i], scene.x[i], scene.y[i], scene.th[i])) {
          const dth = Math.atan2(Math.sin(scene.mth[i] - scene.th[i]), Math.cos(scene.mth[i] - scene.th[i]));
          disc(ctx, T, scene.x[i] + k * (scene.mx[i] - scene.x[i]), scene.y[i] + k * (scene.my[i] - scene.y[i]),
               scene.th[i] + k * dth, radius, null, colour(i), true);
        }
      }
    }
    const shown = [];
    for (let i = 0; i < scene.x.length; i++) {
      if (finite(scene.x[i], scene.y[i], scene.th[i])) shown.push(i);
    }
    const sprites = robotSprites(radius, scene.x.length, layers.ids);
    if (!sprites) {  // zoomed in far: a few large discs, drawn as paths
      for (const i of shown) {
        const lost = scene.lost && scene.lost.includes(i);
        disc(ctx, T, scene.x[i], scene.y[i], scene.th[i], radius, lost ? LOST : colour(i), "#222", false);
      }
      if (layers.ids) {
        ctx.font = idFont(radius);
        ctx.textAlign = "center";
        ctx.textBaseline = "middle";
        ctx.fillStyle = "#111";
        for (const i of shown) ctx.fillText(String(i), T.px(scene.x[i]), T.py(scene.y[i]) - radius - 8);
      }
      return;
    }
    // Each robot's disc and id copied from its sprite at whole pixels; the headings in one path.
    const { w, h, cx, cy } = sprites;
    ctx.beginPath();
    for (const i of shown) {
      const x = Math.round(T.px(scene.x[i])), y = Math.round(T.py(scene.y[i]));
      const row = scene.lost && scene.lost.includes(i) ? h : 0;
      ctx.drawImage(sprites.sheet, i * w, row, w, h, x - cx, y - cy, w, h);
      ctx.moveTo(x, y);
      ctx.lineTo(x + Math.cos(scene.th[i]) * radius, y - Math.sin(scene.th[i]) * radius);
    }
    ctx.strokeStyle = "#222";
    ctx.lineWidth = 1.5;
    ctx.stroke();
  }

  // Each robot's disc (its colour, outlined) with its id above, and the same grey for a lost
  // robot, drawn once per size into one image and copied each frame: to a software-rendering
  // browser a copy costs less than filling and stroking an anti-aliased arc, and far less than
  // writing text (docs/performance.md#dream-view). null when zoomed in so far that discs are large.
  const LOST = "#bbb", MAX_SPRITE_RADIUS = 40;
  const idFont = (radius) => `${Math.max(10, Math.round(radius))}px system-ui, sans-serif`;
  let spriteCache = null;
  function robotSprites(radius, count, ids) {
    if (radius > MAX_SPRITE_RADIUS || count === 0) return null;
    const key = `${radius}/${count}/${ids}`;
    if (spriteCache && spriteCache.key === key) return spriteCache;
    const half = Math.ceil(radius + 2), size = Math.max(10, Math.round(radius));
    const labelH = Math.ceil(size * 1.6), above = Math.round(radius) + 8;  // the id's middle above the centre
    const measure = document.createElement("canvas").getContext("2d");
    measure.font = idFont(radius);
    let labelW = 0;
    for (let i = 0; ids && i < count; i++) labelW = Math.max(labelW, Math.ceil(measure.measureText(String(i)).width) + 4);
    const w = Math.max(2 * half, labelW), cx = Math.round(w / 2);
    const cy = ids ? Math.max(half, above + Math.ceil(labelH / 2)) : half, h = cy + half;
    if (w * count > 16384) return null;  // more robots than one image of them holds
    const sheet = typeof OffscreenCanvas === "function" ? new OffscreenCanvas(w * count, 2 * h)
      : Object.assign(document.createElement("canvas"), { width: w * count, height: 2 * h });
    const d = sheet.getContext("2d");
    d.lineWidth = 1.5;
    d.strokeStyle = "#222";
    d.font = idFont(radius);
    d.textAlign = "center";
    d.textBaseline = "middle";
    for (let row = 0; row < 2; row++) {
      for (let i = 0; i < count; i++) {
        d.beginPath();
        d.arc(i * w + cx, row * h + cy, radius, 0, 2 * Math.PI);
        d.fillStyle = row ? LOST : colour(i);
        d.fill();
        d.stroke();
        d.fillStyle = "#111";
        if (ids) d.fillText(String(i), i * w + cx, row * h + cy - above);
      }
    }
    // An ImageBitmap: the cheapest source to copy from.
    const image = sheet.transferToImageBitmap ? sheet.transferToImageBitmap() : sheet;
    spriteCache = { key, sheet: image, w, h, cx, cy };
    return spriteCache;
  }

  // The robot looked at: a ring around it and lines to the robots it hears or sees.
  function selection(ctx, T, setup, scene, selected) {
    const i = selected.id;
    if (!finite(scene.x[i], scene.y[i])) return;
    const radius = Math.max(3, (T.s * setup.robot_diameter) / 2);
    ctx.strokeStyle = "#000";
    ctx.lineWidth = 1;
    ctx.setLineDash([4, 3]);
    for (const j of selected.neighbours || []) {
      if (!finite(scene.x[j], scene.y[j])) continue;
      ctx.beginPath(); ctx.moveTo(T.px(scene.x[i]), T.py(scene.y[i])); ctx.lineTo(T.px(scene.x[j]), T.py(scene.y[j]));
      ctx.stroke();
    }
    ctx.setLineDash([]);
    ctx.lineWidth = 3;
    ctx.beginPath(); ctx.arc(T.px(scene.x[i]), T.py(scene.y[i]), radius + 5, 0, 2 * Math.PI); ctx.stroke();
  }

  // A rule broken over many steps (robots pushing each other) gives a mark
  // each step: each robot or pair is drawn once, an X where it started and,
  // while the latest is new, a ring with what and when.
  function violations(ctx, T, marks) {
    const episodes = new Map();
    for (const mark of marks || []) {
      if (!finite(mark.x, mark.y)) continue;
      const key = `${mark.kind}/${mark.robot}/${mark.other}`;
      const episode = episodes.get(key);
      if (!episode) episodes.set(key, { first: mark, latest: mark });
      else episode.latest = mark;
    }
    ctx.strokeStyle = "#d00";
    ctx.lineWidth = 2;
    for (const { first, latest } of episodes.values()) {
      const x = T.px(first.x), y = T.py(first.y);
      ctx.beginPath();
      ctx.moveTo(x - 5, y - 5); ctx.lineTo(x + 5, y + 5); ctx.moveTo(x - 5, y + 5); ctx.lineTo(x + 5, y - 5);
      ctx.stroke();
      if (latest.flash > 0) {
        const lx = T.px(latest.x), ly = T.py(latest.y);
        ctx.globalAlpha = latest.flash;
        ctx.beginPath(); ctx.arc(lx, ly, 12 + 24 * latest.flash, 0, 2 * Math.PI); ctx.stroke();
        ctx.fillStyle = "#d00";
        ctx.font = "bold 12px system-ui, sans-serif";
        ctx.textAlign = "left";
        ctx.textBaseline = "bottom";
        const since = first.step !== latest.step ? ` (since step ${first.step})` : "";
        const text = describe(latest) + since;
        const width = ctx.measureText(text).width;  // near the right edge: written to the left
        ctx.fillText(text, lx + 14 + width > ctx.canvas.width ? lx - 14 - width : lx + 14, ly - 14);
        ctx.globalAlpha = 1;
      }
    }
  }

  // What changes seldom (the axes, the arena's edge and, while no obstacle moves, the obstacles
  // and the goals) is drawn into an offscreen canvas when it changes and copied each frame: one
  // opaque copy instead of the clear, the axes' text and the paths (docs/performance.md#dream-view).
  // Returns {key, layer, still}: still, it holds the obstacles and goals too.
  let cached = null;
  function background(canvas, T, setup, list, goalLayer, progress) {
    const still = (list || []).every(([, , , , , vx, vy]) => !(finite(vx, vy) && (vx !== 0 || vy !== 0)));
    const key = `${canvas.width}x${canvas.height}/${T.s}/${T.px(0)}/${T.py(0)}/${setup.arena}/` +
                (still ? `${String(list || [])}/${goalLayer ? String(progress || []) : "no goals"}` : "moving");
    if (!cached || cached.key !== key) {
      const layer = sized(cached && cached.layer, canvas);
      const bg = layer.getContext("2d", { alpha: false });
      bg.fillStyle = "#fff";
      bg.fillRect(0, 0, layer.width, layer.height);
      axes(bg, T, setup);
      if (still) {
        obstacles(bg, T, list);
        if (goalLayer) goals(bg, T, setup, progress);
      }
      cached = { key, layer, still };
    }
    return cached;
  }

  // An offscreen canvas of `canvas`'s size, cleared: `layer` when it has that size already.
  function sized(layer, canvas) {
    const fits = layer && layer.width === canvas.width && layer.height === canvas.height;
    const fresh = fits ? layer : document.createElement("canvas");
    fresh.width = canvas.width;  // also clears a canvas used again
    fresh.height = canvas.height;
    return fresh;
  }

  // Live trails only grow at their heads (and lose points at their tails): the background with
  // the trails as they were a few frames ago is kept in an offscreen canvas, redrawn every
  // TRAIL_REDRAW frames, and each frame copies it and adds each trail's newest points. Used once
  // the same `paths` come twice (a replay builds new ones each frame); false: not drawn.
  const TRAIL_REDRAW = 8;
  let trailCache = null;
  function backgroundWithTrails(ctx, T, bg, paths) {
    const c = trailCache;
    if (!c || c.paths !== paths) {
      trailCache = { paths, layer: c && c.layer, bgKey: null };
      return false;
    }
    const heads = c.bgKey === bg.key && c.age < TRAIL_REDRAW ? headsSince(c.last, paths) : null;
    if (!heads) {
      c.layer = sized(c.layer, ctx.canvas);
      const t = c.layer.getContext("2d", { alpha: false });
      t.drawImage(bg.layer, 0, 0);
      trails(t, T, paths);
      c.last = paths.map((path) => path && path[path.length - 1]);
      c.bgKey = bg.key;
      c.age = 0;
    } else {
      c.age += 1;
    }
    ctx.drawImage(c.layer, 0, 0);
    if (heads) trails(ctx, T, heads);
    return true;
  }

  // Each path's points from `last` (its newest point when the layer was drawn) on; null when a
  // path lost that point (a new run).
  function headsSince(last, paths) {
    const heads = [];
    for (let id = 0; id < paths.length; id++) {
      const path = paths[id];
      if (!path) continue;
      const from = last[id] === undefined ? 0 : path.lastIndexOf(last[id]);
      if (from < 0) return null;
      heads[id] = path.slice(from);
    }
    return heads;
  }

  // What the controllers drew (DREAM_DRAW_<id>): entries [step, robot, clipped, shapes], each shape
  // [kind, rgba, width m, size m, fill, [x...], [y...], text]; kinds as drawing_t's (1 line, 2 circle,
  // 3 polygon, 4 arrow, 5 text). The same look as dream render's (sim/render/src/drawing_painter.cc).
  const LINE = 1, CIRCLE = 2, POLYGON = 3, ARROW = 4, TEXT = 5;
  function rgbaText(rgba) {
    return `rgba(${(rgba >>> 24) & 255}, ${(rgba >>> 16) & 255}, ${(rgba >>> 8) & 255}, ${((rgba & 255) / 255).toFixed(3)})`;
  }
  function shape(ctx, T, [kind, rgba, width, size, fill, xs, ys, text]) {
    if (!xs.length || !finite(...xs, ...ys)) return;
    const colour = rgbaText(rgba);
    const line = Math.max(1, width * T.s);
    ctx.strokeStyle = colour;
    ctx.fillStyle = colour;
    ctx.lineWidth = line;
    ctx.beginPath();
    if (kind === TEXT) {
      ctx.font = `${Math.max(4, size * T.s).toFixed(1)}px system-ui, sans-serif`;
      ctx.textAlign = "left";
      ctx.textBaseline = "alphabetic";
      ctx.fillText(text, T.px(xs[0]), T.py(ys[0]));
      return;
    }
    if (kind === CIRCLE) {
      ctx.arc(T.px(xs[0]), T.py(ys[0]), Math.max(0, size * T.s), 0, 2 * Math.PI);
    } else {
      ctx.moveTo(T.px(xs[0]), T.py(ys[0]));
      for (let k = 1; k < xs.length; k++) ctx.lineTo(T.px(xs[k]), T.py(ys[k]));
      if (kind === POLYGON) ctx.closePath();
    }
    if (fill && (kind === CIRCLE || kind === POLYGON)) ctx.fill(); else ctx.stroke();
    if (kind !== ARROW) return;
    const x0 = T.px(xs[0]), y0 = T.py(ys[0]), x1 = T.px(xs[1]), y1 = T.py(ys[1]);
    const length = Math.hypot(x1 - x0, y1 - y0);
    if (length <= 0) return;
    const head = Math.min(Math.max(8, 4 * line), 0.5 * length), ux = (x1 - x0) / length, uy = (y1 - y0) / length;
    ctx.beginPath();
    ctx.moveTo(x1, y1);
    ctx.lineTo(x1 - head * ux - 0.5 * head * uy, y1 - head * uy + 0.5 * head * ux);
    ctx.lineTo(x1 - head * ux + 0.5 * head * uy, y1 - head * uy - 0.5 * head * ux);
    ctx.closePath();
    ctx.fill();
  }
  function drawings(ctx, T, setup, list) {
    if (!list || !list.length) return;
    const [x0, x1, y0, y1] = setup.arena;
    ctx.save();
    ctx.beginPath();
    ctx.rect(T.px(x0), T.py(y1), T.px(x1) - T.px(x0), T.py(y0) - T.py(y1));
    ctx.clip();
    ctx.lineCap = "round";
    ctx.lineJoin = "round";
    for (const [, , , shapes] of list) for (const s of shapes) shape(ctx, T, s);
    ctx.restore();
  }

  function describe(mark) {
    const who = mark.kind === "collision" ? `robots ${mark.robot} and ${mark.other}`
      : mark.kind === "obstacle" ? `robot ${mark.robot} in obstacle ${mark.other}` : `robot ${mark.robot} outside`;
    return `${mark.kind}: ${who}, step ${mark.step}`;
  }

  // scene: {x, y, th, v?, w?, mx?, my?, mth?, obstacles, links, drawings?, marks, lost, goalProgress?, selected?};
  // paths: per robot [[x, y], ...]; camera: {zoom, panX, panY}. Returns the transform drawn with
  // (world <-> canvas pixels), for what the page does with the mouse.
  function draw(canvas, setup, scene, layers, paths, camera) {
    // Opaque: the browser composites it without blending it over the page.
    const ctx = canvas.getContext("2d", { alpha: false });
    if (!setup || !setup.arena) {
      ctx.fillStyle = "#fff";
      ctx.fillRect(0, 0, canvas.width, canvas.height);
      return null;
    }
    const T = transform(canvas, setup, scene, camera);
    const list = scene && scene.obstacles;
    const bg = background(canvas, T, setup, list, layers.goals, scene && scene.goalProgress);
    const trailsDrawn = scene && layers.trails && bg.still && paths && backgroundWithTrails(ctx, T, bg, paths);
    if (!trailsDrawn && !(scene && layers.trails)) trailCache = null;  // drawn again from scratch when shown
    if (!trailsDrawn) {
      ctx.drawImage(bg.layer, 0, 0);
      if (!bg.still) {
        obstacles(ctx, T, list);
        if (layers.goals) goals(ctx, T, setup, scene && scene.goalProgress);
      }
    }
    if (!scene) return T;
    if (layers.trails && !trailsDrawn) trails(ctx, T, paths);
    if (layers.sensors) sensors(ctx, T, setup, scene);
    if (layers.radio) links(ctx, T, scene);
    if (layers.drawings) drawings(ctx, T, setup, scene.drawings);
    robots(ctx, T, setup, scene, layers);
    if (layers.velocities) velocities(ctx, T, scene);
    if (layers.commands) velocities(ctx, T, scene, scene.cv, scene.cw, "#ef6c00", "#ef6c00", [5, 3]);
    if (scene.selected) selection(ctx, T, setup, scene, scene.selected);
    if (layers.violations) violations(ctx, T, scene.marks);
    return T;
  }

  return { draw, describe, colour, PALETTE_SIZE };
})();
