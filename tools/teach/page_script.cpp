// The teach page's script (see page.h). The cell is drawn by the drawing
// code every page shares (robotsimDrawing, runtime/render/page_draw_script.cpp);
// the state comes from the server (server-sent events at each new
// revision, /api/state once at the start); every button and key posts one
// command ({"op": ...}, tools/teach/commands.h) and waits for the state to come
// back. A move's motion frames (PendantState::motion) are played in real
// time before the state's final pose is shown. The keys come from the
// model (tools/teach/keys.h), the same table the terminal pendant reads. In
// read-only mode (the model's readOnly: the debugger's view) the state is
// a stopped run's (tools/teach/run_source.h) and every command is refused.
// window.robotsim exposes the state and the selection to tests.
#include "tools/teach/page.h"

namespace rs::teach::page {

const std::string_view kScript = R"JS('use strict';
(function () {
  const model = JSON.parse(document.getElementById('robotsim-model').textContent);
  const token = new URLSearchParams(location.search).get('token') || '';
  const canvas = document.getElementById('cell');
  const D = robotsimDrawing(model, canvas);  // the drawing code the animation page shares
  const el = (id) => document.getElementById(id);
  const still = { view: [0, 0, 0], window: [0, 0, 0] };
  const S = { state: null, selectedMotor: 0, selectedPoint: null, step: 10, axes: !!model.camera.axes,
              mode: 'joint', selectedAxis: 0, axisNames: '',
              anim: null, shown: null, pending: 0, confirm: null, choices: null };
  el('title').textContent = model.title;
  // Read-only (the debugger's view of a stopped run): the pendant's
  // controls are hidden; a key that would move the robot is still sent
  // and the server's refusal shown.
  if (model.readOnly) document.body.classList.add('readonly');
  el('file').textContent = model.program;

  // ---- Drawing: the shown pose (a motion frame while a move plays).
  const poses = new Map();
  function objectPose(o) {
    const shown = S.shown;
    if (!shown || !shown.objects) return null;
    const m = shown.objects[model.objects.indexOf(o)];
    if (!m) return null;
    if (m === 'gone') return D.GONE;  // a part a sink took, a feeder's empty slot
    let P = poses.get(o);
    if (!P) { P = new Float64Array(12); poses.set(o, P); }
    for (let i = 0; i < 12; i++) P[i] = m[i];
    return P;
  }
  let pending = false;
  function request() { if (!pending) { pending = true; requestAnimationFrame(frame); } }
  function frame(stamp) {
    pending = false;
    if (S.anim) {
      if (S.anim.start === null) S.anim.start = stamp;
      const t = (stamp - S.anim.start) * 1000, frames = S.anim.frames;
      let i = S.anim.i;
      while (i + 1 < frames.length && frames[i + 1].at <= t) i++;
      S.anim.i = i;
      S.shown = { encoders: frames[i].encoders, objects: frames[i].objects };
      if (i + 1 >= frames.length) { S.anim = null; S.shown = shownOf(S.state); }
      else request();
    }
    if (!S.shown) return;
    D.draw(still, S.shown.encoders, objectPose, S.axes, model.cell + (S.anim ? '   moving' : ''));
  }
  function shownOf(st) {
    return { encoders: st.encoders, objects: st.objects.map((o) => (o.present === false ? 'gone' : o.pose)) };
  }

  // ---- The panel, built once from the first state.
  const motorRows = [];
  function buildMotors(st) {
    st.motors.forEach((m, i) => {
      const tr = document.createElement('tr');
      tr.innerHTML = '<td class="m"><b></b> <span></span></td><td class="v"></td>' +
        '<td class="jog"><button class="minus" aria-label="minus">&minus;</button><button class="plus" aria-label="plus">+</button></td>' +
        '<td class="range"></td><td class="r"><input type="range"></td>';
      tr.dataset.motor = String(i);
      tr.querySelector('b').textContent = m.letter;
      tr.querySelector('span').textContent = m.kind;
      tr.querySelector('.range').textContent = m.min + '..' + m.max;
      const slider = tr.querySelector('input');
      slider.min = String(m.min); slider.max = String(m.max); slider.step = '1';
      slider.setAttribute('aria-label', 'motor ' + m.letter);
      tr.title = m.letter + ': ' + m.kind + ', ' + m.min + '..' + m.max + ', ' + m.speed + ' counts/s';
      tr.querySelector('.minus').addEventListener('click', () => { selectMotor(i); send({ op: 'jog', motor: i, delta: -S.step }); });
      tr.querySelector('.plus').addEventListener('click', () => { selectMotor(i); send({ op: 'jog', motor: i, delta: S.step }); });
      slider.addEventListener('change', () => { selectMotor(i); send({ op: 'set', motor: i, value: Number(slider.value) }); });
      tr.addEventListener('click', () => selectMotor(i));
      el('motors').append(tr);
      motorRows.push({ tr, value: tr.children[1], slider });
    });
    for (const side of ['inputs', 'outputs']) {
      for (let i = 1; i <= st[side].length; i++) {  // the state lists every line
        const d = document.createElement('div');
        d.className = 'lamp'; d.textContent = String(i); d.title = side.slice(0, -1) + ' ' + i;
        d.dataset.line = String(i);
        d.addEventListener('click', () => send(side === 'inputs' ? { op: 'input', line: i }
                                                                  : { op: 'output', line: i, on: !S.state.outputs[i - 1] }));
        el(side).append(d);
      }
    }
    el('read').disabled = !st.device;
    el('keys').textContent = model.keys.map((k) => k.key.padEnd(11) + k.help).join('\n');
    selectMotor(0);
  }
  function selectMotor(i) {
    if (!S.state) return;
    S.selectedMotor = Math.max(0, Math.min(S.state.motors.length - 1, i));
    motorRows.forEach((r, k) => r.tr.classList.toggle('selected', k === S.selectedMotor));
  }
  // ---- Jog modes: joint (the motors' rows), world and tool (the axes the
  // state lists for each, through the inverse kinematics on the server).
  function jogAxes() { return S.state ? S.state.jogAxes[S.mode] || [] : []; }
  function buildAxes() {
    const axes = jogAxes(), names = S.mode + ':' + axes.map((a) => a.name + '/' + a.help).join(',');
    if (names === S.axisNames) return;
    S.axisNames = names;
    el('axes').textContent = '';
    axes.forEach((a, i) => {
      const tr = document.createElement('tr');
      tr.innerHTML = '<td class="m"><b></b></td><td class="help"></td>' +
        '<td class="jog"><button class="minus" aria-label="minus">&minus;</button><button class="plus" aria-label="plus">+</button></td>';
      tr.dataset.axis = a.name;
      tr.querySelector('b').textContent = a.name;
      tr.querySelector('.help').textContent = a.help;
      tr.querySelector('.minus').addEventListener('click', () => { selectAxis(i); jogAxis(-1); });
      tr.querySelector('.plus').addEventListener('click', () => { selectAxis(i); jogAxis(1); });
      tr.addEventListener('click', () => selectAxis(i));
      el('axes').append(tr);
    });
    selectAxis(S.selectedAxis);
  }
  function selectAxis(i) {
    const n = jogAxes().length;
    S.selectedAxis = Math.max(0, Math.min(n - 1, i));
    [...el('axes').children].forEach((tr, k) => tr.classList.toggle('selected', k === S.selectedAxis));
  }
  function jogAxis(sign) {
    const a = jogAxes()[S.selectedAxis];
    if (!a) return;
    const amount = sign * (a.rotation ? model.jogDegrees[String(S.step)] : S.step);
    return send({ op: 'jogCartesian', frame: S.mode, axis: a.name, amount });
  }
  function setMode(mode) {
    if (mode !== 'joint' && S.state && !S.state.jogAxes.world.length) {
      el('message').textContent = 'this robot has no kinematic chain: it jogs joint by joint only';
      mode = 'joint';
    }
    S.mode = mode;
    el('mode').value = mode;
    const cartesian = mode !== 'joint';
    document.body.classList.toggle('cartesian', cartesian);
    el('axesBox').classList.toggle('on', cartesian);
    el('axesTitle').textContent = mode === 'world' ? 'World axes (the cell\'s)' : 'Tool axes (the tool\'s own)';
    showStep();
    buildAxes();
  }
  function showStep() {
    el('stepUnit').textContent = S.mode === 'joint' ? 'counts'
      : 'length units, ' + model.jogDegrees[String(S.step)] + ' degrees';
  }
  function selectPoint(name) {
    S.selectedPoint = name;
    for (const li of el('points').children) li.classList.toggle('selected', li.dataset.name === name);
  }
  function updatePanel(st) {
    st.encoders.forEach((v, i) => {
      const r = motorRows[i];
      r.value.textContent = String(v);
      if (document.activeElement !== r.slider) r.slider.value = String(v);
    });
    el('gripper').textContent = st.gripper;
    el('tcp').textContent = st.tcp ? '(' + st.tcp.map((x) => x.toFixed(2)).join(', ') + ')' : 'no chain';
    el('approach').textContent = st.approach ? 'approach (' + st.approach.map((x) => x.toFixed(3)).join(', ') + ')' : '';
    buildAxes();
    [...el('inputs').children].forEach((d, i) => d.classList.toggle('on', st.inputs[i]));
    [...el('outputs').children].forEach((d, i) => d.classList.toggle('on', st.outputs[i]));
    // The cell's devices: a sensor drawn while ON, and listed with its belts and feeders.
    const dev = st.devices || { sensors: [], conveyors: [], feeders: [] };
    dev.sensors.forEach((x, i) => D.setSensor(i, x.on));
    el('devices').textContent = dev.sensors.map((x) => 'sensor ' + x.name + (x.on ? ' ON' : ' off') + ' (' + x.count + ')')
      .concat(dev.conveyors.map((x) => 'belt ' + x.name + (x.running ? ' runs' : ' stopped')))
      .concat((dev.feeders || []).map((x) => 'feeder ' + x.name + ' fed ' + x.fed))
      .join('  ·  ');
    const list = el('points');
    list.textContent = '';
    if (S.selectedPoint && !st.points.some((p) => p.name.toUpperCase() === S.selectedPoint.toUpperCase()))
      S.selectedPoint = null;
    for (const p of st.points) {
      const li = document.createElement('li'), v = document.createElement('span');
      li.dataset.name = p.name;
      v.className = 'v';
      v.textContent = '  ' + (p.pose ? '(a tool pose: AT ...)' : p.readable ? p.values.join(' ') : '(not whole numbers)') + '   line ' + p.line;
      li.append(document.createTextNode(p.name), v);
      li.addEventListener('click', () => selectPoint(p.name));
      list.append(li);
    }
    if (S.selectedPoint) selectPoint(st.points.find((p) => p.name.toUpperCase() === S.selectedPoint.toUpperCase()).name);
    if (st.readOnly)
      el('where').textContent = 'line ' + st.line + ' @' + st.instruction + ', step ' + st.steps + ', clock ' +
        (st.clock / 1e6).toFixed(3) + ' s' + (st.finished ? ' (the run is over)' : '');
    el('message').textContent = st.message;
    el('message').parentElement.classList.toggle('failed', st.failed);
    el('fault').textContent = st.fault ? 'DEVICE FAULT: every motor stopped. ' + st.fault : '';
    el('fault').classList.toggle('on', !!st.fault);
  }

  // ---- State from the server.
  function receive(st) {
    if (S.state && st.revision <= S.state.revision) return;
    const first = !S.state;
    S.state = st;
    if (first) buildMotors(st);
    updatePanel(st);
    if (!first && st.motion.length > 1) {
      S.anim = { frames: st.motion, i: 0, start: null };
    } else if (!S.anim) {
      S.shown = shownOf(st);
    }
    request();
  }
  async function send(command) {
    S.pending++;
    try {
      const res = await fetch('api/command?token=' + encodeURIComponent(token), {
        method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(command) });
      const reply = await res.json();
      if (!reply.ok) { el('message').textContent = reply.message; el('message').parentElement.classList.add('failed'); }
      const st = await (await fetch('api/state?token=' + encodeURIComponent(token))).json();
      receive(st);
      return reply;
    } finally {
      S.pending--;
    }
  }
  fetch('api/state?token=' + encodeURIComponent(token)).then((r) => r.json()).then(receive);
  const events = new EventSource('api/events?token=' + encodeURIComponent(token));
  events.onmessage = (e) => receive(JSON.parse(e.data));
  events.onerror = () => {
    // Refused (too many pages open) or the server gone: say so, once.
    if (events.readyState !== EventSource.CLOSED) return;
    el('message').textContent = 'live updates stopped (the server ended, or too many of its pages are open): reload the page';
    el('message').parentElement.classList.add('failed');
  };

  // ---- Points: teach, go to, re-teach and delete (after a yes), rename.
  // A question: yes or no; or, with `choices` (answers by button id), one of them or no.
  function ask(question, command, choices) {
    S.confirm = command;
    S.choices = choices || null;
    el('question').textContent = question;
    el('yes').style.display = choices ? 'none' : '';
    for (const id of ['asPose', 'asCounts']) el(id).style.display = choices && choices[id] ? '' : 'none';
    el('confirm').classList.add('on');
  }
  function answer(yes, choice) {
    const c = choice && S.choices ? S.choices[choice] : S.confirm;
    S.confirm = null;
    S.choices = null;
    el('confirm').classList.remove('on');
    if (yes && c) send(c);
  }
  el('yes').addEventListener('click', () => answer(true));
  el('no').addEventListener('click', () => answer(false));
  el('asPose').addEventListener('click', () => answer(true, 'asPose'));
  el('asCounts').addEventListener('click', () => answer(true, 'asCounts'));
  function reteach(name) {
    const p = (S.state ? S.state.points : []).find((q) => q.name === name);
    if (!p || !p.pose) { ask('Re-teach ' + name + ' with the current pose?', { op: 'reteach', name }); return; }
    ask('Re-teach ' + name + ', written as a tool pose: keep it a pose (AT ...), or write the counts?', null,
        { asPose: { op: 'reteach', name, as: 'pose' }, asCounts: { op: 'reteach', name, as: 'counts' } });
  }
  function teach() {
    const name = el('teachName').value.trim();
    if (!name) { el('teachName').focus(); return; }
    send({ op: 'teach', name }).then((r) => { if (r.ok) { el('teachName').value = ''; selectPoint(name); } });
  }
  const selected = (then) => () => {
    if (!S.selectedPoint) { el('message').textContent = 'select a point first'; return; }
    then(S.selectedPoint);
  };
  const actions = {
    prevMotor: () => (S.mode === 'joint' ? selectMotor(S.selectedMotor - 1) : selectAxis(S.selectedAxis - 1)),
    nextMotor: () => (S.mode === 'joint' ? selectMotor(S.selectedMotor + 1) : selectAxis(S.selectedAxis + 1)),
    jogMinus: () => (S.mode === 'joint' ? send({ op: 'jog', motor: S.selectedMotor, delta: -S.step }) : jogAxis(-1)),
    jogPlus: () => (S.mode === 'joint' ? send({ op: 'jog', motor: S.selectedMotor, delta: S.step }) : jogAxis(1)),
    step1: () => setStep(1), step10: () => setStep(10), step100: () => setStep(100),
    jogMode: () => setMode(S.mode === 'joint' ? 'world' : S.mode === 'world' ? 'tool' : 'joint'),
    openGripper: () => send({ op: 'gripper', close: false }),
    closeGripper: () => send({ op: 'gripper', close: true }),
    teach: () => (el('teachName').value.trim() ? teach() : el('teachName').focus()),
    goTo: selected((name) => send({ op: 'goTo', name })),
    reteach: selected(reteach),
    delete: selected((name) => ask('Delete point ' + name + '?', { op: 'delete', name })),
    rename: selected((name) => {
      const to = el('newName').value.trim();
      if (!to) { el('newName').focus(); return; }
      send({ op: 'rename', from: name, to }).then((r) => { if (r.ok) { el('newName').value = ''; selectPoint(to); } });
    }),
    prevPoint: () => movePointSelection(-1), nextPoint: () => movePointSelection(1),
    readPosition: () => send({ op: 'readPosition' }),
    resetCell: () => ask('Reset the cell (motors home, objects back)?', { op: 'reset' }),
    runCell: () => send({ op: 'runCell', seconds: 1 }),
    help: () => el('keys').classList.toggle('on'),
    quit: () => {},
  };
  function setStep(n) { S.step = n; el('step').value = String(n); showStep(); }
  function movePointSelection(d) {
    const pts = S.state ? S.state.points : [];
    if (!pts.length) return;
    const at = pts.findIndex((p) => p.name === S.selectedPoint);
    selectPoint(pts[Math.max(0, Math.min(pts.length - 1, at < 0 ? 0 : at + d))].name);
  }
  el('step').addEventListener('change', () => { S.step = Number(el('step').value) || 1; showStep(); });
  el('mode').addEventListener('change', () => setMode(el('mode').value));
  el('open').addEventListener('click', actions.openGripper);
  el('close').addEventListener('click', actions.closeGripper);
  el('teach').addEventListener('click', teach);
  el('teachName').addEventListener('keydown', (e) => { if (e.key === 'Enter') teach(); });
  el('goto').addEventListener('click', actions.goTo);
  el('reteach').addEventListener('click', actions.reteach);
  el('delete').addEventListener('click', actions.delete);
  el('rename').addEventListener('click', actions.rename);
  el('reset').addEventListener('click', actions.resetCell);
  el('runCell').addEventListener('click', actions.runCell);
  el('read').addEventListener('click', actions.readPosition);
  el('reload').addEventListener('click', () => send({ op: 'reload' }));
  const axesBox = el('axes');
  axesBox.checked = S.axes;
  axesBox.addEventListener('change', () => { S.axes = axesBox.checked; request(); });
  el('resetView').addEventListener('click', () => { D.resetView(); request(); });
  const keyMap = new Map(model.keys.map((k) => [k.key, k.action]));
  document.addEventListener('keydown', (e) => {
    if (e.target instanceof HTMLInputElement && e.target.type === 'text') return;
    if (e.target instanceof HTMLSelectElement || e.ctrlKey || e.metaKey || e.altKey) return;
    const action = keyMap.get(e.key);
    if (!action || !actions[action]) return;
    e.preventDefault();
    actions[action]();
  });
  D.attachCamera(request);

  window.robotsim = {
    model,
    get state() { return S.state; },
    get selection() {
      const a = jogAxes()[S.selectedAxis];
      return { motor: S.selectedMotor, point: S.selectedPoint, step: S.step, mode: S.mode, axis: a ? a.name : null };
    },
    get busy() { return S.pending > 0 || !!S.anim; },
    get shown() { return S.shown; },
    // The still's projection of the shown pose (no mouse): lines in
    // `robotsim render --dump-lines` order, then the tool centre points.
    project(width, height) {
      const r = D.projectStill(still, S.shown.encoders, objectPose, width, height);
      request();
      return r;
    },
    send,
  };
})();
)JS";

}  // namespace rs::teach::page
