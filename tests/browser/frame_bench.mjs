// The animation's frame time in Chromium (not a test: it prints numbers for
// docs/render.md). Makes the page with `robotsim animate`, plays it in
// headless Debian chromium and reads the page's own statistics: the
// intervals between requestAnimationFrame timestamps while playing, and the
// time each frame's drawing took (kinematics, projection, canvas calls).
//
//   node tests/browser/frame_bench.mjs --robotsim BUILD/robotsim
//        --cell DIR/bench-cell.rsd --program DIR/bench.rsp [--seconds 8] [--smoke]
//
// render_bench (bench/render_bench.cpp) writes the 5,000-line cell and
// program. --smoke (the test suite's bench-smoke-frames) plays half a second
// after a warm-up of a fifth: it measures nothing, it shows the script runs.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { launch, options } from './harness.mjs';

const usage = 'frame_bench.mjs --robotsim PATH --cell FILE --program FILE [--seconds S] [--smoke] [--chromium PATH]';
if (process.argv.includes('--help')) {
  console.log('usage: ' + usage);
  process.exit(0);
}
const opt = options(usage, {
  cell: { type: 'string' },
  program: { type: 'string' },
  seconds: { type: 'string' },
  smoke: { type: 'boolean', default: false },
}, ['robotsim', 'cell', 'program']);
// Seconds of playback a pass: a number above 0 and at most an hour, else
// the usage (a NaN would be a wait of nothing and a mean of no frames).
const seconds = Number(opt.seconds ?? (opt.smoke ? '0.5' : '8'));
const wellFormed = opt.seconds === undefined || /^[0-9]+(\.[0-9]+)?$/.test(opt.seconds);
if (!wellFormed || !(seconds > 0 && seconds <= 3600)) {
  console.error(`frame_bench.mjs: error: --seconds takes a number of seconds above 0 and at most 3600, not '${opt.seconds}'`);
  console.error('usage: ' + usage);
  process.exit(2);
}
const warmUpMs = opt.smoke ? 200 : 1000;
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'robotsim-frames-'));
const html = path.join(work, 'bench.html');
// Collisions off: the bench arm's 5,016 lines overlap at home (a cell made
// to be drawn, not to be safe), and the page's drawing, measured here, is
// the same with or without the run's collision checks.
execFileSync(opt.robotsim, ['animate', opt.program, '--cell', opt.cell, '--collisions=off', '-o', html],
             { stdio: 'inherit' });
const context = await launch(chromium, opt.chromium, path.join(work, 'profile'),
                             { width: 1404, height: 800 });  // a 1024-pixel-wide canvas
try {
  const page = context.pages()[0] ?? await context.newPage();
  await page.goto('file://' + html);
  await page.waitForFunction(() => window.robotsim !== undefined);
  const info = await page.evaluate(() => {
    const c = document.getElementById('cell');
    let lines = 0;
    for (const r of window.robotsim.model.robots) for (const p of r.parts) lines += p.colors.length;
    for (const o of window.robotsim.model.objects) lines += o.colors.length;
    return { lines, width: c.clientWidth, height: c.clientHeight };
  });
  const f = (x) => x.toFixed(2);
  console.log(`frame_bench: ${info.lines} lines, canvas ${info.width}x${info.height} CSS px, ${seconds} s of playback each`);
  // Two passes: as a user sees it, then with each frame's rasterising forced
  // inside the timed draw (a pixel read back), which shows the full cost.
  for (const flush of [false, true]) {
    await page.evaluate((on) => { window.robotsim.flush = on; window.robotsim.setTime(0); window.robotsim.play(); }, flush);
    await page.waitForTimeout(warmUpMs);  // warm up: JIT, first frames
    await page.evaluate(() => window.robotsim.resetStats());
    await page.waitForTimeout(seconds * 1000);
    const s = await page.evaluate(() => { window.robotsim.pause(); return window.robotsim.stats(); });
    console.log(flush ? ' with rasterising in the draw time:' : ' as played:');
    console.log(`  rAF interval  mean ${f(s.interval.mean)}  p50 ${f(s.interval.p50)}  p95 ${f(s.interval.p95)}  max ${f(s.interval.max)} ms  (${s.interval.count} frames, ${f(1000 / s.interval.mean)} fps)`);
    console.log(`  draw          mean ${f(s.draw.mean)}  p50 ${f(s.draw.p50)}  p95 ${f(s.draw.p95)}  max ${f(s.draw.max)} ms`);
  }
} finally {
  await context.close();
  fs.rmSync(work, { recursive: true, force: true });
}
