// What each command of the extension runs: pure functions from a file and
// the settings to robotsim's arguments, and the problem matcher's pattern,
// kept apart from VS Code's API so that test/run-tests.js can run them
// against the real robotsim without VS Code.
'use strict';

const path = require('path');

// The pattern of package.json's problem matcher ("robotsim"): every
// robotsim diagnostic is `file:line:col: severity: message`.
const diagnosticPattern = /^(.+?):(\d+):(\d+): (error|warning|note): (.*)$/;

// The robot a program runs on: its own `; cell: NAME` line first (robotsim
// reads it too, so nothing is passed), else the robotsim.cell setting, else
// robotsim's default robot.
const cellDirective = /^[ \t]*;[ \t]*cell:[ \t]*(\S+)/im;

function directiveCell(text) {
  const m = cellDirective.exec(text || '');
  return m ? m[1] : '';
}

function libArgs(settings) {
  return (settings.lib || []).flatMap((dir) => ['--lib', dir]);
}

/**
 * Arguments common to run, check and animate: --cell (unless the file names
 * its cell), --lib, and --collisions when the setting is not check's default
 * (the language server's run honours the same setting).
 */
function cellArgs(settings, text) {
  const args = [];
  if (settings.cell && !directiveCell(text)) args.push('--cell', settings.cell);
  const collisions = settings.collisions && settings.collisions !== 'error' ? ['--collisions', settings.collisions] : [];
  return [...args, ...libArgs(settings), ...collisions];
}

/** The stimuli file beside a program (same name, .stim), when there is one. */
function stimuliBeside(file, exists) {
  const stim = file.replace(/\.rsp$/i, '.stim');
  return stim !== file && exists(stim) ? ['--stimuli', stim] : [];
}

/**
 * robotsim's arguments for `command` on `file`, whose text is `text`. `out`
 * is where render and animate write (a .png, a .html); `exists` tells
 * whether a file exists.
 */
function commandArgs(command, file, settings, { out, exists, text } = {}) {
  const has = exists || (() => false);
  const beside = (ext) => out || file.replace(/\.[^.]+$/, '') + ext;
  switch (command) {
    case 'run':
      return ['run', file, ...cellArgs(settings, text), ...stimuliBeside(file, has)];
    case 'check':
      return ['check', file, ...cellArgs(settings, text), ...stimuliBeside(file, has)];
    case 'test': // a program's cell comes from its own `; test:` / `; cell:` lines
      return ['test', file, ...libArgs(settings)];
    case 'render': // a description is drawn as it is; a program at the end of its run, on its cell
      if (/\.rsd$/i.test(file)) return ['render', file, ...libArgs(settings), '-o', beside('.png')];
      return ['render', directiveCell(text) || settings.cell || 'rhino-scara', '--program', file,
              ...libArgs(settings), ...stimuliBeside(file, has), '-o', beside('.png')];
    case 'animate':
      return ['animate', file, ...cellArgs(settings, text), ...stimuliBeside(file, has), '-o', beside('.html')];
    default:
      throw new Error(`unknown robotsim command '${command}'`);
  }
}

/**
 * The launch configuration "Debug robot program" starts for `file` (whose
 * text is `text`): `robotsim dap` launches it on the cell setting unless
 * the file names its own cell, with the stimuli file beside it and the
 * collisions setting (as Run and Check pass --collisions), stopping before
 * the first instruction.
 */
function debugConfiguration(file, settings, { exists, text } = {}) {
  const has = exists || (() => false);
  const config = { type: 'robotsim', request: 'launch', name: `Debug ${path.basename(file)}`, program: file,
                   stopOnEntry: true };
  if (settings.cell && !directiveCell(text)) config.cell = settings.cell;
  if ((settings.lib || []).length) config.lib = settings.lib;
  const stim = stimuliBeside(file, has);
  if (stim.length) config.stimuli = stim[1];
  if (settings.collisions && settings.collisions !== 'error') config.collisions = settings.collisions;
  return config;
}

/**
 * What the Go to Time command sends for what was typed: the custom request
 * `gotoTime`'s arguments (seconds as the terminal's goto-time takes them),
 * or, for text that is no time, `problem` (the input box shows it).
 */
function gotoTimeRequest(typed) {
  const time = String(typed || '').trim();
  if (!/^[0-9]+(\.[0-9]{1,6})?$/.test(time))
    return { problem: 'a time in seconds of simulated time, such as 2.5 (at most six decimals)' };
  return { command: 'gotoTime', arguments: { time } };
}

/** Diagnostics in robotsim's output, as the problem matcher reads them. */
function parseDiagnostics(text) {
  const found = [];
  for (const line of text.split(/\r?\n/)) {
    const m = diagnosticPattern.exec(line);
    if (m) found.push({ file: m[1], line: Number(m[2]), column: Number(m[3]), severity: m[4], message: m[5] });
  }
  return found;
}

/** The page a webview shows for an animation: robotsim's file, as written. */
function animationTitle(file) {
  return `Animate ${path.basename(file)}`;
}

module.exports = {
  diagnosticPattern, commandArgs, debugConfiguration, gotoTimeRequest, parseDiagnostics, animationTitle, directiveCell,
};
