// The debugger's live view in a real browser: `robotsim debug --view` on
// examples/gantry_pick.rsp and the gantry-cell, its commands fed on
// standard input (batch mode) while Debian's chromium (headless, driven by
// playwright-core) shows the page. Stops within --timeout seconds.
//
//   node tests/browser/debug_view_test.mjs --robotsim BUILD/robotsim [--out DIR]
//        [--chromium /usr/bin/chromium] [--timeout 120]
//
// Checks: the page loads in read-only mode (the pendant's controls hidden,
// the banner shown) without errors or any request but its own server; at
// each stop (a breakpoint going forwards, a reverse step going back) the
// page takes the new state, draws the robot again (the canvas changes and
// shows the state's encoder counts) and shows the place and clock; the tool
// centre point it shows is the gantry's, worked out here from the encoder
// counts (x = 500 + X/10, y = 200 - Y/10, z = 400 + Z/10, the comment at the
// top of gantry_pick.rsp); a jog key is refused with the server's message
// and moves nothing; the end of the commands ends the debugger (exit 0).
// Saves DIR/debug_view.png.
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';

const here = path.dirname(fileURLToPath(import.meta.url));
const source = path.resolve(here, '../..');
const { values: opt } = parseArgs({
  options: {
    robotsim: { type: 'string' },
    out: { type: 'string' },
    chromium: { type: 'string', default: '/usr/bin/chromium' },
    timeout: { type: 'string', default: '120' },
  },
});
if (!opt.robotsim) fail('usage: debug_view_test.mjs --robotsim PATH [--out DIR] [--chromium PATH] [--timeout S]');

function fail(message) {
  console.error('FAIL: ' + message);
  process.exit(1);
}
let checks = 0;
function check(ok, what, detail = '') {
  if (!ok) throw new Error(what + (detail ? ': ' + detail : ''));
  checks++;
  console.log('ok   ' + what + (detail ? '  (' + detail + ')' : ''));
}

const { chromium } = await import('playwright-core').catch(() =>
  fail('playwright-core is missing: run `npm ci --prefix tests/browser` (see tests/browser/README.md)'));
if (!fs.existsSync(opt.chromium)) fail(`no browser at ${opt.chromium}: install Debian's chromium`);

const out = opt.out ? path.resolve(opt.out) : fs.mkdtempSync(path.join(os.tmpdir(), 'robotsim-debug-view-'));
fs.mkdirSync(out, { recursive: true });
const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'robotsim-chromium-'));
let context = null;
const debug = spawn(opt.robotsim, ['debug', path.join(source, 'examples/gantry_pick.rsp'), '--cell', 'gantry-cell',
                                   '--view'], { stdio: ['pipe', 'pipe', 'pipe'] });
let said = '', errText = '';
debug.stdout.on('data', (d) => { said += d; });
debug.stderr.on('data', (d) => { errText += d; });
function cleanUp() {
  if (debug.exitCode === null) debug.kill('SIGKILL');
  fs.rmSync(profile, { recursive: true, force: true });
}
const deadline = setTimeout(async () => {
  console.error(`FAIL: timed out after ${opt.timeout} s`);
  try { await context?.close(); } catch {}
  cleanUp();
  process.exit(1);
}, Number(opt.timeout) * 1000);

const url = await new Promise((resolve, reject) => {
  const poll = setInterval(() => {
    const m = said.match(/live view: (http:\/\/127\.0\.0\.1:\d+\/\?token=[0-9a-f]{32})/);
    if (m) { clearInterval(poll); resolve(m[1]); }
    if (debug.exitCode !== null) { clearInterval(poll); reject(new Error('robotsim debug exited: ' + errText)); }
  }, 50);
}).catch((e) => { cleanUp(); fail(e.message); });
const origin = new URL(url).origin;

try {
  context = await chromium.launchPersistentContext(profile, {
    executablePath: opt.chromium,
    headless: true,
    viewport: { width: 1280, height: 860 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking',
           '--disable-component-update', '--disable-sync'],
  });
  const page = context.pages()[0] ?? await context.newPage();
  const requests = [], errors = [];
  page.on('request', (r) => requests.push(r.url()));
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('console', (m) => { if (m.type() === 'error' && !m.text().includes('403')) errors.push(m.text()); });
  await page.goto(url);
  await page.waitForFunction(() => window.robotsim && window.robotsim.state, null, { timeout: 10000 });
  const frames = () => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  await frames();
  check(errors.length === 0, 'the page runs without errors', errors.join('; '));
  check(await page.evaluate(() => document.body.classList.contains('readonly')), 'the page is in read-only mode');
  check(await page.locator('#viewonly').isVisible(), '  the banner says so');
  for (const id of ['#teach', '#open', '#reset', '#step', '#points'])
    check(!(await page.locator(id).isVisible()), `  ${id} is hidden`);
  check(!(await page.locator('#motors button.plus').first().isVisible()), '  the jog buttons are hidden');

  // The canvas as a number, to see it drawn again.
  const picture = () => page.evaluate(() => {
    const c = document.getElementById('cell'), d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let h = 0;
    for (let i = 0; i < d.length; i += 4) h = (h * 31 + d[i] * 7 + d[i + 1] * 3 + d[i + 2]) >>> 0;
    return h;
  });
  const shownState = () => page.evaluate(() => ({
    state: window.robotsim.state,
    shown: window.robotsim.shown.encoders,
    cells: [...document.querySelectorAll('#motors td.v')].map((td) => Number(td.textContent)),
    where: document.getElementById('where').textContent,
    message: document.getElementById('message').textContent,
    tcp: document.getElementById('tcp').textContent,
  }));
  // The page at a stop: the state it drew, checked against the gantry's
  // own arithmetic for the tool centre point.
  async function checkStop(what, steps, previousPicture) {
    await page.waitForFunction((n) => window.robotsim.state.steps === n, steps, { timeout: 10000 });
    await frames();
    const s = await shownState();
    const [X, Z, Y] = s.state.encoders;
    const tcp = [500 + X / 10, 200 - Y / 10, 400 + Z / 10];
    check(JSON.stringify(s.shown) === JSON.stringify(s.state.encoders), `${what}: the robot is drawn at the stop`,
          s.shown.join(' '));
    check(JSON.stringify(s.cells) === JSON.stringify(s.state.encoders), '  the motor table shows it');
    check(s.tcp === '(' + tcp.map((x) => x.toFixed(2)).join(', ') + ')', '  the tool centre point is the gantry\'s',
          s.tcp);
    check(s.where.startsWith(`line ${s.state.line} @${s.state.instruction}, step ${steps}, clock `), '  the place',
          s.where);
    const now = await picture();
    if (previousPicture !== undefined) check(now !== previousPicture, '  the canvas was drawn again');
    return { s, picture: now };
  }
  let at = await checkStop('the start', 0);
  check(at.s.message === 'at the start of the run', '  why it stopped', at.s.message);

  // ---- forwards to the breakpoint at label place: the block is carried
  debug.stdin.write('break place\ncontinue\n');
  await page.waitForFunction(() => window.robotsim.state.steps > 0, null, { timeout: 10000 });
  const atPlace = (await page.evaluate(() => window.robotsim.state)).steps;
  at = await checkStop('a breakpoint', atPlace, at.picture);
  check(at.s.message.startsWith('breakpoint 1'), '  why it stopped', at.s.message);
  // The gripper closes to A = 100 of its 0..104: "between", holding.
  check(at.s.state.objects[1].held && at.s.state.gripper === 'between', '  the gripper holds block 1',
        at.s.state.gripper);
  await page.screenshot({ path: path.join(out, 'debug_view.png') });

  // ---- backwards two instructions
  debug.stdin.write('reverse-step 2\n');
  at = await checkStop('a reverse step', atPlace - 2, at.picture);
  check(at.s.message === 'step back done', '  why it stopped', at.s.message);

  // ---- a jog key: refused by the server, shown, nothing moves
  const before = at.s.state.encoders;
  await page.locator('#cell').click({ position: { x: 5, y: 5 } });
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => document.getElementById('message').textContent.startsWith('read-only'), null,
                             { timeout: 10000 });
  const after = await shownState();
  check(after.message.includes('robotsim teach'), 'a jog key gets the server\'s refusal', after.message);
  check(JSON.stringify(after.state.encoders) === JSON.stringify(before), '  nothing moved');

  check(requests.every((r) => r.startsWith(origin + '/')), 'no request but the page\'s own server',
        `${requests.length} requests`);
  debug.stdin.end();
  const code = await new Promise((r) => (debug.exitCode !== null ? r(debug.exitCode) : debug.on('exit', r)));
  check(code === 0, 'the end of the commands ends the debugger', `exit ${code}`);
  console.log(`PASS: ${checks} checks`);
} catch (e) {
  console.error('FAIL: ' + e.message);
  process.exitCode = 1;
} finally {
  clearTimeout(deadline);
  await context?.close();
  cleanUp();
}
