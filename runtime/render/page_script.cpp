// The animation page's script (see page.h). It replays the run embedded in
// the page as JSON (animation.cpp) and recomputes every frame from it:
//
//   time t  -> the step in progress (binary search on the steps' starts)
//           -> each motor's encoder count (its last segment through
//              runtime/sim/motion.h's profile, rounded as positionAt rounds)
//           -> the shared drawing code (page_draw_script.cpp): forward
//              kinematics, the camera, one stroke per EGA colour.
//
// Objects: an object's lines are stored in world coordinates at its
// placement. The run's grasp events (run.grasps) move it: after a take,
// its lines go through the program robot's last frame F_world_E(t) times
// the recorded F_E_object (composed with the placement's inverse); after a
// let-go, through the recorded resting pose; before its first event it is
// where the workcell placed it. A cell's devices (run.motions) move parts
// too: a record puts a part somewhere at its time and says how a belt
// carries it from there (velocity, travel); the later of an object's grasp
// and its motion is in force (at one step and time: a let-go, then the
// motion it starts, then a take). A part a sink took, or a feeder's empty
// slot, is not drawn; a sensor is drawn while its edges (run.sensors) say ON.
// In a cell of several robots (run.others) every other robot moves by time
// as its own log says, and its takes and let-gos move objects too: the
// latest grasp of any robot by then is in force.
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
  const canvas = document.getElementById('cell');
  const D = robotsimDrawing(model, canvas);  // page_draw_script.cpp
  const { affine, multiply } = D;

  // Each object's grasp events (in step order), and its two matrices.
  const carrier = D.carrier;
  for (const o of model.objects) o.grasps = { step: [], at: [], held: [], pose: [] };
  if (carrier) {
    const g = run.grasps;
    g.object.forEach((obj, e) => {
      const list = model.objects[obj].grasps;
      list.step.push(g.step[e]); list.at.push(g.at[e]); list.held.push(g.held[e]);
      list.pose.push(Float64Array.from(g.pose.slice(12 * e, 12 * e + 12)));
    });
  }

  // The cell's other robots (run.others): their motors by time, and each
  // object's takes and let-gos by them, in time order.
  const others = (run.others || []).map((x) => ({ x, robot: model.robots[x.robot], enc: new Int32Array(x.motors.length) }));
  for (const o of model.objects) o.others = { at: [], held: [], pose: [], by: [] };
  const byTime = [];
  others.forEach((r) => r.x.grasps.object.forEach((obj, e) => byTime.push([r.x.grasps.at[e], byTime.length, r, obj, e])));
  byTime.sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  for (const [at, , r, obj, e] of byTime) {
    const list = model.objects[obj].others, g = r.x.grasps;
    list.at.push(at); list.held.push(g.held[e]); list.by.push(r.robot);
    list.pose.push(Float64Array.from(g.pose.slice(12 * e, 12 * e + 12)));
  }
  function poseOthers(t) {
    for (const r of others) {
      for (let m = 0; m < r.enc.length; m++) {
        const mv = r.x.moves[m], i = lastUpTo(mv.start, t);
        r.enc[m] = i < 0 ? 0 : positionAt(mv, i, r.x.motors[m], t);
      }
      r.robot.enc = r.enc;
    }
  }

  // Each object's motions on the cell's belts (run.motions), and each
  // sensor's edges (run.sensors).
  for (const o of model.objects) o.motions = { step: [], at: [], pose: [], vel: [], travel: [], present: [] };
  if (run.motions) {
    const m = run.motions;
    m.object.forEach((obj, e) => {
      const list = model.objects[obj].motions;
      list.step.push(m.step[e]); list.at.push(m.at[e]); list.present.push(m.present[e]);
      list.pose.push(Float64Array.from(m.pose.slice(12 * e, 12 * e + 12)));
      list.vel.push(m.velocity.slice(3 * e, 3 * e + 3)); list.travel.push(m.travel[e]);
    });
  }
  const sensorEdges = (model.sensors || []).map(() => ({ at: [], on: [] }));
  if (run.sensors) run.sensors.sensor.forEach((s, e) => {
    if (sensorEdges[s]) { sensorEdges[s].at.push(run.sensors.at[e]); sensorEdges[s].on.push(run.sensors.on[e]); }
  });
  function showSensors(t) {
    sensorEdges.forEach((edges, s) => { const e = lastUpTo(edges.at, t); D.setSensor(s, e >= 0 && edges.on[e]); });
  }
  // Where motion record f puts object o at time t: its pose moved along
  // its velocity for as far as it travels.
  function motionPose(o, f, t) {
    const m = o.motions;
    if (!m.present[f]) return D.GONE;
    const v = m.vel[f], speed = Math.hypot(v[0], v[1], v[2]), P = m.pose[f];
    if (!(speed > 0) || t <= m.at[f]) return P;
    const travel = m.travel[f] < 0 ? Infinity : m.travel[f];
    const d = Math.min(speed * (t - m.at[f]) / 1e6, travel) / speed;
    const out = o.M || (o.M = affine());
    out.set(P);
    out[9] += v[0] * d; out[10] += v[1] * d; out[11] += v[2] * d;
    return out;
  }
  // The map from object o's stored pts to the world at step k, time t, or
  // null while it is where the workcell placed it. The event in force is
  // the last one of a step up to k that had happened by t (a take at its
  // step's end, a let-go at its step's start): so stepping to the
  // instruction before an opening move still shows the object held.
  function objectPose(o, k, t) {
    const g = o.grasps, m = o.motions;
    let e = k < 0 ? -1 : lastUpTo(g.step, k);
    while (e >= 0 && g.at[e] > t) e--;
    let f = k < 0 ? -1 : lastUpTo(m.step, k);
    while (f >= 0 && m.at[f] > t) f--;
    const moving = f >= 0 && (e < 0 || m.step[f] > g.step[e] ||
                   (m.step[f] === g.step[e] && (g.held[e] ? m.at[f] > g.at[e] : m.at[f] >= g.at[e])));
    const x = o.others, h = lastUpTo(x.at, t);  // another robot's grasp, later than this run's
    if (h >= 0 && x.at[h] > (moving ? m.at[f] : e >= 0 ? g.at[e] : -1)) {
      const by = x.by[h];
      return x.held[h] ? multiply(by.F[by.n], x.pose[h], o.W) : x.pose[h];
    }
    if (moving) return motionPose(o, f, t);
    if (e < 0) return null;
    return g.held[e] ? multiply(carrier.F[carrier.n], g.pose[e], o.W) : g.pose[e];
  }
  // ---- The run: state at step k, time t (runtime/run_log.cpp's stateAtStep).
  function lastUpTo(list, k) {  // index of the last entry <= k in a sorted list, or -1
    let lo = 0, hi = list.length;
    while (lo < hi) { const mid = (lo + hi) >> 1; if (list[mid] <= k) lo = mid + 1; else hi = mid; }
    return lo - 1;
  }
  function stepAt(t) { return lastUpTo(run.start, t); }
  // runtime/sim/motion.h's profiles, exactly: constant speed in doubles (every
  // product stays below 2^53), the rest in BigInt.
  function phasesOf(v, a, d) {  // BigInts; [ta, tc] in whole microseconds
    const M = 1000000n;
    if (d * a >= v * v) return [(v * M + a - 1n) / a, ((d * a - v * v) * M + v * a - 1n) / (v * a)];
    const need = d * M * M;
    let th = BigInt(Math.ceil(Math.sqrt(Number(need) / Number(a))));
    while (a * th * th < need) th++;
    while (th > 0n && a * (th - 1n) * (th - 1n) >= need) th--;
    return [th, 0n];
  }
  function coveredAt(motor, d, elapsed) {
    if (motor.actuation) return Number(BigInt(elapsed) * BigInt(d) / BigInt(motor.actuation));
    if (!motor.acceleration) return Math.floor(elapsed * motor.speed / 1e6);
    const [ta, tc] = phasesOf(BigInt(motor.speed), BigInt(motor.acceleration), BigInt(d));
    const t = BigInt(elapsed), total = 2n * ta + tc, whole = 2n * ta * (ta + tc);
    const u = t <= ta ? t * t : t <= ta + tc ? 2n * ta * t - ta * ta : whole - (total - t) * (total - t);
    return Number(BigInt(d) * u / whole);
  }
  function positionAt(mv, i, motor, t) {
    const from = mv.from[i], to = mv.to[i];
    if (t <= mv.start[i]) return from;
    if (t >= mv.end[i]) return to;
    const lock = mv.lock ? mv.lock[i] : 0;  // 1 lock-step, 2 lock-step leading (motion.h)
    // The machine's clock is whole microseconds; the page's time between them
    // (playback, a click on the chart) stands at the one before.
    const elapsed = Math.floor(t - mv.start[i]);
    const part = BigInt(Math.abs(to - from)) * BigInt(elapsed), span = BigInt(mv.end[i] - mv.start[i]);
    const covered = lock === 2 ? Number((part + span - 1n) / span)
        : lock === 1 ? Number(part / span)
        : coveredAt(motor, Math.abs(to - from), elapsed);
    return to > from ? from + covered : from - covered;
  }
  const current = { enc: new Int32Array(motorCount), outputs: 0, inputs: 0, view: [0, 0, 0], window: [0, 0, 0] };
  function stateAt(k, t, st) {
    for (let m = 0; m < motorCount; m++) {
      const mv = run.moves[m];
      let i = k < 0 ? -1 : lastUpTo(mv.step, k);
      // a step of several moves (a straight line's knots): the one under way at t
      while (i > 0 && mv.start[i] > t && mv.step[i - 1] === mv.step[i]) i--;
      st.enc[m] = i < 0 ? 0 : positionAt(mv, i, run.motors[m], t);
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
  const S = { t: 0, k: stepAt(0), playing: false, speed: 1, axes: !!model.camera.axes, path: true, flush: false };
  // The parts of a collision are red (EGA 4) from its moment to the end
  // of its move (run.collisions, docs/render.md); the shared drawing code
  // draws a part marked hot in red.
  function markCollisions(t) {
    for (const r of model.robots) for (const p of r.parts) p.hot = false;
    for (const o of model.objects) o.hot = false;
    const c = model.run.collisions;
    if (!c) return;
    for (let i = 0; i < c.at.length; i++) {
      if (t < c.at[i] || t > c.end[i]) continue;
      const driven = model.robots[model.run.driven];
      for (const k of c.robotParts[i]) if (driven && driven.parts[k]) driven.parts[k].hot = true;
      for (const k of c.objects[i]) if (model.objects[k]) model.objects[k].hot = true;
    }
  }
  // The tool centre point's path (model.path, tool_path.h): its points up
  // to the time shown, then where the tool is now; a new stretch at each
  // jump (RESET). Drawn under the tool mark while the "path" box is ticked.
  const path = model.path || null;
  if (path) {
    path.xyz = Float64Array.from(path.pts);
    path.starts = new Uint8Array(path.at.length);
    for (const i of path.jump) path.starts[i] = 1;
  }
  // The path up to time t through V, the robots posed for t: moveTo(u, v)
  // starts a stretch, lineTo(u, v) goes on (render's pathUntil, projected).
  function tracePath(V, t, moveTo, lineTo) {
    const n = lastUpTo(path.at, t) + 1, xyz = path.xyz;
    for (let i = 0; i < n; i++) {
      const p = D.apply(V, xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
      if (i === 0 || path.starts[i]) moveTo(p[0], p[1]); else lineTo(p[0], p[1]);
    }
    const F = carrier.F[carrier.n];
    const last = 3 * (n - 1), dx = F[9] - xyz[last], dy = F[10] - xyz[last + 1], dz = F[11] - xyz[last + 2];
    const now = D.apply(V, F[9], F[10], F[11]);
    if (n === 0) moveTo(now[0], now[1]);
    else if (dx * dx + dy * dy + dz * dz > 1e-18) lineTo(now[0], now[1]);
  }
  function strokePath(V, ctx) {
    if (!S.path || !path || !carrier || !path.at.length) return;
    ctx.beginPath();
    tracePath(V, S.t, (u, v) => ctx.moveTo(u, v), (u, v) => ctx.lineTo(u, v));
    ctx.lineWidth = model.style.pathLineWidth;
    ctx.lineJoin = 'round';
    ctx.strokeStyle = model.style.palette[model.style.pathColor];
    ctx.stroke();
    ctx.lineJoin = 'miter';
    ctx.lineWidth = D.view.hairline;
  }
  function render() {
    stateAt(S.k, S.t, current);
    poseOthers(S.t);
    markCollisions(S.t);
    showSensors(S.t);
    D.draw(current, current.enc, (o) => objectPose(o, S.k, S.t), S.axes,
           model.cell + '   t = ' + (S.t / 1e6).toFixed(3) + ' s', strokePath);
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
    tr.title = m.letter + ': ' + m.kind + ', ' + m.min + '..' + m.max + ', ' + m.speed + ' units/s' + (m.acceleration ? ', ' + m.acceleration + ' units/s²' : '') + (m.actuation ? ', ' + m.actuation / 1e6 + ' s a move' : '');
    el('motors').append(tr);
    motorCells.push({ value: tr.children[1], mark: tr.querySelector('i'), last: null, m });
  });
  const lamps = { inputs: [], outputs: [] };
  for (const side of ['inputs', 'outputs']) {
    for (let i = 1; i <= run.lines; i++) {
      const d = document.createElement('div');
      d.className = 'lamp'; d.textContent = String(i); d.title = side.slice(0, -1) + ' ' + i;
      el(side).append(d); lamps[side].push(d);
    }
  }
  // What set each input last (run.inputCauses, in change order): a lamp's
  // title says it, in the debugger's words ("input 1 ON since 1.100 s:
  // wire from sensor eye").
  const causes = run.inputCauses, causeAt = [], causeOf = [], shownCause = [];
  for (let i = 0; i < run.lines; i++) causeAt.push([]), causeOf.push([]), shownCause.push(-1);
  if (causes) causes.input.forEach((n, c) => { causeAt[n - 1].push(causes.at[c]); causeOf[n - 1].push(c); });
  function showCauses(t) {
    lamps.inputs.forEach((d, i) => {
      const j = lastUpTo(causeAt[i], t), c = j < 0 ? -1 : causeOf[i][j];
      if (c === shownCause[i]) return;
      shownCause[i] = c;
      d.title = 'input ' + (i + 1) + (c < 0 ? '' : ' ' + (causes.on[c] ? 'ON' : 'OFF') + ' ' + causes.since[c]);
    });
  }
  const timeline = el('timeline'), timeText = el('time'), status = el('status'), playButton = el('play');
  timeline.max = String(Math.max(run.end, 1));
  let shownLine = -1, shownIn = -1, shownOut = -1;
  // A long run comes cut down to frames (frames.h): say so under the status.
  const framesNote = run.frames ? '\n' + run.frames.steps + ' instructions shown as ' + steps +
      ' frames: every event, and the first to start in each ' + (run.frames.slot / 1e6).toFixed(3) + ' s' : '';
  function currentLine() {
    return S.k >= 0 && S.k < steps ? model.program.lineOf[run.index[S.k]] || 0 : 0;
  }
  // The run's chart under the scrub bar (chart_draw.h, the picture `robotsim
  // plot` draws): the cursor stands at the time shown, a click seeks to the
  // time under it. model.chart: its SVG, its size in pixels, the x of time 0
  // ("left") and of the run's end ("right").
  const chart = model.chart, chartImg = el('chart'), chartCursor = el('chartCursor');
  function chartX(t) { return chart.left + (chart.right - chart.left) * (chart.end > 0 ? t / chart.end : 0); }
  function chartTimeAt(x) {
    return chart.end > 0 ? Math.round(((x - chart.left) / (chart.right - chart.left)) * chart.end) : 0;
  }
  function placeChartCursor() {
    if (chart) chartCursor.style.left = (chartX(S.t) * chartImg.clientWidth) / chart.width + 'px';
  }
  if (chart) {
    chartImg.src = 'data:image/svg+xml;charset=utf-8,' + encodeURIComponent(chart.svg);
    chartImg.addEventListener('load', placeChartCursor);
    chartImg.addEventListener('click', (e) => {
      const r = chartImg.getBoundingClientRect();
      pause();
      setTime(chartTimeAt(((e.clientX - r.left) * chart.width) / r.width));
    });
    window.addEventListener('resize', placeChartCursor);
  } else {
    el('chartPane').style.display = 'none';
  }
  function updatePanel() {
    placeChartCursor();
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
    if (causes) showCauses(S.t);
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
    status.textContent = where + (end ? (run.outcome ? '\nstopped: ' + run.outcome : '\nEND') +
                                        (run.warning ? '\nwarning: ' + run.warning : '') : '') + framesNote;
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
    if (S.flush) D.ctx.getImageData(0, 0, 1, 1);  // benchmarks: include the rasterising
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
  const pathBox = el('path');
  pathBox.checked = S.path;
  pathBox.addEventListener('change', () => { S.path = pathBox.checked; request(); });
  el('resetView').addEventListener('click', () => { D.resetView(); request(); });
  let scrubbing = false;
  timeline.addEventListener('input', () => { scrubbing = true; setTime(Number(timeline.value)); });
  timeline.addEventListener('change', () => { scrubbing = false; });
  D.attachCamera(request);
  document.addEventListener('keydown', (e) => {
    if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
    if (e.key === ' ') { e.preventDefault(); S.playing ? pause() : play(); }
    else if (e.key === 'ArrowLeft') stepBy(-1);
    else if (e.key === 'ArrowRight') stepBy(1);
    else if (e.key === 'Home') { pause(); setTime(0); }
  });

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
               window: st.window, user: { ...D.view.user }, speed: S.speed, path: S.path };
    },
    play, pause, setTime, stepBy,
    setSpeed(v) { S.speed = v; },
    // The still's projection at time t (µs): the starting camera plus the
    // program's VIEW/WINDOW, no mouse; lines in `robotsim render
    // --dump-lines` order, then the tool centre points.
    project(t, width, height) {
      const k = stepAt(t), st = stateAt(k, t, { enc: new Int32Array(motorCount), view: [0, 0, 0], window: [0, 0, 0] });
      showSensors(t);
      poseOthers(t);
      const still = D.projectStill(st, st.enc, (o) => objectPose(o, k, t), width, height);
      request();
      return { encoders: Array.from(st.enc), lines: still.lines, tools: still.tools };
    },
    // The tool's path at time t (µs) as `robotsim render --at --path
    // --dump-lines=json` gives it: a list of [u, v] vertices per stretch.
    projectPath(t, width, height) {
      if (!path || !carrier || !path.at.length) return [];
      const k = stepAt(t), st = stateAt(k, t, { enc: new Int32Array(motorCount), view: [0, 0, 0], window: [0, 0, 0] });
      const cam = D.cameraFor(st, { rx: 0, ry: 0, zoom: 1 });
      const M = D.viewMatrix(cam.view, cam.window, cam.zoom, width, height, affine());
      D.projectAll(M, st.enc, (o) => objectPose(o, k, t));
      const out = [];
      tracePath(M, t, (u, v) => out.push([[u, v]]), (u, v) => out[out.length - 1].push([u, v]));
      request();
      return out;
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
