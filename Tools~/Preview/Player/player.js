// Motion preview player: tracks of global joint positions drawn side by side on a 2D canvas with a
// small perspective camera (no WebGL, no library), in sync, with keys and a per-frame error plot.
(function () {
  'use strict';
  var data = JSON.parse(document.getElementById('preview-data').textContent);
  var J = data.joints.length, N = data.frames, q = data.quantum, H = data.height, floorY = data.floor;
  var keys = data.keys, keySet = new Set(keys);
  // Labels are the file's frame numbers (a preview of --frames 200-299 shows 200..299); indices stay 0-based.
  var first = data.firstFrame || 0, body = data.bodyRoot || 0;
  var drawsBone = data.drawsBone || data.parents.map(function (p) { return p >= 0 ? 1 : 0; });
  var cmPerUnit = data.cmPerUnit || 0;
  var SVG = 'http://www.w3.org/2000/svg';

  // Positions arrive as integer changes from the previous frame; sum them back up once.
  var tracks = data.tracks.map(function (t, index) {
    var stride = J * 3, n = t.frames, pos = new Float32Array(n * stride), d = t.deltas;
    for (var k = 0; k < stride; k++) {
      var acc = 0;
      for (var f = 0; f < n; f++) { acc += d[f * stride + k]; pos[f * stride + k] = acc * q; }
    }
    return { index: index, name: t.name, color: t.color, frames: n, pos: pos, offset: t.offset,
             errors: t.errors ? t.errors.map(function (e) { return e * q; }) : null, meanError: t.meanError,
             footJoints: t.footJoints || null, planted: t.planted || null };
  });
  var heads = [];
  for (var j = 0; j < J; j++) {
    var isLeaf = data.parents.indexOf(j) < 0;
    if (isLeaf && /head/i.test(data.joints[j])) heads.push(j);
  }

  // ---- state shared with scripts and tests -------------------------------------------------------
  var state = { frame: 0, playing: true, speed: 1, follow: true };
  var preview = {
    get frame() { return state.frame; },
    get playing() { return state.playing; },
    frameCount: N,
    fps: data.fps,
    keys: keys.slice(),
    firstFrame: first,
    setFrame: function (k) { setFrame(k); },
    // Screen position [x, y, depth] of joint j of track t at the current frame (null: behind the camera).
    screenOf: function (t, j) { updateView(); var p = jointAt(tracks[t], state.frame, j); return project(p[0], p[1], p[2]); },
    // The foot joints of track `t` planted at the current frame (drawn as footprints on the floor).
    plantedAt: function (t) { return plantedJoints(tracks[t], state.frame); },
    play: function () { setPlaying(true); },
    pause: function () { setPlaying(false); }
  };
  window.preview = preview;

  // ---- DOM ---------------------------------------------------------------------------------------
  var canvas = document.getElementById('view'), ctx = canvas.getContext('2d');
  var scrub = document.getElementById('scrub'), playButton = document.getElementById('play');
  var frameText = document.getElementById('frame'), timeText = document.getElementById('time');
  var badge = document.getElementById('badge');
  scrub.max = String(N - 1);
  document.getElementById('frames').textContent = ' / ' + (first + N - 1);
  var legend = document.getElementById('legend');
  tracks.forEach(function (t) {
    var chip = document.createElement('span');
    chip.className = 'chip';
    var dot = document.createElement('i');
    dot.style.background = t.color;
    chip.appendChild(dot);
    chip.appendChild(document.createTextNode(t.name));
    if (t.index === data.groundTruth) {
      // "Ground truth ground truth" reads as a stutter: say it only when the name does not.
      if (!/ground[ -]?truth/i.test(t.name)) chip.appendChild(small(' ground truth'));
    } else if (t.meanError !== undefined) {
      chip.appendChild(small(' mean error ' + distance(t.meanError) + (keys.length ? ' per joint between keys' : ' per joint')));
    }
    legend.appendChild(chip);
  });
  // The footprint note after every track's chip, not between two of them.
  if (tracks.some(function (t) { return t.planted; })) {
    legend.dataset.planted = '1';
    legend.appendChild(small('ellipses on the floor: planted feet (within 3 % of a leg length of the ground, slower than 15 % of a leg length per second)'));
  }
  var km = document.getElementById('keymarks');
  keys.forEach(function (k) {
    var b = document.createElement('b');
    b.style.left = (N > 1 ? 100 * k / (N - 1) : 0) + '%';
    b.title = 'key frame ' + (first + k);
    km.appendChild(b);
  });

  function small(text) { var s = document.createElement('small'); s.textContent = text; return s; }
  function fmt(x) { return x >= 100 ? x.toFixed(0) : x >= 10 ? x.toFixed(1) : x >= 1 ? x.toFixed(2) : x.toPrecision(2); }
  // A distance in data units with its unit: centimetres when the skeleton told the unit.
  function distance(x) { return cmPerUnit ? fmt(x * cmPerUnit) + ' cm' : fmt(x) + ' data units'; }

  // ---- camera: spherical orbit around a target -------------------------------------------------
  var FOV = 32 * Math.PI / 180;
  var cam = {};
  function center(frame) {
    var x = 0, z = 0;
    tracks.forEach(function (t) {
      var i = (Math.min(frame, t.frames - 1) * J + body) * 3;
      x += t.pos[i] + t.offset[0]; z += t.pos[i + 2] + t.offset[2];
    });
    return [x / tracks.length, floorY + 0.45 * H, z / tracks.length];
  }
  function resetCamera() {
    // From the side the motion heads to, square to the row of tracks (which stand apart across the
    // travel), so every figure is as far from the camera as the others and none looks bigger; far
    // enough to frame the whole row.
    var tr = data.travel, yaw0 = Math.atan2(tr[0], tr[2]);
    var o0 = tracks[0].offset, o1 = tracks[tracks.length - 1].offset;
    var width = Math.hypot(o1[0] - o0[0], o1[2] - o0[2]) + 1.2 * H;
    var aspect = Math.max(0.5, view.w / Math.max(1, view.h)), tan = Math.tan(FOV / 2);
    cam.yaw = yaw0;
    cam.pitch = 0.3;
    cam.dist = Math.max(2.2 * H / (2 * tan), 1.3 * width / (2 * tan * aspect));
    cam.target = center(state.frame);
  }

  var view = { w: 1, h: 1, f: 1, eye: [0, 0, 0], r: [1, 0, 0], u: [0, 1, 0], fw: [0, 0, 1] };
  function updateView() {
    var cp = Math.cos(cam.pitch), t = cam.target;
    var eye = [t[0] + cam.dist * cp * Math.sin(cam.yaw), t[1] + cam.dist * Math.sin(cam.pitch), t[2] + cam.dist * cp * Math.cos(cam.yaw)];
    var fw = norm([t[0] - eye[0], t[1] - eye[1], t[2] - eye[2]]);
    var r = norm(cross(fw, [0, 1, 0]));
    var u = cross(r, fw);
    view.eye = eye; view.fw = fw; view.r = r; view.u = u;
    view.f = (view.h / 2) / Math.tan(FOV / 2);
  }
  function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
  function norm(a) { var l = Math.hypot(a[0], a[1], a[2]) || 1; return [a[0] / l, a[1] / l, a[2] / l]; }
  // World point → [screen x, screen y, depth]; depth ≤ near means behind the camera.
  function project(x, y, z) {
    var vx = x - view.eye[0], vy = y - view.eye[1], vz = z - view.eye[2];
    var cx = vx * view.r[0] + vy * view.r[1] + vz * view.r[2];
    var cy = vx * view.u[0] + vy * view.u[1] + vz * view.u[2];
    var cz = vx * view.fw[0] + vy * view.fw[1] + vz * view.fw[2];
    if (cz < 1e-3 * H) return null;
    return [view.w / 2 + cx * view.f / cz, view.h / 2 - cy * view.f / cz, cz];
  }

  // ---- drawing -----------------------------------------------------------------------------------
  var dpr = 1;
  function resize() {
    dpr = window.devicePixelRatio || 1;
    var w = canvas.clientWidth, h = canvas.clientHeight;
    canvas.width = Math.max(1, Math.round(w * dpr));
    canvas.height = Math.max(1, Math.round(h * dpr));
    view.w = w; view.h = h;
    drawPlot();
  }

  function niceStep(x) {
    var p = Math.pow(10, Math.floor(Math.log10(x))), m = x / p;
    return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
  }
  var cell = niceStep(H / 2);

  function drawGrid() {
    var t = cam.target, n = 14, cx = Math.round(t[0] / cell), cz = Math.round(t[2] / cell);
    ctx.lineWidth = 1;
    for (var axis = 0; axis < 2; axis++) {
      for (var i = -n; i <= n; i++) {
        var major = ((axis ? cx : cz) + i) % 5 === 0;
        for (var s = -n; s < n; s++) {
          var a, b;
          if (axis === 0) { a = project((cx + s) * cell, floorY, (cz + i) * cell); b = project((cx + s + 1) * cell, floorY, (cz + i) * cell); }
          else { a = project((cx + i) * cell, floorY, (cz + s) * cell); b = project((cx + i) * cell, floorY, (cz + s + 1) * cell); }
          if (!a || !b) continue;
          var fade = 1 - Math.min(1, Math.hypot(i, s + 0.5) / n);
          ctx.strokeStyle = 'rgba(170,185,200,' + (fade * (major ? 0.32 : 0.14)).toFixed(3) + ')';
          ctx.beginPath(); ctx.moveTo(a[0], a[1]); ctx.lineTo(b[0], b[1]); ctx.stroke();
        }
      }
    }
  }

  function plantedJoints(t, frame) {
    if (!t || !t.planted) return [];
    var mask = t.planted[Math.min(frame, t.frames - 1)], out = [];
    t.footJoints.forEach(function (j, k) { if (mask & (1 << k)) out.push(j); });
    return out;
  }

  function jointAt(t, frame, j) {
    var i = (Math.min(frame, t.frames - 1) * J + j) * 3;
    return [t.pos[i] + t.offset[0], t.pos[i + 1], t.pos[i + 2] + t.offset[2]];
  }

  function draw() {
    updateView();
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.clearRect(0, 0, view.w, view.h);
    drawGrid();
    var frame = state.frame, isKey = keySet.has(frame);
    var items = [], boneWidth = 0.026 * H, jointRadius = 0.017 * H;
    ctx.lineCap = 'round';
    tracks.forEach(function (t) {
      var pts = [], shadow = [];
      for (var j = 0; j < J; j++) {
        var p = jointAt(t, frame, j);
        pts.push(project(p[0], p[1], p[2]));
        shadow.push(project(p[0], floorY, p[2]));
      }
      // Shadows first: they ground the skeletons and show where the feet touch the floor.
      ctx.strokeStyle = 'rgba(0,0,0,0.35)';
      for (j = 1; j < J; j++) {
        var a = shadow[j], b = shadow[data.parents[j]];
        if (!a || !b || !drawsBone[j]) continue;
        ctx.lineWidth = boneWidth * view.f / ((a[2] + b[2]) / 2);
        ctx.beginPath(); ctx.moveTo(a[0], a[1]); ctx.lineTo(b[0], b[1]); ctx.stroke();
      }
      // Planted feet: a footprint in the track's colour on the floor under each planted foot joint.
      plantedJoints(t, frame).forEach(function (pj) {
        var s = shadow[pj];
        if (!s) return;
        var r = Math.max(3, 0.05 * H * view.f / s[2]);
        ctx.beginPath(); ctx.ellipse(s[0], s[1], r, 0.45 * r, 0, 0, 2 * Math.PI);
        ctx.fillStyle = t.color; ctx.globalAlpha = 0.55; ctx.fill(); ctx.globalAlpha = 1;
      });
      for (j = 1; j < J; j++) {
        var p0 = pts[j], p1 = pts[data.parents[j]];
        if (p0 && p1 && drawsBone[j]) items.push({ kind: 0, a: p1, b: p0, depth: (p0[2] + p1[2]) / 2, t: t });
      }
      for (j = 0; j < J; j++) {
        // Joints above the body root (a root node at the origin) are not drawn at all.
        if (pts[j] && (j === body || drawsBone[j])) items.push({ kind: 1, a: pts[j], depth: pts[j][2] - 1e-4 * H, t: t, head: heads.indexOf(j) >= 0 });
      }
      t.labelAt = labelPoint(t, frame);
    });
    // Painter's order: far first.
    items.sort(function (x, y) { return y.depth - x.depth; });
    items.forEach(function (it) {
      var scale = view.f / it.depth;
      if (it.kind === 0) {
        ctx.strokeStyle = it.t.color;
        ctx.lineWidth = Math.max(1.5, boneWidth * scale);
        ctx.beginPath(); ctx.moveTo(it.a[0], it.a[1]); ctx.lineTo(it.b[0], it.b[1]); ctx.stroke();
      } else {
        var rad = Math.max(2, (it.head ? 2.4 : 1) * jointRadius * scale);
        ctx.beginPath(); ctx.arc(it.a[0], it.a[1], rad, 0, 2 * Math.PI);
        ctx.fillStyle = isKey ? '#ffc933' : '#f4f6f8';
        ctx.fill();
        ctx.lineWidth = Math.max(1, 0.35 * rad);
        ctx.strokeStyle = it.t.color;
        ctx.stroke();
      }
    });
    // Labels above the heads, with the current error where there is a ground truth.
    ctx.font = '600 13px system-ui, sans-serif';
    ctx.textAlign = 'center';
    tracks.forEach(function (t) {
      var p = t.labelAt;
      if (!p) return;
      var text = t.name;
      if (t.errors) text += '  ' + distance(t.errors[Math.min(frame, t.errors.length - 1)]);
      ctx.fillStyle = 'rgba(21,24,28,0.75)';
      var w = ctx.measureText(text).width + 12;
      ctx.fillRect(p[0] - w / 2, p[1] - 17, w, 20);
      ctx.fillStyle = t.color;
      ctx.fillText(text, p[0], p[1] - 2);
    });
    badge.hidden = !isKey;
  }

  function labelPoint(t, frame) {
    var top = -Infinity, root = jointAt(t, frame, body);
    for (var j = 0; j < J; j++) top = Math.max(top, jointAt(t, frame, j)[1]);
    return project(root[0], top + 0.18 * H, root[2]);
  }

  // ---- error plot (SVG, redrawn on resize; a cursor line follows the frame) ----------------------
  var plot = document.getElementById('plot'), cursor = null, plotGeom = null;
  var withErrors = tracks.filter(function (t) { return t.errors; });
  if (withErrors.length) {
    document.getElementById('errors').hidden = false;
    document.getElementById('truth-name').textContent = tracks[data.groundTruth].name + (cmPerUnit ? ' (cm)' : ' (data units)');
  }
  function el(name, attrs, parent) {
    var e = document.createElementNS(SVG, name);
    for (var k in attrs) e.setAttribute(k, attrs[k]);
    if (parent) parent.appendChild(e);
    return e;
  }
  function drawPlot() {
    if (!withErrors.length) return;
    var w = plot.clientWidth, h = plot.clientHeight;
    if (w < 10 || h < 10) return;
    while (plot.firstChild) plot.removeChild(plot.firstChild);
    plot.setAttribute('viewBox', '0 0 ' + w + ' ' + h);
    var left = 48, right = 12, top = 10, bottom = 24;
    // Plotted in the unit the header names: centimetres when known, else data units.
    var unit = cmPerUnit || 1, max = 0;
    withErrors.forEach(function (t) { t.errors.forEach(function (e) { if (e * unit > max) max = e * unit; }); });
    var step = niceStep(Math.max(max, 1e-9) / 4), ymax = Math.ceil(max / step) * step || step;
    var decimals = Math.max(0, Math.min(6, -Math.floor(Math.log10(step))));
    var X = function (f) { return left + (N > 1 ? f / (N - 1) : 0) * (w - left - right); };
    var Y = function (e) { return h - bottom - e / ymax * (h - top - bottom); };
    var Ye = function (e) { return Y(e * unit); };
    plotGeom = { X: X, left: left, right: right, w: w };
    for (var v = 0; v <= ymax + step / 2; v += step) {
      el('line', { x1: left, x2: w - right, y1: Y(v), y2: Y(v), stroke: '#2c333b' }, plot);
      el('text', { x: left - 6, y: Y(v) + 4, 'text-anchor': 'end' }, plot).textContent = v.toFixed(decimals);
    }
    keys.forEach(function (k) { el('line', { x1: X(k), x2: X(k), y1: top, y2: h - bottom, stroke: '#ffc933', 'stroke-opacity': 0.35 }, plot); });
    var fstep = niceStep(Math.max(1, (N - 1) / 8));
    // Ticks on round file frame numbers (frame index + first).
    for (var f = Math.ceil(first / fstep) * fstep - first; f < N; f += fstep) el('text', { x: X(f), y: h - 7, 'text-anchor': 'middle' }, plot).textContent = String(first + f);
    withErrors.forEach(function (t) {
      var pts = t.errors.map(function (e, i) { return X(i).toFixed(1) + ',' + Ye(e).toFixed(1); }).join(' ');
      el('polyline', { points: pts, fill: 'none', stroke: t.color, 'stroke-width': 1.6, 'stroke-linejoin': 'round' }, plot);
    });
    cursor = el('line', { y1: top, y2: h - bottom, stroke: '#dfe4ea', 'stroke-width': 1 }, plot);
    moveCursor();
  }
  function moveCursor() {
    if (!cursor || !plotGeom) return;
    var x = plotGeom.X(state.frame);
    cursor.setAttribute('x1', x); cursor.setAttribute('x2', x);
  }
  function plotScrub(ev) {
    if (!plotGeom) return;
    var rect = plot.getBoundingClientRect();
    var x = (ev.clientX - rect.left) / rect.width * plotGeom.w;
    var u = (x - plotGeom.left) / (plotGeom.w - plotGeom.left - plotGeom.right);
    setPlaying(false);
    setFrame(Math.round(u * (N - 1)));
  }
  var plotDrag = false;
  plot.addEventListener('pointerdown', function (ev) { plotDrag = true; plot.setPointerCapture(ev.pointerId); plotScrub(ev); });
  plot.addEventListener('pointermove', function (ev) { if (plotDrag) plotScrub(ev); });
  plot.addEventListener('pointerup', function () { plotDrag = false; });

  // ---- frame, playback, input --------------------------------------------------------------------
  function setFrame(k) {
    k = Math.max(0, Math.min(N - 1, Math.round(Number(k) || 0)));
    state.frame = k;
    scrub.value = String(k);
    frameText.textContent = String(first + k);
    timeText.textContent = ((first + k) / data.fps).toFixed(2) + ' s';
    if (state.follow) cam.target = center(k);
    moveCursor();
    dirty = true;
  }
  function setPlaying(on) {
    state.playing = on;
    playButton.textContent = on ? 'Pause' : 'Play';
    last = null;
  }
  playButton.addEventListener('click', function () { setPlaying(!state.playing); });
  scrub.addEventListener('input', function () { setPlaying(false); setFrame(scrub.value); });
  document.getElementById('speed').addEventListener('change', function (ev) { state.speed = Number(ev.target.value); });
  document.getElementById('follow').addEventListener('change', function (ev) { state.follow = ev.target.checked; if (state.follow) cam.target = center(state.frame); dirty = true; });
  document.addEventListener('keydown', function (ev) {
    if (ev.target && ev.target.tagName === 'SELECT') return;
    if (ev.code === 'Space') { ev.preventDefault(); setPlaying(!state.playing); }
    else if (ev.code === 'ArrowRight') { ev.preventDefault(); setPlaying(false); setFrame(state.frame + 1); }
    else if (ev.code === 'ArrowLeft') { ev.preventDefault(); setPlaying(false); setFrame(state.frame - 1); }
  });

  var drag = null;
  canvas.addEventListener('pointerdown', function (ev) { drag = { x: ev.clientX, y: ev.clientY }; canvas.setPointerCapture(ev.pointerId); canvas.classList.add('dragging'); });
  canvas.addEventListener('pointermove', function (ev) {
    if (!drag) return;
    cam.yaw -= (ev.clientX - drag.x) * 0.008;
    cam.pitch = Math.max(-0.15, Math.min(1.5, cam.pitch + (ev.clientY - drag.y) * 0.006));
    drag = { x: ev.clientX, y: ev.clientY };
    dirty = true;
  });
  canvas.addEventListener('pointerup', function () { drag = null; canvas.classList.remove('dragging'); });
  canvas.addEventListener('wheel', function (ev) {
    ev.preventDefault();
    cam.dist = Math.max(0.3 * H, Math.min(200 * H, cam.dist * Math.exp(ev.deltaY * 0.0012)));
    dirty = true;
  }, { passive: false });
  canvas.addEventListener('dblclick', function () { resetCamera(); dirty = true; });
  window.addEventListener('resize', function () { resize(); dirty = true; });

  var last = null, acc = 0, dirty = true;
  function tick(now) {
    if (state.playing && N > 1) {
      if (last !== null) {
        acc += (now - last) / 1000 * data.fps * state.speed;
        if (acc >= 1) {
          var steps = Math.floor(acc);
          acc -= steps;
          setFrame((state.frame + steps) % N);
        }
      }
      last = now;
    }
    if (dirty) { dirty = false; draw(); }
    requestAnimationFrame(tick);
  }
  resize();
  resetCamera();
  // A link may name a frame to open on, paused: file.html#frame=45 (the file's frame number, as shown).
  var start = /frame=(\d+)/.exec(location.hash);
  setFrame(start ? Number(start[1]) - first : 0);
  if (start) setPlaying(false);
  requestAnimationFrame(tick);
})();
