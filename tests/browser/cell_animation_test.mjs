// The animation page of a cell of several robots (issue 36) in a real
// browser: every robot moves, the others by time as their own logs say.
// Its projection must equal `robotsim render CELL --at T --dump-lines=json`
// (every robot where its motors are, a part where the robot carrying it has
// it) at moments before, during and after each robot's carry in
// examples/two_robots/handover.rsd (the feeder carries the block from about
// 3 to 7.5 s, the packer from about 14 to 18 s: docs/models.md), and in the
// interlock cell while either robot moves, and through the hand-over of
// relay.rsd.
//
//   node tests/browser/cell_animation_test.mjs --robotsim BUILD/robotsim [--out DIR]
//        [--chromium /usr/bin/chromium] [--timeout 120]
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { check, checkCount, chromiumAt, launch, source, testOptions, watchdog } from './harness.mjs';

const opt = testOptions('cell_animation_test.mjs --robotsim PATH [--out DIR] [--chromium PATH] [--timeout S]');
const chromium = await chromiumAt(opt.chromium);
const out = opt.out ? path.resolve(opt.out) : fs.mkdtempSync(path.join(os.tmpdir(), 'robotsim-browser-'));
fs.mkdirSync(out, { recursive: true });
const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'robotsim-chromium-'));
let context = null;
const deadline = watchdog(opt.timeout, () => context, () => fs.rmSync(profile, { recursive: true, force: true }));

const robotsim = (args) => execFileSync(opt.robotsim, args, { encoding: 'utf8', timeout: 60000 });
const cells = [
  { cell: 'handover.rsd', times: [1, 5, 9, 12, 16, 19] },
  { cell: 'interlock.rsd', times: [0.5, 2.5, 3.5, 5] },
  // The giver takes the bar at 3.736 s, the taker takes it over at 7.394 s,
  // the giver opens 7.394 .. 7.994 s, the taker carries it on.
  { cell: 'relay.rsd', times: [3, 5, 7.5, 7.9, 10, 14] },
  // Both robots moving at once (right runs two moves, then turns on the
  // output left waits for, and ends: written below; two copies of left.rsp
  // would deadlock, each one's OUTSIG answered at that instant): at 0.5
  // and 1.5 s both are mid-move.
  { cell: 'interlock.rsd', times: [0.5, 1.5], programs: ['right=' + path.join(out, 'both_move.rsp')],
    page: 'both_left' },
];
fs.writeFileSync(path.join(out, 'both_move.rsp'), '        MOVE 300 0 0 0 0 0\n        MOVE -300 0 0 0 0 0\n        OUTSIG 1 ON\n        END\n');

// Largest difference between the page's lines and tools and render's.
function difference(mine, reference) {
  if (mine.lines.length !== reference.lines.length) return Infinity;
  let worst = 0;
  reference.lines.forEach((l, i) => {
    const p = mine.lines[i], q = [l.a[0], l.a[1], l.b[0], l.b[1]];
    for (let k = 0; k < 4; k++) worst = Math.max(worst, Math.abs(p[k] - q[k]));
  });
  reference.tools.forEach((t, i) => {
    worst = Math.max(worst, Math.abs(mine.tools[i][0] - t.at[0]), Math.abs(mine.tools[i][1] - t.at[1]));
  });
  return worst;
}

try {
  context = await launch(chromium, opt.chromium, profile, { width: 1280, height: 800 });
  const page = context.pages()[0] ?? await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  for (const { cell, times, programs = [], page: name } of cells) {
    const file = path.join(source, 'examples', 'two_robots', cell);
    const html = path.join(out, (name ?? cell.replace('.rsd', '')) + '.html');
    robotsim(['animate', '--cell', file, ...programs, '-o', html]);
    await page.goto('file://' + html);
    await page.waitForFunction(() => window.robotsim !== undefined, null, { timeout: 10000 });
    check(errors.length === 0, `${cell}: the page runs without errors`, errors.join('; '));
    for (const t of times) {
      const reference = JSON.parse(robotsim(['render', file, ...programs, '--at', String(t), '--dump-lines=json']));
      const mine = await page.evaluate((us) => window.robotsim.project(us, 1024, 768), t * 1e6);
      const worst = difference(mine, reference);
      check(worst <= 1e-6, `${cell}: the page projects like render --at ${t}`,
            `${mine.lines.length} lines, largest difference ${worst.toExponential(2)} px`);
    }
  }
  console.log(`PASS: ${checkCount()} checks`);
} catch (e) {
  console.error('FAIL: ' + e.message);
  process.exitCode = 1;
} finally {
  clearTimeout(deadline);
  await context?.close();
  fs.rmSync(profile, { recursive: true, force: true });
}
