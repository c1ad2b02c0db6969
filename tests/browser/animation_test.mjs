// The animation page in a real browser: Debian's chromium, headless, driven
// by playwright-core. Starts everything it needs (robotsim, the browser),
// touches nothing but loopback/file:// and stops within --timeout seconds.
//
//   node tests/browser/animation_test.mjs --robotsim BUILD/robotsim [--out DIR]
//        [--chromium /usr/bin/chromium] [--timeout 120]
//
// Checks: the page loads without fetching anything, its canvas is drawn,
// its projection equals `robotsim render --dump-lines` to 1e-6 px (and its
// tool path `render --path`'s, to the thinning's tolerance), dragging
// turns the picture, the wheel zooms, Play advances the time and the
// highlighted line, the lamps follow the outputs, a block the gripper
// carries moves with it and the others stay, a collision's parts are drawn
// red while it lasts. Saves DIR/animation.png.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { check, checkCount, chromiumAt, launch, source, testOptions, watchdog } from './harness.mjs';

const opt = testOptions('animation_test.mjs --robotsim PATH [--out DIR] [--chromium PATH] [--timeout S]');
const chromium = await chromiumAt(opt.chromium);

const out = opt.out ? path.resolve(opt.out) : fs.mkdtempSync(path.join(os.tmpdir(), 'robotsim-browser-'));
fs.mkdirSync(out, { recursive: true });
const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'robotsim-chromium-'));
let context = null;
const deadline = watchdog(opt.timeout, () => context, () => fs.rmSync(profile, { recursive: true, force: true }));

// ---- the page and the reference picture, from robotsim itself
const examples = path.join(source, 'examples');
const html = path.join(out, 'run.html');
const robotsim = (args) => execFileSync(opt.robotsim, args, { encoding: 'utf8', timeout: 30000 });
robotsim(['animate', path.join(examples, 'pick_and_place.rsp'), '--cell', 'scara-pick',
          '--stimuli', path.join(examples, 'pick_and_place.stim'), '-o', html]);
// Moments to compare the page's projection with render's: pick_and_place
// (the slide C and the gripper A move) and workcell_view (VIEW and WINDOW).
const AT = 2.5;  // seconds: MOVEP ABOVE_PICK is under way
const stills = (program, cell, times, extra = []) => times.map((t) => ({
  t,
  still: JSON.parse(robotsim(['render', cell, '--program', path.resolve(examples, program), ...extra, '--at', String(t),
                              '--dump-lines=json'])),
}));
const pickStills = stills('pick_and_place.rsp', 'scara-pick', [AT, 4.2, 6.2, 20],
                          ['--stimuli', path.join(examples, 'pick_and_place.stim')]);
const still = pickStills[0].still;
const pathStills = stills('pick_and_place.rsp', 'scara-pick', [AT, 20],
                          ['--stimuli', path.join(examples, 'pick_and_place.stim'), '--path']);
const viewHtml = path.join(out, 'view.html');
robotsim(['animate', path.join(examples, 'workcell_view.rsp'), '--cell', 'scara-pick', '-o', viewHtml]);
const viewStills = stills('workcell_view.rsp', 'scara-pick', [1, 3, 3.6, 5]);
// A gantry pick-and-place free of collisions (runs check them: the way
// examples/gantry_pick.rsp goes, straight down and up, gripping 1 mm above
// the block's middle). X, Z at 1000 counts/s, Y 800, A 200: over block 1
// (object 1) 0..2.8 s; down 1490 to 4.6625; the gripper takes it at the end
// of its closing move, 5.1625; up to 7.025; carried (X 5100 counts) to
// 12.125; down to 13.9875, where it lets go as its opening move starts
// (to 14.4875); up to 16.35, home (X 2300) at 18.65.
const gantryProgram = path.join(out, 'gantry_carry.rsp');
fs.writeFileSync(gantryProgram, ['MOVETO -2800 2800 0 0', 'MOVETO -2800 2800 1490 0', 'MOVE 0 0 0 100',
                                 'MOVETO -2800 2800 0 100', 'MOVETO 2300 -2200 0 100', 'MOVETO 2300 -2200 1490 100',
                                 'MOVE 0 0 0 -100', 'MOVETO 2300 -2200 0 0', 'MOVETO 0 0 0 0', 'END', ''].join('\n'));
const gantryHtml = path.join(out, 'gantry.html');
robotsim(['animate', gantryProgram, '--cell', 'gantry-cell', '-o', gantryHtml]);
const GANTRY_AT = { before: 2, closing: 5, carrying: 8, opening: 14.2, away: 18 };  // seconds
// A cell with devices (issue 35): adept_production on adept-cell. The belts
// carry blocks during the robot's waits and moves, the beam at x = 300
// breaks at 1.1 s, the feeder puts blocks at 0 and 6 s, the sink takes
// the first carried out at 5.635 s: the page must draw each moment as
// render --at does (parts, the broken beam, no empty feeder slot).
const devicesHtml = path.join(out, 'devices.html');
robotsim(['animate', path.join(examples, 'adept_production.rsp'), '--cell', 'adept-cell', '-o', devicesHtml]);
const devicesStills = stills('adept_production.rsp', 'adept-cell', [0.5, 1.2, 3, 5.7, 6.1, 30]);
// A collision, kept going with --collisions=warn: closing at the block's
// middle (Y 1500, 4.675 .. 5.175 s) the fingers' lower corners swing 0.09
// below their resting tips, into the pallet (docs/teach.md): the left
// finger (finger 2, the first the checker finds) and pallet 1 are red from
// that moment to the move's end, and nothing is red before.
const hotProgram = path.join(out, 'gantry_graze.rsp');
fs.writeFileSync(hotProgram, ['MOVETO -2800 2800 0 0', 'MOVETO -2800 2800 1500 0', 'MOVE 0 0 0 100', 'END', '']
  .join('\n'));
const hotHtml = path.join(out, 'graze.html');
robotsim(['animate', hotProgram, '--cell', 'gantry-cell', '--collisions=warn', '-o', hotHtml]);
const HOT_AT = { before: 4.6, during: 5.1 };  // seconds
// A grasp 40 too high (Y 1100, not 1490: the tool centre point at y 90,
// the block's centre at 50, its top at 70): the gripper closes on nothing
// at line 3 (2.8 s over, 1100 / 800 = 1.375 s down, 100 / 200 = 0.5 s
// closing: the run ends at 4.675 s), and the page's status says so under
// END, as `robotsim run` warns.
const highProgram = path.join(out, 'gantry_high.rsp');
fs.writeFileSync(highProgram, ['MOVETO -2800 2800 0 0', 'MOVETO -2800 2800 1100 0', 'MOVE 0 0 0 100', 'END', '']
  .join('\n'));
const highHtml = path.join(out, 'high.html');
robotsim(['animate', highProgram, '--cell', 'gantry-cell', '-o', highHtml]);
const gantryStills = stills(gantryProgram, 'gantry-cell', Object.values(GANTRY_AT));
// The IRB 120's joints accelerate (runtime/sim/motion.h, mirrored in the page
// with BigInt): a trapezoid on G and F (0 to 0.449287 s), a triangle on E
// (to 0.533805 s), the gripper's fixed 0.1 s (to 0.633805 s); moments in
// each phase of each.
const trapezoidProgram = path.join(out, 'irb120_moves.rsp');
fs.writeFileSync(trapezoidProgram, ['MOVE 9000 3000 0 0 0 0 0', 'MOVE 0 0 500 0 0 0 0', 'MOVE 0 0 0 0 0 0 60', 'END', '']
  .join('\n'));
const trapezoidHtml = path.join(out, 'irb120.html');
robotsim(['animate', trapezoidProgram, '--cell', 'irb120-cell', '-o', trapezoidHtml]);
const trapezoidStills = stills(trapezoidProgram, 'irb120-cell', [0.05, 0.15, 0.3, 0.42, 0.48, 0.52, 0.58]);

// A run longer than the page keeps step by step (docs/render.md, "Frames"):
// the gantry's 6,500 back-and-forth moves of X by one count (1 ms each at
// 1000 counts/s), 26,001 steps in 13 s, cut down to slots of 1/600 s: the
// moves left out come back as jumps. At the start of each frame the page
// must show what render --at shows for the whole run.
const longProgram = path.join(out, 'long_jiggle.rsp');
fs.writeFileSync(longProgram, ['loop: MOVE 1 0 0 0', 'MOVE -1 0 0 0', 'ADD N 1', 'JMPVAR N < 6500 loop', 'END', '']
  .join('\n'));
const longHtml = path.join(out, 'long.html');
robotsim(['animate', longProgram, '--cell', 'gantry-cell', '-o', longHtml]);
const longModel = (() => {
  const text = fs.readFileSync(longHtml, 'utf8'), open = 'id="robotsim-model">';
  const from = text.indexOf(open) + open.length;
  return JSON.parse(text.slice(from, text.indexOf('</script>', from)));
})();
const longFrames = longModel.run.start.length;
const longStills = stills(longProgram, 'gantry-cell', [1, 2, 3, 4].map((j) => {
  const k = Math.floor((longFrames * j) / 5);
  return (longModel.run.start[k] / 1e6).toFixed(6);
}).map(Number));

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
// How far apart two tool paths are (lists of [u, v] stretches, as
// render --path --dump-lines=json gives them): the farthest vertex of either
// from the other's polyline; Infinity when their stretches differ in number
// or in their ends (which both give exactly: home, and the tool at t).
function pathDifference(mine, reference) {
  if (mine.length !== reference.length) return Infinity;
  const toPolyline = (p, line) => {
    let best = Infinity;
    for (let i = 0; i + 1 < line.length || i === 0; i++) {
      const a = line[i], b = line[Math.min(i + 1, line.length - 1)];
      const dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
      const s = len2 > 0 ? Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2)) : 0;
      best = Math.min(best, Math.hypot(p[0] - a[0] - s * dx, p[1] - a[1] - s * dy));
      if (line.length < 2) break;
    }
    return best;
  };
  let worst = 0;
  for (let k = 0; k < mine.length; k++) {
    const a = mine[k], b = reference[k];
    for (const end of [0, -1]) {
      const p = a.at(end), q = b.at(end);
      if (Math.abs(p[0] - q[0]) > 1e-6 || Math.abs(p[1] - q[1]) > 1e-6) return Infinity;
    }
    for (const p of a) worst = Math.max(worst, toPolyline(p, b));
    for (const p of b) worst = Math.max(worst, toPolyline(p, a));
  }
  return worst;
}
const encodersOf = (reference) => reference.legend[1].split(/\s+/).slice(1).map((w) => Number(w.split('=')[1]));

try {
  context = await launch(chromium, opt.chromium, profile, { width: 1280, height: 800 });
  const page = context.pages()[0] ?? await context.newPage();
  const requests = [], errors = [];
  page.on('request', (r) => requests.push(r.url()));
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  const url = 'file://' + html;
  await page.goto(url);
  await page.waitForFunction(() => window.robotsim !== undefined, null, { timeout: 10000 });
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  check(errors.length === 0, 'the page runs without errors', errors.join('; '));

  // ---- the canvas is drawn: many non-background pixels, in several EGA colours
  const pixels = () => page.evaluate(() => {
    const c = document.getElementById('cell'), d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let drawn = 0, hash = 0;
    const colours = new Set();
    for (let i = 0; i < d.length; i += 4) {
      if (d[i] !== 0x10 || d[i + 1] !== 0x12 || d[i + 2] !== 0x1c) drawn++;
      if (d[i] % 0x55 === 0 && d[i + 1] % 0x55 === 0 && d[i + 2] % 0x55 === 0) colours.add(d[i] * 65536 + d[i + 1] * 256 + d[i + 2]);
      hash = (hash * 31 + d[i] + 7 * d[i + 1] + 13 * d[i + 2]) >>> 0;
    }
    return { drawn, hash, colours: colours.size, width: c.width, height: c.height };
  });
  const first = await pixels();
  check(first.width > 500 && first.height > 400, 'the canvas fills the view', `${first.width}x${first.height}`);
  check(first.drawn > 2000, 'the canvas is drawn', `${first.drawn} pixels`);
  check(first.colours >= 4, 'in several EGA colours', `${first.colours}`);

  // ---- the page's kinematics and camera equal robotsim render's
  const compare = async (list) => {
    for (const { t, still: reference } of list) {
      const mine = await page.evaluate((us) => window.robotsim.project(us, 1024, 768), t * 1e6);
      const worst = difference(mine, reference);
      check(worst <= 1e-6, `the page projects like render --at ${t}`,
            `${mine.lines.length} lines, largest difference ${worst.toExponential(2)} px`);
      check(JSON.stringify(mine.encoders) === JSON.stringify(encodersOf(reference)), `  with the same encoder counts`,
            mine.encoders.join(' '));
    }
  };
  await compare(pickStills);
  // ---- the tool's path: the page's, up to the time shown, is render --path's.
  // render --at runs only until then, so where the two thin a stretch may
  // differ by the thinning's tolerance (a third of a pixel) each way.
  for (const { t, still: reference } of pathStills) {
    const mine = await page.evaluate((us) => window.robotsim.projectPath(us, 1024, 768), t * 1e6);
    const worst = pathDifference(mine, reference.path || []);
    check(worst <= 0.75, `the page's tool path is render --path's at ${t}`,
          `${mine.length} stretch(es), ${mine.reduce((n, s) => n + s.length, 0)} vertices, largest difference ` +
          `${worst.toExponential(2)} px`);
  }
  check((await page.evaluate(() => window.robotsim.state.path)) === true, 'the path box starts ticked');
  const legend = encodersOf(still);

  // ---- dragging turns the picture; the wheel zooms
  const box = await page.locator('#cell').boundingBox();
  const cx = box.x + box.width / 2, cy = box.y + box.height / 2;
  await page.mouse.move(cx, cy);
  await page.mouse.down();
  for (let i = 1; i <= 10; i++) await page.mouse.move(cx + 12 * i, cy + 4 * i);
  await page.mouse.up();
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const dragged = await pixels();
  const user = (await page.evaluate(() => window.robotsim.state)).user;
  check(user.ry === 60 && user.rx === 20, 'dragging turns the view', `ry ${user.ry}, rx ${user.rx}`);
  check(dragged.hash !== first.hash, 'the picture changed after the drag');
  await page.mouse.wheel(0, -240);
  await page.waitForFunction(() => window.robotsim.state.user.zoom > 1.2, null, { timeout: 5000 });
  const zoom = await page.evaluate(() => window.robotsim.state.user.zoom);
  check(zoom > 1.2, 'the wheel zooms in', zoom.toFixed(3));

  // ---- Play: the time and the highlighted line advance
  const before = await page.evaluate(() => window.robotsim.state);
  const currentLi = () => page.evaluate(() => {
    const li = document.querySelector('#listing li.current');
    return li ? Number(li.querySelector('.n').textContent) : 0;
  });
  const lineBefore = await currentLi();
  check(before.t === 0 && !before.playing, 'the page starts paused at 0 s');
  check(lineBefore === before.line && lineBefore > 0, 'the first instruction under way is highlighted', `line ${lineBefore}`);
  await page.click('#play');
  await page.waitForFunction((line) => window.robotsim.state.line !== line && window.robotsim.state.t > 1.2e6,
                             lineBefore, { timeout: 15000 });
  const during = await page.evaluate(() => window.robotsim.state);
  const lineDuring = await currentLi();
  check(during.playing, 'Play plays', `t = ${(during.t / 1e6).toFixed(3)} s`);
  check(lineDuring === during.line && lineDuring !== lineBefore, 'the highlighted line advances',
        `line ${lineBefore} -> ${lineDuring}`);
  const timeText = await page.textContent('#time');
  check(/^\d+\.\d{3} \/ 34\.900 s$/.test(timeText) && timeText !== '0.000 / 34.900 s', 'the time display advances', timeText);
  await page.click('#play');
  check(!(await page.evaluate(() => window.robotsim.state.playing)), 'Pause pauses');

  // ---- scrubbing, speed, lamps and motors
  await page.evaluate(() => window.robotsim.setTime(1.0e6));  // OUTSIG 1 ON, waiting for the part
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const lamps = await page.evaluate(() => ({
    outputs: [...document.querySelectorAll('#outputs .lamp')].map((l) => l.classList.contains('on')),
    state: window.robotsim.state,
  }));
  check(lamps.outputs[0] && lamps.state.outputs === 1, 'output 1 is lit while the conveyor runs');
  await page.selectOption('#speed', '10');
  check((await page.evaluate(() => window.robotsim.state.speed)) === 10, 'the speed control sets 10x');
  await page.evaluate(() => window.robotsim.setTime(2.5e6));
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const motors = await page.$$eval('#motors td.v', (tds) => tds.map((td) => Number(td.textContent)));
  check(JSON.stringify(motors) === JSON.stringify(legend), 'the motor table shows the encoder counts', motors.join(' '));

  // ---- double-click goes back to the starting view; a screenshot for people
  await page.dblclick('#cell');
  const reset = (await page.evaluate(() => window.robotsim.state)).user;
  check(reset.rx === 0 && reset.ry === 0 && reset.zoom === 1, 'double-click resets the view');
  await page.evaluate(() => { window.robotsim.setTime(6.2e6); });
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const shot = path.join(out, 'animation.png');
  await page.screenshot({ path: shot });
  check(fs.statSync(shot).size > 10000, 'screenshot saved', shot);

  // ---- a program's VIEW and WINDOW turn and shift the page's camera as render's
  await page.goto('file://' + viewHtml);
  await page.waitForFunction(() => window.robotsim !== undefined, null, { timeout: 10000 });
  await compare(viewStills);

  // ---- accelerating joints and a timed gripper: the page's poses are render's
  await page.goto('file://' + trapezoidHtml);
  await page.waitForFunction(() => window.robotsim !== undefined, null, { timeout: 10000 });
  await compare(trapezoidStills);

  // ---- a long run's page holds frames, and each frame is the run's own moment
  await page.goto('file://' + longHtml);
  await page.waitForFunction(() => window.robotsim !== undefined, null, { timeout: 10000 });
  check(longModel.run.frames && longModel.run.frames.steps === 26001 && longModel.run.frames.slot === 1667 &&
        longFrames < 13000 && longFrames > 7000,
        'a run of 26,001 steps comes as frames of 1/600 s', `${longFrames} frames`);
  await compare(longStills);
  const longStatus = await (async () => {
    await page.evaluate(() => window.robotsim.setTime(1e6));
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    return page.evaluate(() => document.getElementById('status').textContent);
  })();
  check(longStatus.includes(`26001 instructions shown as ${longFrames} frames: every event, and the first to start ` +
                            'in each 0.002 s'), '  and its status says so', JSON.stringify(longStatus));

  // ---- a cell's devices: belts carry parts, the broken beam, parts fed and taken
  await page.goto('file://' + devicesHtml);
  await page.waitForFunction(() => window.robotsim !== undefined, null, { timeout: 10000 });
  check(devicesStills[1].still.lines.some((l) => l.owner === 'sensor') &&
        !devicesStills[0].still.lines.some((l) => l.owner === 'sensor'),
        'render --at draws the beam while it is broken (1.2 s), not before (0.5 s)');
  await compare(devicesStills);
  // The input lamp's title says what set it last, in the debugger's words
  // (the text trace: input 1 ON at 1.100 s and OFF at 1.485 s, both by the
  // wire from sensor eye); before the first change it names the input only.
  const inputTitle = async (t) => {
    await page.evaluate((us) => window.robotsim.setTime(us), t * 1e6);
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    return page.evaluate(() => document.querySelector('#inputs .lamp').title);
  };
  for (const [t, want] of [[1.2, 'input 1 ON since 1.100 s: wire from sensor eye'],
                           [2, 'input 1 OFF since 1.485 s: wire from sensor eye'], [0.5, 'input 1']]) {
    const title = await inputTitle(t);
    check(title === want, `at ${t} s the input lamp's title says what set it`, JSON.stringify(title));
  }

  // ---- the carried block moves with the gripper; the other block does not
  await page.goto('file://' + gantryHtml);
  await page.waitForFunction(() => window.robotsim !== undefined, null, { timeout: 10000 });
  await compare(gantryStills);
  // Object o's lines in project()'s list: after every robot part's, then
  // the objects' in order. Their mean screen point stands for the object.
  const gantry = await page.evaluate((times) => {
    const m = window.robotsim.model;
    let first = 0;
    for (const r of m.robots) for (const p of r.parts) first += p.colors.length;
    const range = m.objects.map((o) => { const at = first; first += o.colors.length; return [at, o.colors.length]; });
    const at = {};
    for (const [name, t] of Object.entries(times)) {
      const { lines, tools } = window.robotsim.project(t * 1e6, 1024, 768);
      at[name] = {
        tool: tools[0],
        objects: range.map(([a, n]) => {
          let u = 0, v = 0;
          for (let i = a; i < a + n; i++) { u += lines[i][0] + lines[i][2]; v += lines[i][1] + lines[i][3]; }
          return [u / (2 * n), v / (2 * n)];
        }),
      };
    }
    return { names: m.objects.map((o) => o.name), at };
  }, GANTRY_AT);
  const moved = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1]);
  const G = gantry.at;
  check(gantry.names[1] === 'block' && gantry.names[2] === 'block', 'the gantry cell has its two blocks',
        gantry.names.join(' '));
  check(moved(G.before.objects[1], G.closing.objects[1]) < 1e-9, 'a closing gripper has not taken the block yet');
  const carried = moved(G.before.objects[1], G.carrying.objects[1]);
  check(carried > 50, 'the carried block moves with the gripper', `${carried.toFixed(1)} px at ${GANTRY_AT.carrying} s`);
  // The gantry only translates and the projection is affine: the block
  // moves on screen exactly as the tool centre point does.
  const offset = (o, t) => [o[0] - t[0], o[1] - t[1]];
  check(moved(offset(G.closing.objects[1], G.closing.tool), offset(G.carrying.objects[1], G.carrying.tool)) < 1e-6,
        '  as the tool centre point does');
  check(moved(G.opening.objects[1], G.away.objects[1]) < 1e-9 && moved(G.opening.tool, G.away.tool) > 50,
        'once let go, it stays where it was put');
  check(moved(G.opening.objects[1], G.before.objects[1]) > 50, '  away from where it started');
  const othersStill = Object.keys(GANTRY_AT).every((k) => [0, 2, 3].every((o) => moved(G[k].objects[o], G.before.objects[o]) < 1e-9));
  check(othersStill, 'the other block and the pallets do not move');

  // ---- the status under END: a warning when the gripper never took anything
  const statusAt = async (seconds) => {
    await page.evaluate((t) => window.robotsim.setTime(t), seconds * 1e6);
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    return page.evaluate(() => document.getElementById('status').textContent);
  };
  const carriedEnd = await statusAt(GANTRY_AT.away + 10);
  check(carriedEnd.endsWith('END'), 'a run that took its block ends with END and no warning', JSON.stringify(carriedEnd));
  await page.goto('file://' + highHtml);
  await page.waitForFunction(() => window.robotsim !== undefined, null, { timeout: 10000 });
  const highMiddle = await statusAt(4.0), highEnd = await statusAt(4.675);
  check(!highMiddle.includes('warning'), 'before the end the status warns of nothing', JSON.stringify(highMiddle));
  check(highEnd.includes('END\nwarning: line 3: the gripper closed once but never took an object') &&
        highEnd.includes('its centre 40 below the tool centre point, which is 20 outside its box'),
        'a grasp 40 too high: the status under END says the gripper never took anything, and why',
        JSON.stringify(highEnd));

  // ---- a collision's parts are drawn red (EGA 4) while it lasts, and only they
  await page.goto('file://' + hotHtml);
  await page.waitForFunction(() => window.robotsim !== undefined, null, { timeout: 10000 });
  const redAt = async (seconds) => {
    await page.evaluate((t) => window.robotsim.setTime(t), seconds * 1e6);
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    return page.evaluate(() => {
      const m = window.robotsim.model, canvas = document.getElementById('cell');
      const { width, height } = canvas, dpr = window.devicePixelRatio || 1;
      const px = canvas.getContext('2d').getImageData(0, 0, width, height).data;
      // Red: EGA 4 (170, 0, 0) over the dark background, at any coverage; the
      // blocks' light red (255, 85, 85) and the pallets' brown (170, 85, 0) are not.
      const red = [];
      for (let i = 0; i < px.length; i += 4)
        if (px[i] > 60 && px[i + 1] < 25 && px[i + 2] < 32) red.push([(i / 4) % width, Math.floor(i / 4 / width)]);
      const hot = [];
      m.robots[0].parts.forEach((p) => { if (p.hot) hot.push({ name: p.kind + ' ' + p.index, screen: p.screen, n: p.count }); });
      m.objects.forEach((o, k) => { if (o.hot) hot.push({ name: 'object ' + (k + 1) + ' ' + o.name, screen: o.screen, n: o.count }); });
      // Each red pixel's distance to the nearest line of a hot part (device pixels).
      const near = (x, y, part) => {
        let best = Infinity;
        for (let j = 0; j < 4 * part.n; j += 4) {
          const ax = part.screen[j] * dpr, ay = part.screen[j + 1] * dpr, bx = part.screen[j + 2] * dpr,
                by = part.screen[j + 3] * dpr;
          const dx = bx - ax, dy = by - ay, len = dx * dx + dy * dy;
          const u = len ? Math.max(0, Math.min(1, ((x + 0.5 - ax) * dx + (y + 0.5 - ay) * dy) / len)) : 0;
          best = Math.min(best, Math.hypot(ax + u * dx - x - 0.5, ay + u * dy - y - 0.5));
        }
        return best;
      };
      const stray = red.filter(([x, y]) => hot.every((h) => near(x, y, h) > 2)).length;
      const perPart = hot.map((h) => red.filter(([x, y]) => near(x, y, h) <= 2).length);
      return { red: red.length, hot: hot.map((h) => h.name), stray, perPart };
    });
  };
  const cold = await redAt(HOT_AT.before);
  check(cold.red === 0 && cold.hot.length === 0, 'before the collision nothing is red', `${cold.red} red pixels`);
  const hot = await redAt(HOT_AT.during);
  check(JSON.stringify(hot.hot) === JSON.stringify(['finger2 3', 'object 1 pallet']),
        'during the collision its two parts are marked', hot.hot.join(', '));
  check(hot.perPart.every((n) => n > 20) && hot.stray === 0, '  and drawn red, along their lines only',
        `${hot.perPart.join(' and ')} red pixels, ${hot.stray} elsewhere`);

  const foreign = requests.filter((u) => u !== url && u !== 'file://' + viewHtml && u !== 'file://' + gantryHtml &&
                                         u !== 'file://' + trapezoidHtml && u !== 'file://' + hotHtml && u !== 'file://' + highHtml &&
                                         u !== 'file://' + longHtml && u !== 'file://' + devicesHtml &&
                                         !u.startsWith('data:'));
  check(foreign.length === 0, 'nothing but the page itself was requested', foreign.join(' '));
  check(errors.length === 0, 'no errors on the way', errors.join('; '));
  console.log(`PASS: ${checkCount()} checks`);
} catch (e) {
  console.error('FAIL: ' + e.message);
  process.exitCode = 1;
} finally {
  clearTimeout(deadline);
  await context?.close();
  fs.rmSync(profile, { recursive: true, force: true });
}
