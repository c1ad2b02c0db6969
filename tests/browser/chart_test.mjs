// The run's chart under the animation page's scrub bar, in a real browser
// (Debian's chromium, headless, driven by playwright-core): the chart is
// the picture `robotsim plot` draws, it sits under the controls, its cursor
// follows the time shown (setTime, the scrub bar, playback), and a click
// on it seeks to the time under the pointer.
//
//   node tests/browser/chart_test.mjs --robotsim BUILD/robotsim [--out DIR]
//        [--chromium /usr/bin/chromium] [--timeout 120]
//
// Saves DIR/chart.png.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { check, checkCount, chromiumAt, launch, source, testOptions, watchdog } from './harness.mjs';

const opt = testOptions('chart_test.mjs --robotsim PATH [--out DIR] [--chromium PATH] [--timeout S]');
const chromium = await chromiumAt(opt.chromium);
const out = opt.out ? path.resolve(opt.out) : fs.mkdtempSync(path.join(os.tmpdir(), 'robotsim-chart-'));
fs.mkdirSync(out, { recursive: true });
const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'robotsim-chromium-'));
let context = null;
const deadline = watchdog(opt.timeout, () => context, () => fs.rmSync(profile, { recursive: true, force: true }));

// examples/gantry_pick.rsp on the gantry-cell: its first move takes X from 0
// to -2800 at 1000 counts/s (0 .. 2.8 s), so X = -t·1000 counts in it.
const program = path.join(source, 'examples', 'gantry_pick.rsp');
const html = path.join(out, 'run.html'), svg = path.join(out, 'run.svg');
const robotsim = (args) => execFileSync(opt.robotsim, args, { encoding: 'utf8', timeout: 30000 });
robotsim(['animate', program, '--cell', 'gantry-cell', '-o', html]);
robotsim(['plot', program, '--cell', 'gantry-cell', '-o', svg]);
const plotted = fs.readFileSync(svg, 'utf8');

try {
  context = await launch(chromium, opt.chromium, profile, { width: 1280, height: 900 });
  const page = context.pages()[0] ?? await context.newPage();
  const requests = [], errors = [];
  page.on('request', (r) => requests.push(r.url()));
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  const url = 'file://' + html;
  await page.goto(url);
  await page.waitForFunction(() => window.robotsim !== undefined, null, { timeout: 10000 });
  await page.waitForFunction(() => document.getElementById('chart').complete &&
                                   document.getElementById('chart').naturalWidth > 0, null, { timeout: 10000 });
  const frame = () => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  await frame();
  check(errors.length === 0, 'the page runs without errors', errors.join('; '));

  const chart = await page.evaluate(() => {
    const c = window.robotsim.model.chart;
    return { width: c.width, height: c.height, left: c.left, right: c.right, end: c.end, svg: c.svg };
  });
  check(chart.svg === plotted, 'the page\'s chart is the picture robotsim plot draws',
        `${chart.svg.length} and ${plotted.length} bytes`);
  const natural = await page.evaluate(() => {
    const img = document.getElementById('chart');
    return [img.naturalWidth, img.naturalHeight];
  });
  // cairo gives the SVG's size in points (1200 px: 1200pt, 1600 CSS px), its
  // viewBox in the layout's pixels: the same shape.
  check(natural[0] > 0 && Math.abs(natural[0] / natural[1] - chart.width / chart.height) < 0.01,
        'the browser decodes the chart, in its shape', `${natural.join('x')} for ${chart.width}x${chart.height}`);

  // ---- under the scrub bar, as wide as the view
  const boxes = await page.evaluate(() => {
    const r = (id) => document.getElementById(id).getBoundingClientRect();
    const b = (x) => ({ left: x.left, top: x.top, right: x.right, bottom: x.bottom, width: x.width, height: x.height });
    return { chart: b(r('chart')), controls: b(r('controls')), timeline: b(r('timeline')), view: b(r('view')),
             pane: b(r('chartPane')) };
  });
  check(boxes.pane.top >= boxes.controls.bottom - 1 && boxes.chart.top >= boxes.timeline.bottom,
        'the chart sits under the scrub bar', `chart top ${boxes.chart.top}, controls bottom ${boxes.controls.bottom}`);
  check(Math.abs(boxes.chart.width - boxes.view.width) < 20 && boxes.chart.width > 600, 'as wide as the view',
        `${boxes.chart.width} and ${boxes.view.width} px`);
  check(boxes.view.height > 300, 'the workcell keeps most of the window', `${boxes.view.height} px`);

  // Where the cursor should be for time t, from the model's layout and the
  // image's size on screen; and where it is.
  const scale = boxes.chart.width / chart.width;
  const expectedX = (t) => boxes.chart.left + (chart.left + ((chart.right - chart.left) * t) / chart.end) * scale;
  const cursorX = () => page.evaluate(() => {
    const r = document.getElementById('chartCursor').getBoundingClientRect();
    return r.left + r.width / 2;
  });
  const cursorAt = async (t, what) => {
    await frame();
    const x = await cursorX();
    check(Math.abs(x - expectedX(t)) <= 1.5, what, `cursor at ${x.toFixed(2)} px, time ${t} µs at ${expectedX(t).toFixed(2)}`);
  };
  await cursorAt(0, 'the cursor starts at time 0');
  for (const t of [2.8e6, 7.5e6, chart.end]) {
    await page.evaluate((us) => window.robotsim.setTime(us), t);
    await cursorAt(t, `the cursor follows setTime(${t / 1e6} s)`);
  }

  // ---- the scrub bar moves it
  await page.evaluate((us) => {
    const tl = document.getElementById('timeline');
    tl.value = String(us);
    tl.dispatchEvent(new Event('input'));
    tl.dispatchEvent(new Event('change'));
  }, 4e6);
  const scrubbed = (await page.evaluate(() => window.robotsim.state)).t;
  check(Math.abs(scrubbed - 4e6) < 1, 'the scrub bar sets the time', String(scrubbed));
  await cursorAt(scrubbed, 'the cursor follows the scrub bar');

  // ---- playback moves it
  await page.evaluate(() => { window.robotsim.setTime(0); window.robotsim.setSpeed(4); window.robotsim.play(); });
  await page.waitForFunction(() => window.robotsim.state.t > 1.5e6, null, { timeout: 10000 });
  await page.evaluate(() => window.robotsim.pause());
  const played = (await page.evaluate(() => window.robotsim.state)).t;
  await cursorAt(played, 'the cursor follows playback');

  // ---- a click on the chart seeks to the time under the pointer (and pauses)
  const target = 2.0e6;
  await page.evaluate(() => window.robotsim.play());
  await page.mouse.click(expectedX(target), boxes.chart.top + boxes.chart.height / 2);
  await frame();
  const clicked = await page.evaluate(() => window.robotsim.state);
  const perPixel = chart.end / ((chart.right - chart.left) * scale);  // µs a screen pixel spans
  check(!clicked.playing, 'a click on the chart pauses');
  check(Math.abs(clicked.t - target) <= perPixel, 'a click on the chart seeks to the time under it',
        `${clicked.t} µs for ${target}, a pixel is ${perPixel.toFixed(0)} µs`);
  check(Math.abs(clicked.encoders[0] + Math.floor(clicked.t / 1000)) <= 0, '  where X is -t·1000 counts, as the move runs',
        `X ${clicked.encoders[0]} at ${clicked.t} µs`);
  await cursorAt(clicked.t, '  and the cursor stands there');
  const current = await page.evaluate(() => Number(document.querySelector('#listing li.current .n').textContent));
  check(current === clicked.line && current > 0, '  and the listing highlights the line running then', String(current));

  await page.screenshot({ path: path.join(out, 'chart.png') });
  const foreign = requests.filter((u) => u !== url && !u.startsWith('data:'));
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
