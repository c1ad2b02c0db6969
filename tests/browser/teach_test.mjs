// The teach pendant's page in a real browser: `robotsim teach` serves it on
// 127.0.0.1, Debian's chromium (headless, driven by playwright-core) uses it
// as a student would. Starts everything it needs and stops within
// --timeout seconds.
//
//   node tests/browser/teach_test.mjs --robotsim BUILD/robotsim [--out DIR]
//        [--images DIR] [--chromium /usr/bin/chromium] [--timeout 120]
//
// Checks: the page loads and draws without fetching anything but its own
// server; two motors jogged with the buttons and the keys; a slider; two
// points taught, one re-taught after a confirmation; going to a point
// animates the move and ends on the point; an input toggled; the jog
// modes (world and tool jogs by key and button, a refusal); the program
// file written equals tests/browser/golden/teach_pick_and_place.rsp byte
// for byte (worked out by hand: see the comment at `golden` below) and its
// .bak the program as it was; a write refused after the file changed on
// disk, the file left as the other editor wrote it; Ctrl-C stops the
// server; --open hands xdg-open a private file (never the token) that
// brings the browser to the page, and removes it at the end. Saves
// DIR/teach.png (and, with --images, docs screenshots).
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { check, checkCount, chromiumAt, fail, launch, source, started, testOptions, watchdog } from './harness.mjs';

const here = path.join(source, 'tests/browser');
const opt = testOptions('teach_test.mjs --robotsim PATH [--out DIR] [--images DIR] [--chromium PATH] [--timeout S]',
                        { images: { type: 'string' } });
const chromium = await chromiumAt(opt.chromium);

const out = opt.out ? path.resolve(opt.out) : fs.mkdtempSync(path.join(os.tmpdir(), 'robotsim-teach-'));
fs.mkdirSync(out, { recursive: true });
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'robotsim-teach-work-'));
const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'robotsim-chromium-'));
let context = null, server = null;
function cleanUp() {
  for (const p of [server, emulator?.proc, deviceTeach?.proc]) if (p && p.exitCode === null) p.kill('SIGKILL');
  fs.rmSync(profile, { recursive: true, force: true });
  fs.rmSync(work, { recursive: true, force: true });
}
const deadline = watchdog(opt.timeout, () => context, cleanUp);

// The program: examples/pick_and_place.rsp, whose POINTS rows are
// right-aligned at columns 17, 23, 26, 32 and 37.
const original = fs.readFileSync(path.join(source, 'examples/pick_and_place.rsp'), 'utf8');
const program = path.join(work, 'pick_and_place.rsp');
fs.writeFileSync(program, original);
// The golden file is the program with two rows after ABOVE_PRESS, laid
// out by hand by the rule of tools/teach/points_edit.h: FIRST (400 -29 120 100
// 0, re-taught) and SECOND (400 -29 120 0 0); "120" is one wider than its
// column (it ends at 27), so one space precedes it and the next column
// catches up at 32.
const golden = fs.readFileSync(path.join(here, 'golden/teach_pick_and_place.rsp'), 'utf8');

const teachUrl = /http:\/\/127\.0\.0\.1:\d+\/\?token=[0-9a-f]{32}/;

// ---- robotsim teach, its URL from its first lines
const teach = started(opt.robotsim, ['teach', program, '--cell', 'scara-pick']);
server = teach.proc;
const url = (await teach.match(teachUrl).catch((e) => { cleanUp(); fail(e.message); }))[0];
const origin = new URL(url).origin;
let emulator = null, deviceTeach = null;

try {
  context = await launch(chromium, opt.chromium, profile, { width: 1280, height: 860 });
  const page = context.pages()[0] ?? await context.newPage();
  const requests = [], errors = [];
  page.on('request', (r) => requests.push(r.url()));
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  await page.goto(url);
  await page.waitForFunction(() => window.robotsim && window.robotsim.state, null, { timeout: 10000 });
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  check(errors.length === 0, 'the page runs without errors', errors.join('; '));
  const drawn = await page.evaluate(() => {
    const c = document.getElementById('cell'), d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] !== 0x10 || d[i + 1] !== 0x12 || d[i + 2] !== 0x1c) n++;
    return n;
  });
  check(drawn > 2000, 'the workcell is drawn', `${drawn} pixels`);
  const state = () => page.evaluate(() => window.robotsim.state);
  const settled = () => page.waitForFunction(() => !window.robotsim.busy, null, { timeout: 10000 });
  const encodersAre = async (want) => {
    await page.waitForFunction((w) => JSON.stringify(window.robotsim.state.encoders) === JSON.stringify(w), want,
                               { timeout: 10000 });
    await settled();
  };
  const motorsRow = (i) => page.locator(`#motors tr[data-motor="${i}"]`);
  const labels = await page.locator('#motors td.m b').allTextContents();
  check(labels.join('') === 'EDCBA', 'every motor with its letter', labels.join(' '));
  check((await page.locator('#motors td.range').first().textContent()) === '-1000..1000', '  and its range');

  // ---- jog two motors: E +100 four times with the buttons, D -10 three
  // times, then one count with the keys (select D, step 1, arrow right).
  await page.selectOption('#step', '100');
  for (let k = 0; k < 4; k++) { await motorsRow(0).locator('button.plus').click(); await settled(); }
  await encodersAre([400, 0, 0, 0, 0]);
  check(true, 'the + button jogs motor E by the step (4 x 100)');
  await page.selectOption('#step', '10');
  for (let k = 0; k < 3; k++) { await motorsRow(1).locator('button.minus').click(); await settled(); }
  await encodersAre([400, -30, 0, 0, 0]);
  check(true, 'the - button jogs motor D by the step (3 x -10)');
  await page.locator('#cell').click({ position: { x: 5, y: 5 } });  // focus away from the controls
  await page.keyboard.press('ArrowUp');
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('1');
  await page.keyboard.press('ArrowRight');
  await encodersAre([400, -29, 0, 0, 0]);
  check((await page.evaluate(() => window.robotsim.selection.step)) === 1, 'the keys set the step and jog', 'D = -29');
  check((await motorsRow(1).locator('td.v').textContent()) === '-29', 'the page shows the new count');

  // ---- teach two points (the button, then Enter), a slider between them
  await page.fill('#teachName', 'FIRST');
  await page.click('#teach');
  await page.waitForFunction(() => window.robotsim.state.points.some((p) => p.name === 'FIRST'), null, { timeout: 10000 });
  check(true, 'TEACH adds point FIRST');
  await motorsRow(2).locator('input[type=range]').fill('120');
  await encodersAre([400, -29, 120, 0, 0]);
  check(true, 'the slider sets motor C');
  await page.fill('#teachName', 'SECOND');
  await page.press('#teachName', 'Enter');
  await page.waitForFunction(() => window.robotsim.state.points.some((p) => p.name === 'SECOND'), null, { timeout: 10000 });
  const names = await page.locator('#points li').evaluateAll((lis) => lis.map((li) => li.dataset.name));
  check(JSON.stringify(names) === JSON.stringify(['ABOVE_PICK', 'ABOVE_PRESS', 'FIRST', 'SECOND']),
        'the points list shows the program\'s points and the taught ones', names.join(' '));

  // ---- re-teach FIRST after a confirmation
  await page.selectOption('#step', '100');
  await motorsRow(3).locator('button.plus').click();
  await encodersAre([400, -29, 120, 100, 0]);
  await page.locator('#points li[data-name="FIRST"]').click();
  await page.click('#reteach');
  check(await page.locator('#confirm.on').isVisible(), 're-teach asks first',
        await page.locator('#question').textContent());
  await page.click('#yes');
  await page.waitForFunction(() => JSON.stringify(window.robotsim.state.points.find((p) => p.name === 'FIRST').values) ===
                                   '[400,-29,120,100,0]', null, { timeout: 10000 });
  check(true, 'yes re-teaches FIRST with the current pose');

  // ---- go to ABOVE_PICK: the move is animated, then ends on the point
  await page.locator('#points li[data-name="ABOVE_PICK"]').click();
  await page.click('#goto');
  await page.waitForFunction(() => window.robotsim.state.message.startsWith('went to ABOVE_PICK'), null, { timeout: 10000 });
  const motion = (await state()).motion;
  // D travels 171 counts at 400/s: 0.4275 s, the longest: 11 frames of 40 ms and the end.
  check(motion.length === 12 && motion[motion.length - 1].at === 427500, 'go to moves at motor speed, time-stepped',
        `${motion.length} frames to ${motion[motion.length - 1].at} µs`);
  const inBetween = await page.waitForFunction(() => {
    const s = window.robotsim.shown;
    return s && s.encoders[1] > -200 && s.encoders[1] < -29 ? s.encoders : null;
  }, null, { timeout: 5000, polling: 'raf' }).then((h) => h.jsonValue()).catch(() => null);
  check(inBetween !== null, 'the page shows the move under way', inBetween ? 'D = ' + inBetween[1] : 'never');
  await encodersAre([400, -200, 0, 250, 0]);
  check(true, 'and ends on the point');
  // The page draws the pose as the stills do (one projection, one forward
  // kinematics): its lines equal `robotsim render --dump-lines` of a
  // program that ends at the same encoder counts.
  const atPoint = path.join(work, 'at_point.rsp');
  fs.writeFileSync(atPoint, 'MOVETO 400 -200 0 250 0\nEND\n');
  const reference = JSON.parse(execFileSync(opt.robotsim, ['render', 'scara-pick', '--program', atPoint, '--at', '5',
                                                           '--dump-lines=json'], { encoding: 'utf8' }));
  const mine = await page.evaluate(() => window.robotsim.project(1024, 768));
  let worst = mine.lines.length === reference.lines.length ? 0 : Infinity;
  reference.lines.forEach((l, i) => {
    const p = mine.lines[i], q = [l.a[0], l.a[1], l.b[0], l.b[1]];
    for (let k = 0; k < 4 && p; k++) worst = Math.max(worst, Math.abs(p[k] - q[k]));
  });
  reference.tools.forEach((t, i) => {
    worst = Math.max(worst, Math.abs(mine.tools[i][0] - t.at[0]), Math.abs(mine.tools[i][1] - t.at[1]));
  });
  check(worst <= 1e-6, 'the page draws the pose as robotsim render does', `${reference.lines.length} lines, worst ${worst} px`);
  const st = await state();
  const tcpText = await page.locator('#tcp').textContent();
  check(tcpText === '(' + st.tcp.map((x) => x.toFixed(2)).join(', ') + ')', 'the tool centre point in world coordinates',
        tcpText);

  // ---- toggle input 3
  await page.locator('#inputs .lamp[data-line="3"]').click();
  await page.waitForFunction(() => window.robotsim.state.inputs[2] === true, null, { timeout: 10000 });
  check(await page.locator('#inputs .lamp[data-line="3"].on').isVisible(), 'input 3 switched on and lit');

  const shot = path.join(out, 'teach.png');
  await page.screenshot({ path: shot });
  check(fs.statSync(shot).size > 10000, 'screenshot saved', shot);
  if (opt.images) fs.copyFileSync(shot, path.join(opt.images, 'teach.png'));

  // ---- the file written, byte for byte
  const written = fs.readFileSync(program, 'utf8');
  check(written === golden, 'the program written equals the golden file byte for byte');
  check(fs.readFileSync(program + '.bak', 'utf8') === original, 'PROG.rsp.bak holds the program as it was');

  // ---- jog modes (docs/teach.md, "Jog modes"): m goes joint -> world ->
  // tool; the mode and the step's units show; in world, X +10 moves the
  // tool centre point 10 along the cell's X (the state's tcp is the rig's
  // forward kinematics of the counts, not the jog's arithmetic: within
  // one length unit of the counts' rounding); RY turns the tool about the
  // point; in tool, Z goes along the approach (down: y falls); a jog out
  // of reach is refused and moves nothing.
  await page.locator('#cell').click({ position: { x: 5, y: 5 } });
  const selection = () => page.evaluate(() => window.robotsim.selection);
  const near = (a, b) => Math.abs(a - b) <= 1;
  await page.keyboard.press('m');
  check((await selection()).mode === 'world' && (await page.locator('#mode').inputValue()) === 'world',
        'm switches the jog mode to world, and the mode menu shows it');
  check(await page.locator('#axesBox.on').isVisible(), '  the world axes are listed');
  const axisNames = await page.locator('#axes tr').evaluateAll((trs) => trs.map((tr) => tr.dataset.axis));
  check(JSON.stringify(axisNames) === '["X","Y","Z","RY"]', '  X, Y, Z and the SCARA\'s turn about the world\'s Y',
        axisNames.join(' '));
  await page.keyboard.press('2');
  check((await page.locator('#stepUnit').textContent()) === 'length units, 5 degrees', '  the step in its units',
        await page.locator('#stepUnit').textContent());
  let jogFrom = await state();
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => window.robotsim.state.message.startsWith('world jog X +10 length units'), null,
                             { timeout: 10000 });
  await settled();
  let jogTo = await state();
  check(near(jogTo.tcp[0], jogFrom.tcp[0] + 10) && near(jogTo.tcp[1], jogFrom.tcp[1]) && near(jogTo.tcp[2], jogFrom.tcp[2]),
        'world X +10 by the key moves the tool centre point 10 along X', `${jogFrom.tcp} -> ${jogTo.tcp}`);
  jogFrom = jogTo;
  await page.locator('#axes tr[data-axis="RY"] button.plus').click();
  await page.waitForFunction(() => window.robotsim.state.message.startsWith('world jog RY +5 degrees'), null,
                             { timeout: 10000 });
  await settled();
  jogTo = await state();
  check(near(jogTo.tcp[0], jogFrom.tcp[0]) && near(jogTo.tcp[2], jogFrom.tcp[2]) &&
        JSON.stringify(jogTo.encoders) !== JSON.stringify(jogFrom.encoders),
        'RY + (the button) turns the tool about the point, which stays', `${jogFrom.tcp} -> ${jogTo.tcp}`);
  jogFrom = jogTo;
  await page.keyboard.press('m');
  check((await selection()).mode === 'tool' && /Tool axes/.test(await page.locator('#axesTitle').textContent()),
        'm again: tool');
  // The row stays where it was (RY, the fourth: in tool it is RZ); one up is Z.
  await page.keyboard.press('ArrowUp');
  check((await selection()).axis === 'Z', '  the arrows select the axis', (await selection()).axis);
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => window.robotsim.state.message.startsWith('tool jog Z +10 length units'), null,
                             { timeout: 10000 });
  await settled();
  jogTo = await state();
  check(near(jogTo.tcp[1], jogFrom.tcp[1] - 10) && near(jogTo.tcp[0], jogFrom.tcp[0]),
        'tool Z +10 moves 10 along the approach (down)', `${jogFrom.tcp} -> ${jogTo.tcp}`);
  jogFrom = jogTo;
  await page.evaluate(() => window.robotsim.send({ op: 'jogCartesian', frame: 'world', axis: 'X', amount: 1000 }));
  await page.waitForFunction(() => window.robotsim.state.limit === 'reach', null, { timeout: 10000 });
  jogTo = await state();
  const refusedText = await page.locator('#message').textContent();
  check(/^world jog X \+1000 length units refused \(reach\): .*; nothing moved$/.test(refusedText) &&
        await page.locator('#status.failed').isVisible() && JSON.stringify(jogTo.encoders) === JSON.stringify(jogFrom.encoders),
        'a jog out of reach is refused, shown, and moves nothing', refusedText);
  await page.locator('#cell').click({ position: { x: 5, y: 5 } });
  await page.keyboard.press('m');
  check((await selection()).mode === 'joint' && !(await page.locator('#axesBox').isVisible()) &&
        (await page.locator('#stepUnit').textContent()) === 'counts', 'm again: back to joint, in counts');
  if (opt.images) await page.screenshot({ path: path.join(opt.images, 'teach-jog.png'), clip: { x: 900, y: 0, width: 380, height: 500 } });

  // ---- someone edits the file: the next write is refused and says so
  const theirs = original + '; edited in another editor\n';
  fs.writeFileSync(program, theirs);
  await page.fill('#teachName', 'LATE');
  await page.click('#teach');
  // The jog's refusal above left the state failed: wait for the teach's own answer.
  await page.waitForFunction((before) => window.robotsim.state.failed && window.robotsim.state.message !== before,
                             refusedText, { timeout: 10000 });
  const refusal = await page.locator('#message').textContent();
  check(/changed on disk since teach read it \(someone edited it\)/.test(refusal), 'a write after an edit on disk is refused',
        refusal);
  check(await page.locator('#status.failed').isVisible(), '  shown as a failure');
  check(fs.readFileSync(program, 'utf8') === theirs, '  and their edit is kept');
  if (opt.images) {
    await page.screenshot({ path: path.join(opt.images, 'teach-refused.png'), clip: { x: 900, y: 0, width: 380, height: 860 } });
  }

  const foreign = requests.filter((u) => !u.startsWith(origin + '/'));
  check(foreign.length === 0, 'nothing but the pendant\'s own server was requested', foreign.join(' '));
  check(errors.length === 0, 'no errors on the way', errors.join('; '));

  // ---- Ctrl-C stops the server cleanly
  await context.close();
  context = null;
  const exited = new Promise((r) => server.on('exit', (code) => r(code)));
  server.kill('SIGINT');
  const code = await exited;
  check(code === 0 && /stopped; .* has 4 points/.test(teach.out), 'Ctrl-C stops robotsim teach', `exit ${code}`);

  // ---- --open: xdg-open (a stand-in on PATH that writes down what it is
  // given) gets a private file, never the token (a command line is
  // readable by every user); the browser, given that file, ends on the page.
  const bin = path.join(work, 'bin');
  const runtime = path.join(work, 'runtime');
  fs.mkdirSync(bin);
  fs.mkdirSync(runtime, { mode: 0o700 });
  // Written whole, then renamed: the file never exists half-written (under
  // load the shell's redirection made it empty for a moment, and the test
  // read it then).
  fs.writeFileSync(path.join(bin, 'xdg-open'),
                   '#!/bin/sh\nprintf "%s" "$1" > "$(dirname "$0")/opened.part" && mv "$(dirname "$0")/opened.part" "$(dirname "$0")/opened"\n',
                   { mode: 0o755 });
  const opener = started(opt.robotsim, ['teach', program, '--cell', 'scara-pick', '--open'], 'ignore',
                         { ...process.env, PATH: bin + ':' + process.env.PATH, XDG_RUNTIME_DIR: runtime });
  const printed = (await opener.match(teachUrl))[0];
  const openedFile = path.join(bin, 'opened');
  for (let i = 0; i < 600 && !fs.existsSync(openedFile); i++) await new Promise((r) => setTimeout(r, 50));
  const given = fs.existsSync(openedFile) ? fs.readFileSync(openedFile, 'utf8') : '';
  const token = new URL(printed).searchParams.get('token');
  check(given.startsWith(runtime + '/') && !given.includes(token) && (fs.statSync(given).mode & 0o777) === 0o600,
        '--open hands xdg-open a file only this user can read, not the token', given);
  // Without the file (the check above failed) there is no page to go to.
  if (given) {
    context = await launch(chromium, opt.chromium, profile, { width: 1280, height: 860 });
    const opage = context.pages()[0] ?? await context.newPage();
    await opage.goto('file://' + given);
    await opage.waitForURL(printed, { timeout: 10000 });
    await opage.waitForFunction(() => window.robotsim && window.robotsim.state, null, { timeout: 10000 });
    check(opage.url() === printed, 'the browser, given that file, ends on the page the URL names');
    await context.close();
  }
  const openerExit = new Promise((r) => opener.proc.on('exit', (code) => r(code)));
  opener.proc.kill('SIGINT');
  await openerExit;
  check(!fs.existsSync(given), 'the file is removed when teach ends');

  // ---- with a device: robotsim emulate on a pty, robotsim teach --device on it
  emulator = started(opt.robotsim, ['emulate', '--speed', '10'], 'pipe');
  const device = (await emulator.match(/emulator on (\/dev\/\S+)/))[1];
  const deviceProgram = path.join(work, 'device.rsp');
  fs.writeFileSync(deviceProgram, '        END\nPOINTS\n');
  deviceTeach = started(opt.robotsim, ['teach', deviceProgram, '--cell', 'scara-pick', '--device', device, '--serial-set', 'timeout=0.2']);
  const deviceUrl = (await deviceTeach.match(teachUrl))[0];
  context = await launch(chromium, opt.chromium, profile, { width: 1280, height: 860 });
  const dpage = context.pages()[0] ?? await context.newPage();
  await dpage.goto(deviceUrl);
  await dpage.waitForFunction(() => window.robotsim && window.robotsim.state, null, { timeout: 10000 });
  const dRow = (i) => dpage.locator(`#motors tr[data-motor="${i}"]`);
  const dSettled = () => dpage.waitForFunction(() => !window.robotsim.busy, null, { timeout: 10000 });
  await dpage.selectOption('#step', '10');
  for (const [motor, button, times] of [[0, 'plus', 3], [1, 'minus', 2], [2, 'plus', 1]])
    for (let k = 0; k < times; k++) { await dRow(motor).locator('button.' + button).click(); await dSettled(); }
  await dpage.waitForFunction(() => JSON.stringify(window.robotsim.state.encoders) === '[30,-20,10,0,0]', null,
                              { timeout: 10000 });
  const shownCounts = await dpage.locator('#motors td.v').allTextContents();
  const before = emulator.out.length;
  emulator.proc.stdin.write('status\n');
  await emulator.match(/motor H: position/);
  const status = emulator.out.slice(before);
  const emulated = ['E', 'D', 'C', 'B', 'A'].map((l) => status.match(new RegExp('motor ' + l + ': position (-?\\d+)'))[1]);
  check(JSON.stringify(emulated) === JSON.stringify(shownCounts), "after the jogs the emulator's motors equal the page's",
        emulated.join(' '));
  // The controller falls silent after the next command: the jog's move is
  // sent, its progress never reported.
  emulator.proc.stdin.write('fault silence after 1\n');
  await dpage.selectOption('#step', '100');
  await dRow(0).locator('button.plus').click();
  await dpage.waitForFunction(() => window.robotsim.state.fault !== '', null, { timeout: 10000 });
  const banner = dpage.locator('#fault.on');
  check(await banner.isVisible(), 'a silent controller during a jog: the page says so', await banner.textContent());
  const colour = await banner.evaluate((e) => getComputedStyle(e).color);
  check(colour === 'rgb(255, 85, 85)', '  in red', colour);
  await dRow(1).locator('button.plus').click();
  await dpage.waitForFunction(() => window.robotsim.state.message.startsWith('the device failed, nothing is sent'), null,
                              { timeout: 10000 });
  check(true, '  and every move after it is refused');
  if (opt.images) await dpage.screenshot({ path: path.join(opt.images, 'teach-fault.png'), clip: { x: 900, y: 0, width: 380, height: 420 } });
  await context.close();
  context = null;
  const deviceExit = new Promise((r) => deviceTeach.proc.on('exit', (code) => r(code)));
  deviceTeach.proc.kill('SIGINT');
  check((await deviceExit) === 0, 'Ctrl-C stops robotsim teach --device');
  emulator.proc.stdin.write('quit\n');
  console.log(`PASS: ${checkCount()} checks`);
} catch (e) {
  console.error('FAIL: ' + e.message);
  console.error(teach.err + (deviceTeach ? deviceTeach.err : ''));
  process.exitCode = 1;
} finally {
  clearTimeout(deadline);
  await context?.close();
  cleanUp();
}
