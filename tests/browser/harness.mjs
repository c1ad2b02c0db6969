// What the browser scripts share: their options, the check that counts and
// the failure that exits, Debian's chromium started through playwright-core
// in a fresh profile, and robotsim started as a process whose output is read
// as it comes. Each test keeps its own checks; this file checks nothing.
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';

/// The repository's root (this file is in tests/browser/).
export const source = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

export function fail(message) {
  console.error('FAIL: ' + message);
  process.exit(1);
}

let checks = 0;
/// Throws (the test's catch reports it) when `ok` is false; else counts
/// the check and prints it.
export function check(ok, what, detail = '') {
  if (!ok) throw new Error(what + (detail ? ': ' + detail : ''));
  checks++;
  console.log('ok   ' + what + (detail ? '  (' + detail + ')' : ''));
}
export const checkCount = () => checks;

/// The command line: --robotsim (required) and --chromium, with `more`
/// options (parseArgs's form); fails with `usage` when one of `required`
/// is missing.
export function options(usage, more = {}, required = ['robotsim']) {
  const { values } = parseArgs({
    options: {
      robotsim: { type: 'string' },
      chromium: { type: 'string', default: '/usr/bin/chromium' },
      ...more,
    },
  });
  if (required.some((name) => !values[name])) fail('usage: ' + usage);
  return values;
}

/// The options of a test: the script's own and --out, --timeout.
export const testOptions = (usage, more = {}) => options(usage, {
  out: { type: 'string' },
  timeout: { type: 'string', default: '120' },
  ...more,
});

/// playwright-core's Chromium launcher, and a check that the browser is
/// there: both say how to get them when they are not.
export async function chromiumAt(executable) {
  const { chromium } = await import('playwright-core').catch(() =>
    fail('playwright-core is missing: run `npm ci --prefix tests/browser` (see tests/browser/README.md)'));
  if (!fs.existsSync(executable)) fail(`no browser at ${executable}: install Debian's chromium`);
  return chromium;
}

/// Headless chromium at `executable` in the profile folder `profile`, a
/// window of `viewport`, nothing fetched in the background.
export function launch(chromium, executable, profile, viewport) {
  return chromium.launchPersistentContext(profile, {
    executablePath: executable,
    headless: true,
    viewport,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking',
           '--disable-component-update', '--disable-sync'],
  });
}

/// After `seconds`, says so, closes the browser (`context()`, when there
/// is one), calls `cleanUp` and exits 1: a hung page never hangs the test.
/// Returns the timer, for clearTimeout at the end.
export function watchdog(seconds, context, cleanUp) {
  return setTimeout(async () => {
    console.error(`FAIL: timed out after ${seconds} s`);
    try { await context()?.close(); } catch {}
    cleanUp();
    process.exit(1);
  }, Number(seconds) * 1000);
}

/// `binary args` started with its output kept as it comes (`out`, `err`);
/// `match(pattern)` waits for the first match in the output, rejected when
/// the process exits first.
export function started(binary, args, stdin = 'ignore', env = process.env) {
  const proc = spawn(binary, args, { stdio: [stdin, 'pipe', 'pipe'], env });
  const p = { proc, out: '', err: '' };
  proc.stdout.on('data', (d) => { p.out += d; });
  proc.stderr.on('data', (d) => { p.err += d; });
  p.match = (pattern) => new Promise((resolve, reject) => {
    const poll = setInterval(() => {
      const m = p.out.match(pattern);
      if (m) { clearInterval(poll); resolve(m); }
      if (proc.exitCode !== null) { clearInterval(poll); reject(new Error(args[0] + ' exited: ' + p.err)); }
    }, 50);
  });
  return p;
}
