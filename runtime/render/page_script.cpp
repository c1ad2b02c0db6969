// The animation page's script (see page.h). It replays the run embedded in
// the page as JSON (animation.cpp) and recomputes every frame from it:
//
//   time t  -> the step in progress (binary search on the steps' starts)
//           -> each motor's encoder count (its last segment, rounded the
//              way SimMachine::positionAt rounds)
//           -> joint values (precision, coupling) -> D-H forward kinematics
//           -> each part's lines, stored in its own frame's coordinates,
//              through one 3x4 matrix per part (view · frame [· finger])
//           -> one canvas path and one stroke per EGA colour.
//
// Objects: an object's lines are stored in world coordinates at its
// placement. The run's grasp events (run.grasps) move it: after a take,
// its lines go through the program robot's last frame F_world_E(t) times
// the recorded F_E_object (composed with the placement's inverse); after a
// let-go, through the recorded resting pose; before its first event it is
// where the workcell placed it.
//
// The camera formula is runtime/render/camera.h's. window.robotsim exposes
// the state, the projection and frame-time statistics to tests and benches.
#include "runtime/render/page.h"

namespace rs::render::page {

const std::string_view kScript = R"JS('use strict';
(function () {
  const model = JSON.parse(document.getElementById('robotsim-model').textContent);
  const run = model.run;
  const steps = run.index.length;
  const motorCount = run.motors.length;
  const style = model.style;  // the stills' colours and marks (palette.h, scene.h, draw.h)
  const EGA = style.palette;

  // ---- Maths. An affine map is a Float64Array(12), column-major: the
  // images of the x, y and z axes, then of the origin (Eigen's layout).
  const RAD = Math.PI / 180;
  function affine() { const m = new Float64Array(12); m[0] = m[4] = m[8] = 1; return m; }
  function multiply(a, b, out) {  // out = a·b; out is neither a nor b
    for (let c = 0; c < 12; c += 3) {
      const x = b[c], y = b[c + 1], z = b[c + 2];
      out[c] = a[0] * x + a[3] * y + a[6] * z;
      out[c + 1] = a[1] * x + a[4] * y + a[7] * z;
      out[c + 2] = a[2] * x + a[5] * y + a[8] * z;
    }
    out[9] += a[9]; out[10] += a[10]; out[11] += a[11];
    return out;
  }
  // sin and cos of degrees, exact at multiples of 90 (as kinematics/trig.h).
  const SC = [0, 1];
  function sincos(deg) {
    const quarter = Math.round(deg / 90);
    const r = (deg - 90 * quarter) * RAD, s = Math.sin(r), c = Math.cos(r);
    switch (((quarter % 4) + 4) % 4) {
      case 0: SC[0] = s; SC[1] = c; break;
      case 1: SC[0] = c; SC[1] = -s; break;
      case 2: SC[0] = -s; SC[1] = -c; break;
      default: SC[0] = -c; SC[1] = s;
    }
    return SC;
  }
  // camera.h: pixel = diag(s, -s, s)·Rx·Ry·Rz·(p + window - center) + (W/2, H/2, 0).
  function viewMatrix(view, win, zoom, W, H, out) {
    const s = zoom * 0.45 * Math.min(W, H) / model.fit.radius;
    const [sx, cx] = sincos(view[0]);  // destructuring copies SC at once
    const [sy, cy] = sincos(view[1]);
    const [sz, cz] = sincos(view[2]);
    const Rx = [1, 0, 0, 0, cx, sx, 0, -sx, cx];  // column-major 3x3
    const Ry = [cy, 0, -sy, 0, 1, 0, sy, 0, cy];
    const Rz = [cz, sz, 0, -sz, cz, 0, 0, 0, 1];
    const m3 = (a, b) => {
      const o = new Array(9);
      for (let c = 0; c < 9; c += 3)
        for (let r = 0; r < 3; r++) o[c + r] = a[r] * b[c] + a[3 + r] * b[c + 1] + a[6 + r] * b[c + 2];
      return o;
    };
    const R = m3(Rx, m3(Ry, Rz));
    for (let c = 0; c < 9; c += 3) { out[c] = s * R[c]; out[c + 1] = -s * R[c + 1]; out[c + 2] = s * R[c + 2]; }
    const c0 = model.fit.center;
    const wx = win[0] - c0[0], wy = win[1] - c0[1], wz = win[2] - c0[2];
    out[9] = out[0] * wx + out[3] * wy + out[6] * wz + W / 2;
    out[10] = out[1] * wx + out[4] * wy + out[7] * wz + H / 2;
    out[11] = out[2] * wx + out[5] * wy + out[8] * wz;
    return out;
  }
  // A_i = Rz(θ)·Tz(d)·Tx(a)·Rx(α), with the joint variable q.
  function dhMatrix(j, q, out) {
    const [st, ct] = j.revolute ? [...sincos(q)] : [j.sinTheta, j.cosTheta];
    const d = j.revolute ? j.d : q;
    const sa = j.sinAlpha, ca = j.cosAlpha;
    out[0] = ct; out[1] = st; out[2] = 0;
    out[3] = -ca * st; out[4] = ca * ct; out[5] = sa;
    out[6] = sa * st; out[7] = -sa * ct; out[8] = ca;
    out[9] = j.a * ct; out[10] = j.a * st; out[11] = d;
  }
  // Right-handed rotation by deg about the line [px, py, pz, dx, dy, dz].
  function aboutLine(ax, deg, out) {
    const a = deg * RAD, c = Math.cos(a), s = Math.sin(a), t = 1 - c;
    const px = ax[0], py = ax[1], pz = ax[2], x = ax[3], y = ax[4], z = ax[5];
    out[0] = t * x * x + c; out[1] = t * x * y + s * z; out[2] = t * x * z - s * y;
    out[3] = t * x * y - s * z; out[4] = t * y * y + c; out[5] = t * y * z + s * x;
    out[6] = t * x * z + s * y; out[7] = t * y * z - s * x; out[8] = t * z * z + c;
    out[9] = px - (out[0] * px + out[3] * py + out[6] * pz);
    out[10] = py - (out[1] * px + out[4] * py + out[7] * pz);
    out[11] = pz - (out[2] * px + out[5] * py + out[8] * pz);
    return out;
  }

  // ---- The model, prepared once: typed arrays, lines grouped by colour.
  function preparePart(p) {
    p.pts = Float64Array.from(p.pts);
    p.count = p.colors.length;
    p.screen = new Float64Array(4 * p.count);
    const lists = [];
    for (let c = 0; c < 16; c++) lists.push([]);
    p.colors.forEach((c, k) => lists[c & 15].push(k));
    p.byColor = lists.map((l) => (l.length ? Int32Array.from(l) : null));
  }
  const allParts = [];
  for (const r of model.robots) {
    r.n = r.joints.length;
    for (const j of r.joints) {
      [j.sinAlpha, j.cosAlpha] = [...sincos(j.alpha)];
      [j.sinTheta, j.cosTheta] = [...sincos(j.theta)];
    }
    r.F = [Float64Array.from(r.base)];
    for (let i = 1; i <= r.n; i++) r.F.push(affine());
    r.q = new Float64Array(r.n);
    r.A = affine();
    r.T = affine();
    r.finger = affine();
    r.zero = new Int32Array(r.letters.length);
    for (const p of r.parts) { preparePart(p); allParts.push(p); }
  }
  for (const o of model.objects) { preparePart(o); allParts.push(o); }

  // Each object's grasp events (in step order), and its two matrices.
  const carrier = model.robots.find((r) => r.program) || null;
  for (const o of model.objects) {
    o.grasps = { step: [], at: [], held: [], pose: [] };
    o.W = affine();  // F_world_E(t) · pose while carried
    o.T = affine();  // view · the above
  }
  if (carrier) {
    const g = run.grasps;
    g.object.forEach((obj, e) => {
      const list = model.objects[obj].grasps;
      list.step.push(g.step[e]); list.at.push(g.at[e]); list.held.push(g.held[e]);
      list.pose.push(Float64Array.from(g.pose.slice(12 * e, 12 * e + 12)));
    });
  }

  function poseRobot(r, enc) {
    const n = r.n, q = r.q;
    for (let k = 0; k < n; k++) {
      const j = r.joints[k];
      q[k] = j.home + j.precision * (enc[j.encoder] || 0);
    }
    for (let k = 0; k + 1 < n; k++) {
      const j = r.joints[k];
      if (j.coupling) q[k + 1] -= q[k] - j.home;
    }
    for (let i = 1; i <= n; i++) {
      dhMatrix(r.joints[i - 1], q[i - 1], r.A);
      multiply(r.F[i - 1], r.A, r.F[i]);
    }
  }
  function projectPart(T, p) {
    const a = T[0], b = T[1], d = T[3], e = T[4], g = T[6], h = T[7], tx = T[9], ty = T[10];
    const pts = p.pts, out = p.screen;
    for (let i = 0, j = 0, n = 2 * p.count; j < 2 * n; i += 3, j += 2) {
      const x = pts[i], y = pts[i + 1], z = pts[i + 2];
      out[j] = a * x + d * y + g * z + tx;
      out[j + 1] = b * x + e * y + h * z + ty;
    }
  }
  // The map from object o's stored pts to the world at step k, time t, or
  // null while it is where the workcell placed it. The event in force is
  // the last one of a step up to k that had happened by t (a take at its
  // step's end, a let-go at its step's start): so stepping to the
  // instruction before an opening move still shows the object held.
  function objectPose(o, k, t) {
    const g = o.grasps;
    let e = k < 0 ? -1 : lastUpTo(g.step, k);
    while (e >= 0 && g.at[e] > t) e--;
    if (e < 0) return null;
    return g.held[e] ? multiply(carrier.F[carrier.n], g.pose[e], o.W) : g.pose[e];
  }
  // Poses every robot for the motor counts `enc` and fills every part's
  // screen coordinates for the view matrix V; objects at step k, time t.
  const tmp = affine();
  function projectAll(V, enc, k, t) {
    for (const r of model.robots) {
      const e = r.program ? enc : r.zero;
      poseRobot(r, e);
      for (const p of r.parts) {
        multiply(V, r.F[p.frame], r.T);
        if (p.kind === 'finger2' || p.kind === 'finger3') {
          const g = r.gripper, phi = g.precision * (e[g.motor] || 0);
          aboutLine(p.kind === 'finger2' ? g.axis2 : g.axis3, phi, r.finger);
          projectPart(multiply(r.T, r.finger, tmp), p);
        } else {
          projectPart(r.T, p);
        }
      }
    }
    for (const o of model.objects) {
      const P = objectPose(o, k, t);
      projectPart(P ? multiply(V, P, o.T) : V, o);
    }
  }
  function apply(T, x, y, z) {
    return [T[0] * x + T[3] * y + T[6] * z + T[9], T[1] * x + T[4] * y + T[7] * z + T[10]];
  }

  // ---- The run: state at step k, time t (runtime/run_log.cpp's stateAtStep).
  function lastUpTo(list, k) {  // index of the last entry <= k in a sorted list, or -1
    let lo = 0, hi = list.length;
    while (lo < hi) { const mid = (lo + hi) >> 1; if (list[mid] <= k) lo = mid + 1; else hi = mid; }
    return lo - 1;
  }
  function stepAt(t) { return lastUpTo(run.start, t); }
  function positionAt(mv, i, speed, t) {
    const from = mv.from[i], to = mv.to[i];
    if (t <= mv.start[i]) return from;
    if (t >= mv.end[i]) return to;
    const covered = Math.floor((t - mv.start[i]) * speed / 1e6);
    return to > from ? from + covered : from - covered;
  }
  const current = { enc: new Int32Array(motorCount), outputs: 0, inputs: 0, view: [0, 0, 0], window: [0, 0, 0] };
  function stateAt(k, t, st) {
    for (let m = 0; m < motorCount; m++) {
      const mv = run.moves[m], i = k < 0 ? -1 : lastUpTo(mv.step, k);
      st.enc[m] = i < 0 ? 0 : positionAt(mv, i, run.motors[m].speed, t);
    }
    const o = k < 0 ? -1 : lastUpTo(run.outputs.step, k);
    st.outputs = o < 0 ? 0 : run.outputs.mask[o];
    const c = k < 0 ? -1 : lastUpTo(run.cameras.step, k);
    for (let a = 0; a < 3; a++) {
      st.view[a] = c < 0 ? 0 : run.cameras.view[3 * c + a];
      st.window[a] = c < 0 ? 0 : run.cameras.window[3 * c + a];
    }
    const l = lastUpTo(run.inputs.at, t);
    st.inputs = l < 0 ? 0 : run.inputs.mask[l];
    return st;
  }

  // ---- Page state.
  const S = { t: 0, k: stepAt(0), playing: false, speed: 1, axes: !!model.camera.axes, flush: false, hairline: 1,
              user: { rx: 0, ry: 0, zoom: 1 }, W: 1, H: 1 };
  const canvas = document.getElementById('cell');
  const ctx = canvas.getContext('2d', { alpha: false });
  const V = affine();
  function cameraFor(st, user) {
    const c = model.camera;
    return {
      view: [c.view[0] + st.view[0] + user.rx, c.view[1] + st.view[1] + user.ry, c.view[2] + st.view[2]],
      window: [c.window[0] + st.window[0], c.window[1] + st.window[1], c.window[2] + st.window[2]],
      zoom: c.zoom * user.zoom,
    };
  }

  // ---- Drawing.
  // The parts of a collision are red (EGA 4) from its moment to the end
  // of its move (run.collisions, docs/render.md).
  function markCollisions(t) {
    for (const p of allParts) p.hot = false;
    const c = model.run.collisions;
    if (!c) return;
    for (let i = 0; i < c.at.length; i++) {
      if (t < c.at[i] || t > c.end[i]) continue;
      for (const k of c.robotParts[i]) if (model.robots[0].parts[k]) model.robots[0].parts[k].hot = true;
      for (const k of c.objects[i]) if (model.objects[k]) model.objects[k].hot = true;
    }
  }
  function strokeParts() {
    for (let c = 0; c < 16; c++) {
      let any = false;
      ctx.beginPath();
      for (const p of allParts) {
        if (p.hot) {
          if (c !== 4) continue;
          const s = p.screen;
          for (let j = 0; j < 4 * p.count; j += 4) { ctx.moveTo(s[j], s[j + 1]); ctx.lineTo(s[j + 2], s[j + 3]); }
          any = true;
          continue;
        }
        const idx = p.byColor[c];
        if (!idx) continue;
        const s = p.screen;
        for (let n = 0; n < idx.length; n++) {
          const j = 4 * idx[n];
          ctx.moveTo(s[j], s[j + 1]);
          ctx.lineTo(s[j + 2], s[j + 3]);
        }
        any = true;
      }
      if (any) { ctx.strokeStyle = EGA[c]; ctx.stroke(); }
    }
  }
  function strokeAxesAndTools(V, axes) {
    const L = style.axisLength * model.fit.radius;
    for (const r of model.robots) {
      if (axes) {
        for (let k = 0; k < 3; k++) {
          ctx.beginPath();
          for (const F of r.F) {
            const o = apply(V, F[9], F[10], F[11]);
            const e = apply(V, F[9] + L * F[3 * k], F[10] + L * F[3 * k + 1], F[11] + L * F[3 * k + 2]);
            ctx.moveTo(o[0], o[1]); ctx.lineTo(e[0], e[1]);
          }
          ctx.strokeStyle = EGA[style.axisColors[k]]; ctx.stroke();
        }
      }
      if (r.tool) {
        const F = r.F[r.n], p = apply(V, F[9], F[10], F[11]), R = style.toolRadius;
        ctx.beginPath();
        ctx.arc(p[0], p[1], R, 0, 2 * Math.PI);
        ctx.moveTo(p[0] - 2 * R, p[1]); ctx.lineTo(p[0] + 2 * R, p[1]);
        ctx.moveTo(p[0], p[1] - 2 * R); ctx.lineTo(p[0], p[1] + 2 * R);
        ctx.lineWidth = style.toolLineWidth; ctx.strokeStyle = EGA[style.toolColor]; ctx.stroke();
        ctx.lineWidth = S.hairline;
      }
    }
  }
  function render() {
    stateAt(S.k, S.t, current);
    const cam = cameraFor(current, S.user);
    viewMatrix(cam.view, cam.window, cam.zoom, S.W, S.H, V);
    projectAll(V, current.enc, S.k, S.t);
    ctx.fillStyle = style.background;
    ctx.fillRect(0, 0, S.W, S.H);
    // One device pixel: Skia then draws hairlines, ten times faster than
    // stroking 5,000 wider lines (docs/render.md).
    ctx.lineWidth = S.hairline;
    ctx.lineCap = 'butt';
    markCollisions(S.t);
    strokeParts();
    strokeAxesAndTools(V, S.axes);
    ctx.fillStyle = EGA[7];
    ctx.font = '13px ui-monospace, "DejaVu Sans Mono", monospace';
    ctx.fillText(model.cell + '   t = ' + (S.t / 1e6).toFixed(3) + ' s', 10, 20);
  }

  // ---- Side panel and controls.
  const el = (id) => document.getElementById(id);
  el('title').textContent = model.title;
  const listing = el('listing'), items = [];
  model.program.lines.forEach((text, i) => {
    const li = document.createElement('li'), n = document.createElement('span');
    n.className = 'n'; n.textContent = String(i + 1);
    li.append(n, document.createTextNode(text.replace(/\t/g, '    ') || ' '));
    listing.append(li); items.push(li);
  });
  const motorCells = [];
  run.motors.forEach((m) => {
    const tr = document.createElement('tr');
    tr.innerHTML = '<td class="m"><b></b> <span></span></td><td class="v"></td><td class="r"><div class="bar"><i></i></div></td>';
    tr.querySelector('b').textContent = m.letter;
    tr.querySelector('span').textContent = m.kind;
    tr.title = m.letter + ': ' + m.kind + ', ' + m.min + '..' + m.max + ', ' + m.speed + ' units/s';
    el('motors').append(tr);
    motorCells.push({ value: tr.children[1], mark: tr.querySelector('i'), last: null, m });
  });
  const lamps = { inputs: [], outputs: [] };
  for (const side of ['inputs', 'outputs']) {
    for (let i = 1; i <= 8; i++) {
      const d = document.createElement('div');
      d.className = 'lamp'; d.textContent = String(i); d.title = side.slice(0, -1) + ' ' + i;
      el(side).append(d); lamps[side].push(d);
    }
  }
  const timeline = el('timeline'), timeText = el('time'), status = el('status'), playButton = el('play');
  timeline.max = String(Math.max(run.end, 1));
  let shownLine = -1, shownIn = -1, shownOut = -1;
  function currentLine() {
    return S.k >= 0 && S.k < steps ? model.program.lineOf[run.index[S.k]] || 0 : 0;
  }
  function updatePanel() {
    timeText.textContent = (S.t / 1e6).toFixed(3) + ' / ' + (run.end / 1e6).toFixed(3) + ' s';
    if (!scrubbing) timeline.value = String(S.t);
    const line = currentLine();
    if (line !== shownLine) {
      if (shownLine > 0 && items[shownLine - 1]) items[shownLine - 1].classList.remove('current');
      if (line > 0 && items[line - 1]) {
        items[line - 1].classList.add('current');
        const li = items[line - 1], top = li.offsetTop - listing.offsetTop;
        if (top < listing.scrollTop || top + li.offsetHeight > listing.scrollTop + listing.clientHeight)
          listing.scrollTop = top - listing.clientHeight / 3;
      }
      shownLine = line;
    }
    motorCells.forEach((c, m) => {
      const v = current.enc[m];
      if (v === c.last) return;
      c.last = v;
      c.value.textContent = String(v);
      const span = c.m.max - c.m.min;
      c.mark.style.left = (span > 0 ? (100 * (v - c.m.min)) / span : 50) + '%';
    });
    if (current.inputs !== shownIn) {
      lamps.inputs.forEach((d, i) => d.classList.toggle('on', !!(current.inputs & (1 << i))));
      shownIn = current.inputs;
    }
    if (current.outputs !== shownOut) {
      lamps.outputs.forEach((d, i) => d.classList.toggle('on', !!(current.outputs & (1 << i))));
      shownOut = current.outputs;
    }
    const where = S.k >= 0 ? 'instruction ' + (run.index[S.k] + 1) + ', line ' + line : 'not started';
    const end = S.t >= run.end && S.k >= steps - 1;
    status.textContent = where + (end ? (run.outcome ? '\nstopped: ' + run.outcome : '\nEND') : '');
    status.classList.toggle('failed', end && !!run.outcome);
    playButton.textContent = S.playing ? 'Pause' : 'Play';
  }

  // ---- Frame loop: draws on demand; while playing, the clock follows the
  // requestAnimationFrame timestamps times the speed.
  const stats = { interval: [], draw: [] };
  function record(list, v) { list.push(v); if (list.length > 2000) list.shift(); }
  let pending = false, lastStamp = null, stepClock = 0;
  function request() { if (!pending) { pending = true; requestAnimationFrame(frame); } }
  function frame(stamp) {
    pending = false;
    if (S.playing) {
      if (lastStamp !== null) {
        const dt = stamp - lastStamp;
        record(stats.interval, dt);
        if (run.end > 0) {
          S.t = Math.min(run.end, S.t + dt * 1000 * S.speed);
          S.k = stepAt(S.t);
          if (S.t >= run.end) { S.k = steps - 1; pause(); }
        } else {  // a run that takes no time: five instructions a second
          stepClock += dt * S.speed;
          while (stepClock >= 200 && S.k < steps - 1) { S.k++; stepClock -= 200; }
          if (S.k >= steps - 1) pause();
        }
      }
      lastStamp = stamp;
    }
    const t0 = performance.now();
    render();
    if (S.flush) ctx.getImageData(0, 0, 1, 1);  // benchmarks: include the rasterising
    record(stats.draw, performance.now() - t0);
    updatePanel();
    if (S.playing) request();
  }
  function play() {
    if (S.playing) return;
    if (S.t >= run.end && S.k >= steps - 1) { S.t = 0; S.k = run.end > 0 ? stepAt(0) : 0; }
    S.playing = true; lastStamp = null; stepClock = 0;
    request();
  }
  function pause() { S.playing = false; lastStamp = null; request(); }
  function setTime(t) {
    S.t = Math.max(0, Math.min(run.end, Number(t)));
    S.k = stepAt(S.t);
    request();
  }
  function stepBy(d) {
    if (!steps) return;
    pause();
    S.k = Math.max(0, Math.min(steps - 1, S.k + d));
    S.t = run.stop[S.k];
    request();
  }

  playButton.addEventListener('click', () => (S.playing ? pause() : play()));
  el('prev').addEventListener('click', () => stepBy(-1));
  el('next').addEventListener('click', () => stepBy(1));
  el('speed').addEventListener('change', (e) => { S.speed = Number(e.target.value) || 1; });
  const axesBox = el('axes');
  axesBox.checked = S.axes;
  axesBox.addEventListener('change', () => { S.axes = axesBox.checked; request(); });
  el('resetView').addEventListener('click', () => { S.user = { rx: 0, ry: 0, zoom: 1 }; request(); });
  let scrubbing = false;
  timeline.addEventListener('input', () => { scrubbing = true; setTime(Number(timeline.value)); });
  timeline.addEventListener('change', () => { scrubbing = false; });
  let drag = null;
  canvas.addEventListener('pointerdown', (e) => {
    drag = { x: e.clientX, y: e.clientY };
    canvas.setPointerCapture(e.pointerId);
    canvas.classList.add('dragging');
  });
  canvas.addEventListener('pointermove', (e) => {
    if (!drag) return;
    S.user.ry += 0.5 * (e.clientX - drag.x);
    S.user.rx += 0.5 * (e.clientY - drag.y);
    drag = { x: e.clientX, y: e.clientY };
    request();
  });
  const endDrag = () => { drag = null; canvas.classList.remove('dragging'); };
  canvas.addEventListener('pointerup', endDrag);
  canvas.addEventListener('pointercancel', endDrag);
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    S.user.zoom = Math.max(0.05, Math.min(50, S.user.zoom * Math.exp(-0.0015 * e.deltaY)));
    request();
  }, { passive: false });
  canvas.addEventListener('dblclick', () => { S.user = { rx: 0, ry: 0, zoom: 1 }; request(); });
  document.addEventListener('keydown', (e) => {
    if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
    if (e.key === ' ') { e.preventDefault(); S.playing ? pause() : play(); }
    else if (e.key === 'ArrowLeft') stepBy(-1);
    else if (e.key === 'ArrowRight') stepBy(1);
    else if (e.key === 'Home') { pause(); setTime(0); }
  });
  function resize() {
    const box = canvas.parentElement.getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
    S.W = Math.max(1, box.width); S.H = Math.max(1, box.height);
    canvas.width = Math.round(S.W * dpr); canvas.height = Math.round(S.H * dpr);
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    S.hairline = 1 / dpr;
    request();
  }
  new ResizeObserver(resize).observe(canvas.parentElement);
  resize();

  // ---- For tests and benchmarks.
  function summary(list) {
    if (!list.length) return { count: 0 };
    const s = [...list].sort((a, b) => a - b), q = (f) => s[Math.min(s.length - 1, Math.floor(f * s.length))];
    return { count: s.length, mean: s.reduce((a, b) => a + b, 0) / s.length, p50: q(0.5), p95: q(0.95), max: s[s.length - 1] };
  }
  window.robotsim = {
    model,
    get state() {
      const st = stateAt(S.k, S.t, { enc: new Int32Array(motorCount), view: [0, 0, 0], window: [0, 0, 0] });
      return { t: S.t, step: S.k, index: S.k >= 0 ? run.index[S.k] : -1, line: currentLine(), playing: S.playing,
               encoders: Array.from(st.enc), outputs: st.outputs, inputs: st.inputs, view: st.view,
               window: st.window, user: { ...S.user }, speed: S.speed };
    },
    play, pause, setTime, stepBy,
    setSpeed(v) { S.speed = v; },
    // The still's projection at time t (µs): the starting camera plus the
    // program's VIEW/WINDOW, no mouse; lines in `robotsim render
    // --dump-lines` order, then the tool centre points.
    project(t, width, height) {
      const k = stepAt(t), st = stateAt(k, t, { enc: new Int32Array(motorCount), view: [0, 0, 0], window: [0, 0, 0] });
      const cam = cameraFor(st, { rx: 0, ry: 0, zoom: 1 });
      const M = viewMatrix(cam.view, cam.window, cam.zoom, width, height, affine());
      projectAll(M, st.enc, k, t);
      const lines = [], tools = [];
      for (const r of model.robots) {
        for (const p of r.parts) for (let j = 0; j < 4 * p.count; j += 4) lines.push(Array.from(p.screen.slice(j, j + 4)));
        if (r.tool) { const F = r.F[r.n]; tools.push(apply(M, F[9], F[10], F[11])); }
      }
      for (const o of model.objects) for (let j = 0; j < 4 * o.count; j += 4) lines.push(Array.from(o.screen.slice(j, j + 4)));
      request();
      return { encoders: Array.from(st.enc), lines, tools };
    },
    stats() { return { interval: summary(stats.interval), draw: summary(stats.draw) }; },
    // With flush on, each frame reads a pixel back, so that the draw time
    // includes the canvas's rasterising (otherwise done later, off the clock).
    set flush(on) { S.flush = !!on; },
    resetStats() { stats.interval.length = 0; stats.draw.length = 0; },
  };
})();
)JS";

}  // namespace rs::render::page
