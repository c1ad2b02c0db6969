// Tests of the VS Code extension's parts that run without VS Code (which
// cannot be installed here): the manifest, each command's robotsim
// arguments run against the real robotsim, the problem matcher on
// robotsim's real output, the snippets compiled by robotsim, the debugger's
// contribution and its launch configurations driving the real `robotsim
// dap`, the TextMate grammars (vscode-tmgrammar-test), the packaged .vsix
// (@vscode/vsce), how the extension finds robotsim, and its activation in
// a scripted session.
//   node test/run-tests.js --robotsim PATH
'use strict';

const test = require('node:test');
const assert = require('node:assert/strict');
const fs = require('fs');
const os = require('os');
const path = require('path');
const { spawnSync } = require('child_process');
const { commandArgs, debugConfiguration, parseDiagnostics, diagnosticPattern, directiveCell } = require('../src/commands');

const here = path.resolve(__dirname, '..');
const root = path.resolve(here, '..', '..');
const at = process.argv.indexOf('--robotsim');
const robotsim = at > 0 ? path.resolve(process.argv[at + 1]) : path.join(root, 'build', 'robotsim');
const manifest = JSON.parse(fs.readFileSync(path.join(here, 'package.json'), 'utf8'));
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'robotsim-vscode-'));

function run(args, options = {}) {
  const r = spawnSync(robotsim, args, { encoding: 'utf8', cwd: root, ...options });
  return { code: r.status, out: r.stdout, err: r.stderr };
}

// A snippet's body with every placeholder at its default (${1:x} -> x,
// ${1|a,b|} -> a, $0 -> nothing), as VS Code inserts it when Tab is pressed through.
function expand(body) {
  let text = body.join('\n');
  for (let i = 0; i < 5; ++i)
    text = text.replace(/\$\{\d+:([^{}]*)\}/g, '$1').replace(/\$\{\d+\|([^,|]*)[^}]*\|\}/g, '$1');
  return text.replace(/\$\d+/g, '');
}

test('every file the manifest names exists and parses', () => {
  const c = manifest.contributes;
  const ids = new Set(c.languages.map((l) => l.id));
  for (const l of c.languages) JSON.parse(fs.readFileSync(path.join(here, l.configuration), 'utf8'));
  for (const g of c.grammars) {
    assert.ok(ids.has(g.language), `grammar for unknown language ${g.language}`);
    const grammar = JSON.parse(fs.readFileSync(path.join(here, g.path), 'utf8'));
    assert.equal(grammar.scopeName, g.scopeName);
  }
  for (const s of c.snippets) {
    assert.ok(ids.has(s.language));
    JSON.parse(fs.readFileSync(path.join(here, s.path), 'utf8'));
  }
  assert.deepEqual(c.languages.map((l) => l.extensions[0]).sort(), ['.rsd', '.rsp', '.stim']);
  assert.ok(fs.existsSync(path.join(here, manifest.main)));
});

test('every command in the manifest is registered by the extension', () => {
  const source = fs.readFileSync(path.join(here, 'src', 'extension.js'), 'utf8');
  const listed = /for \(const command of \[([^\]]*)\]\)/.exec(source)[1].match(/'(\w+)'/g).map((s) => s.slice(1, -1));
  const registered = new Set([...listed.map((c) => `robotsim.${c}`),
    ...[...source.matchAll(/registerCommand\('([\w.]+)'/g)].map((m) => m[1])]);
  assert.deepEqual(manifest.contributes.commands.map((c) => c.command).sort(), [...registered].sort());
});

test('Run, Check and Test run robotsim on an example, with the stimuli file beside it', () => {
  const file = path.join(root, 'examples', 'pick_and_place.rsp');
  const settings = { cell: '', lib: [] };
  for (const command of ['run', 'check']) {
    const args = commandArgs(command, file, settings, { exists: fs.existsSync });
    assert.deepEqual(args.slice(-2), ['--stimuli', path.join(root, 'examples', 'pick_and_place.stim')]);
    const r = run(args);
    assert.equal(r.code, 0, `${command}: ${r.err}`);
  }
  const t = run(commandArgs('test', file, settings));
  assert.equal(t.code, 0, t.out + t.err);
  assert.match(t.out, /passed/);
});

test('the cell setting becomes --cell', () => {
  const args = commandArgs('check', path.join(root, 'examples', 'gantry_pick.rsp'), { cell: 'gantry-cell', lib: ['d'] });
  assert.deepEqual(args.slice(2), ['--cell', 'gantry-cell', '--lib', 'd']);
  const r = run(commandArgs('check', path.join(root, 'examples', 'gantry_pick.rsp'), { cell: 'gantry-cell', lib: [] }));
  assert.equal(r.code, 0, r.err);
});

test('the collisions setting becomes --collisions, and the default passes nothing', () => {
  const file = path.join(root, 'examples', 'mistakes', 'collision.rsp');
  assert.deepEqual(commandArgs('check', file, { collisions: 'error' }).slice(2), []);
  assert.deepEqual(commandArgs('check', file, { collisions: 'off' }).slice(2), ['--collisions', 'off']);
  assert.equal(run(commandArgs('check', file, { collisions: 'error' })).code, 1);  // the swing hits a block
  assert.equal(run(commandArgs('check', file, { collisions: 'off' })).code, 0);
});

test('a program\'s own ; cell: line wins over the setting', () => {
  const text = '; demo\n  ;  cell: gantry-cell\n        END\n';
  assert.equal(directiveCell(text), 'gantry-cell');
  assert.equal(directiveCell('        END ; cell: no\n'), '');
  assert.deepEqual(commandArgs('check', 'f.rsp', { cell: 'scara-pick' }, { text }), ['check', 'f.rsp']);
  assert.deepEqual(commandArgs('render', 'f.rsp', { cell: 'scara-pick' }, { text, out: 'o.png' }),
    ['render', 'gantry-cell', '--program', 'f.rsp', '-o', 'o.png']);
  assert.deepEqual(commandArgs('render', 'f.rsp', {}, { out: 'o.png' }), ['render', 'rhino-scara', '--program', 'f.rsp', '-o', 'o.png']);
});

// Which robotsim the extension runs (src/locate.js), with real folders and
// files: PATH first, then the install places, a non-executable file
// skipped, a path setting taken as it is; and the message when none holds it.
test('the extension finds robotsim on PATH, then in the install places, else says which setting to change', () => {
  const { locateRobotsim, installPlaces } = require('../src/locate');
  const base = fs.mkdtempSync(path.join(tmp, 'locate-'));
  const dir = (name) => { const d = path.join(base, name); fs.mkdirSync(d, { recursive: true }); return d; };
  const onPath = dir('on-path'), empty = dir('empty'), place = dir('place'), plain = dir('plain'), home = dir('home');
  fs.symlinkSync(robotsim, path.join(onPath, 'robotsim'));
  fs.writeFileSync(path.join(plain, 'robotsim'), 'not executable\n', { mode: 0o644 });
  fs.copyFileSync(robotsim, path.join(place, 'robotsim'));
  fs.chmodSync(path.join(place, 'robotsim'), 0o755);
  const env = (...dirs) => ({ PATH: dirs.join(path.delimiter) });

  assert.deepEqual(installPlaces('/home/u'), ['/usr/local/bin', '/usr/bin', '/home/u/.local/bin', '/opt/robotsim/bin']);
  // PATH first, in its order; a file without the execute bit is no command.
  let found = locateRobotsim('', { env: env(plain, onPath), home, places: [place] });
  assert.equal(found.path, path.join(onPath, 'robotsim'));
  // Not on PATH: the install places.
  found = locateRobotsim('', { env: env(empty, plain), home, places: [empty, place] });
  assert.equal(found.path, path.join(place, 'robotsim'));
  assert.equal(locateRobotsim('robotsim', { env: env(), home, places: [place] }).path, path.join(place, 'robotsim'));
  // What was found runs.
  const r = spawnSync(found.path, ['--help'], { encoding: 'utf8' });
  assert.equal(r.status, 0);
  assert.match(r.stdout, /robotsim: compile, check, run/);

  // Nowhere: the message names PATH, every place and the setting.
  const missing = locateRobotsim('', { env: env(empty, plain), home, places: installPlaces(home).map((p) => path.join(base, 'no' + p)) });
  assert.equal(missing.path, undefined);
  assert.match(missing.error, /^ROBOTSIM: the robotsim command is not on PATH nor in /);
  assert.match(missing.error, /set "robotsim\.path" \(Settings > Extensions > ROBOTSIM\) to the full path/);
  assert.deepEqual(missing.looked, [empty, plain, ...installPlaces(home).map((p) => path.join(base, 'no' + p))]
    .map((d) => path.join(d, 'robotsim')));
  // The default list of places is in the message when none is given.
  const defaultPlaces = locateRobotsim('no-such-robotsim-command', { env: env(empty), home });
  for (const p of installPlaces(home)) assert.ok(defaultPlaces.error.includes(p), p);

  // A path setting: as it is (absolute, ~/, relative to the workspace folder), never searched.
  assert.equal(locateRobotsim(path.join(place, 'robotsim'), { env: env(onPath) }).path, path.join(place, 'robotsim'));
  fs.mkdirSync(path.join(home, 'bin'));
  fs.symlinkSync(robotsim, path.join(home, 'bin', 'robotsim'));
  assert.equal(locateRobotsim('~/bin/robotsim', { env: env(), home }).path, path.join(home, 'bin', 'robotsim'));
  assert.equal(locateRobotsim('place/robotsim', { env: env(), home, base }).path, path.join(place, 'robotsim'));
  const gone = locateRobotsim(path.join(base, 'gone', 'robotsim'), { env: env(onPath), home });
  assert.match(gone.error, /robotsim\.path is .*gone\/robotsim, which does not exist: set "robotsim\.path"/);
  assert.match(locateRobotsim(path.join(plain, 'robotsim'), { env: env(onPath) }).error, /which is not an executable file/);
});

// The extension's activation in a scripted session: VS Code cannot run
// here, so its API is a recorder of what the extension asks of it (the
// real robotsim and the real folders otherwise). With robotsim on PATH the
// language server is `FOUND lsp`; without it, no server and the message
// with the button that opens robotsim.path.
function activateWith(PATH, setting) {
  const Module = require('module');
  const seen = { errors: [], servers: [], commands: [], opened: [] };
  const vscode = {
    workspace: {
      workspaceFolders: undefined,
      getConfiguration: () => ({ get: (key, fallback) => (key === 'path' ? setting : fallback) }),
      onDidChangeConfiguration: () => ({ dispose() {} }),
    },
    window: {
      showErrorMessage: (message, ...buttons) => {
        seen.errors.push({ message, buttons });
        return Promise.resolve(buttons[0]);
      },
    },
    commands: {
      registerCommand: (name) => { seen.commands.push(name); return { dispose() {} }; },
      executeCommand: (...args) => { seen.opened.push(args); return Promise.resolve(); },
    },
    debug: { registerDebugAdapterDescriptorFactory: () => ({}), registerDebugConfigurationProvider: () => ({}) },
    tasks: { registerTaskProvider: () => ({}) },
  };
  class LanguageClient {
    constructor(id, name, serverOptions) { seen.servers.push(serverOptions); }
    start() {}
    stop() {}
  }
  const load = Module._load;
  Module._load = function (request, ...rest) {
    if (request === 'vscode') return vscode;
    if (request === 'vscode-languageclient/node') return { LanguageClient, TransportKind: { stdio: 0 } };
    return load.call(this, request, ...rest);
  };
  const savedPath = process.env.PATH;
  const extensionFile = require.resolve('../src/extension');
  try {
    delete require.cache[extensionFile];
    process.env.PATH = PATH;
    require(extensionFile).activate({ subscriptions: [] });
  } finally {
    Module._load = load;
    process.env.PATH = savedPath;
    delete require.cache[extensionFile];
  }
  return seen;
}

test('activation starts robotsim lsp from PATH, or shows the message with the setting to open', async () => {
  const bin = fs.mkdtempSync(path.join(tmp, 'activate-'));
  fs.symlinkSync(robotsim, path.join(bin, 'robotsim'));
  const found = activateWith(bin, '');
  assert.deepEqual(found.errors, []);
  assert.deepEqual(found.servers.map((s) => [s.command, s.args]), [[path.join(bin, 'robotsim'), ['lsp']]]);
  assert.ok(found.commands.includes('robotsim.run'));

  const { installPlaces } = require('../src/locate');
  const installed = installPlaces(os.homedir()).some((d) => fs.existsSync(path.join(d, 'robotsim')));
  const lost = activateWith(fs.mkdtempSync(path.join(tmp, 'activate-empty-')), installed ? '/nonexistent/robotsim' : '');
  assert.deepEqual(lost.servers, []);
  assert.equal(lost.errors.length, 1);
  assert.match(lost.errors[0].message, /robotsim\.path/);
  assert.deepEqual(lost.errors[0].buttons, ['Open Settings']);
  await new Promise((resolve) => setImmediate(resolve));
  assert.deepEqual(lost.opened, [['workbench.action.openSettings', 'robotsim.path']]);
  assert.ok(lost.commands.includes('robotsim.run'), 'the commands are there, to say the same when used');
});

test('Render writes a PNG and Animate a self-contained HTML page', () => {
  const file = path.join(root, 'examples', 'first_moves.rsp');
  const png = path.join(tmp, 'first_moves.png');
  const r = run(commandArgs('render', file, { cell: 'scara-pick' }, { out: png }));
  assert.equal(r.code, 0, r.err);
  assert.deepEqual([...fs.readFileSync(png).subarray(0, 8)], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
  const html = path.join(tmp, 'first_moves.html');
  const a = run(commandArgs('animate', file, { cell: 'scara-pick' }, { out: html }));
  assert.equal(a.code, 0, a.err);
  const page = fs.readFileSync(html, 'utf8');
  assert.match(page, /^<!DOCTYPE html>/i);
  assert.match(page, /<script>/);
  assert.doesNotMatch(page, /<script[^>]+src=|<link[^>]+href="http/, 'the webview page must need no network');
});

test('the problem matcher reads robotsim errors at their file, line and column', () => {
  const text = '        MOVE 10 0 0 0 0\n        GOTO nowhere\n        END\n';
  const file = path.join(tmp, 'broken.rsp');
  fs.writeFileSync(file, text);
  const r = run(commandArgs('check', file, {}));
  assert.notEqual(r.code, 0);
  const found = parseDiagnostics(r.err);
  assert.ok(found.length >= 1, r.err);
  // Independently: "nowhere" is on line 2, at the column after its 13 characters of prefix.
  const line = text.split('\n').findIndex((l) => l.includes('nowhere')) + 1;
  const column = text.split('\n')[line - 1].indexOf('nowhere') + 1;
  assert.deepEqual([found[0].file, found[0].line, found[0].column, found[0].severity], [file, line, column, 'error']);
  assert.match(found[0].message, /nowhere/);
  assert.equal(manifest.contributes.problemMatchers[0].pattern.regexp, diagnosticPattern.source);
});

// Every program snippet, expanded with its defaults, in one program that
// robotsim check compiles and robotsim test runs against the expectation
// the Expectation snippet writes (its first choice); the other choices too.
test('the snippets expand to programs robotsim check and robotsim test accept', () => {
  const snippets = JSON.parse(fs.readFileSync(path.join(here, 'snippets', 'robotsim-program.json'), 'utf8'));
  const used = ['New program', 'Counted loop', 'Wait for a part', 'Subroutine', 'Expectation'];
  assert.deepEqual(Object.keys(snippets).sort(), [...used].sort(), 'a new snippet needs its place below');
  const [program, loop, wait, sub, expectation] = used.map((name) => expand(snippets[name].body));
  // The Wait snippet waits for input 1: the run gets it at 1 s.
  const whole = program.replace(/^\s*END$/m, `${loop}\n${wait}\n        GOSUB name\n        END\n${sub}`) +
    `\n; test: input 1=ON@1\n${expectation}\n`;
  assert.match(expectation, /^; expect: finished$/);
  const file = path.join(tmp, 'snippets.rsp');
  fs.writeFileSync(file, whole);
  const c = run(['check', file, '--input', '1=ON@1']);
  assert.equal(c.code, 0, whole + '\n' + c.err);
  const t = run(['test', file]);
  assert.equal(t.code, 0, whole + '\n' + t.out + t.err);
  assert.match(t.out, /1 passed/);
  // Each choice of the Expectation snippet is an expectation robotsim test reads (and this program meets).
  const choices = /\$\{1\|([^|]*)\|\}/.exec(snippets.Expectation.body.join('\n'))[1].split(',');
  for (const choice of choices) {
    fs.writeFileSync(file, whole.replace(expectation, `; expect: ${choice}`));
    const r = run(['test', file]);
    assert.equal(r.code, 0, `expect: ${choice}\n${r.out}${r.err}`);
  }
  const desc = JSON.parse(fs.readFileSync(path.join(here, 'snippets', 'robotsim-description.json'), 'utf8'));
  const rsd = path.join(tmp, 'snippets.rsd');
  fs.writeFileSync(rsd, expand(desc.Link.body) + '\n' + expand(desc.Workcell.body) + '\n');
  const d = run(commandArgs('render', rsd, {}, { out: path.join(tmp, 'cell.png') }));
  assert.equal(d.code, 0, d.err);
});

// A Debug Adapter Protocol session with `robotsim dap`: the requests framed
// as VS Code frames them, every message it answered, in order.
function dapSession(requests) {
  const frame = (m) => { const body = JSON.stringify(m); return `Content-Length: ${Buffer.byteLength(body)}\r\n\r\n${body}`; };
  const input = requests.map((r, i) => frame({ seq: i + 1, type: 'request', ...r })).join('');
  const r = spawnSync(robotsim, ['dap'], { input, cwd: root, timeout: 30000 });
  assert.equal(r.status, 0, String(r.stderr));
  const messages = [];
  let rest = r.stdout;
  while (rest.length) {
    const header = rest.indexOf('\r\n\r\n');
    const length = Number(/Content-Length: (\d+)/.exec(rest.subarray(0, header).toString())[1]);
    messages.push(JSON.parse(rest.subarray(header + 4, header + 4 + length).toString()));
    rest = rest.subarray(header + 4 + length);
  }
  return messages;
}

test('the debugger is contributed: type robotsim, breakpoints in programs, snippets that parse', () => {
  const [d] = manifest.contributes.debuggers;
  assert.equal(d.type, 'robotsim');
  assert.deepEqual(d.languages, ['robotsim-program']);
  assert.deepEqual(manifest.contributes.breakpoints, [{ language: 'robotsim-program' }]);
  // No attribute is required: a program, or a cell whose robots have programs (`programs`: one thread each).
  assert.equal(d.configurationAttributes.launch.required, undefined);
  const known = Object.keys(d.configurationAttributes.launch.properties);
  assert.ok(known.includes('program') && known.includes('cell') && known.includes('programs'));
  for (const s of d.configurationSnippets) {
    assert.equal(s.body.type, 'robotsim');
    assert.equal(s.body.request, 'launch');
    for (const key of Object.keys(s.body)) assert.ok(['type', 'request', 'name', ...known].includes(key), key);
  }
  for (const c of d.initialConfigurations) assert.equal(c.type, 'robotsim');
  assert.ok(manifest.activationEvents.includes('onDebugResolve:robotsim'));
  const source = fs.readFileSync(path.join(here, 'src', 'extension.js'), 'utf8');
  // The adapter is the robotsim the extension finds (src/locate.js), run as `robotsim dap`.
  assert.match(source, /const robotsim = robotsimCommand\(settings\(\)\.path\);\s+return robotsim \? new vscode\.DebugAdapterExecutable\(robotsim, \['dap'\]\)/);
});

test('Debug robot program: its launch configuration', () => {
  const file = path.join(root, 'examples', 'pick_and_place.rsp');
  assert.deepEqual(debugConfiguration(file, { cell: 'scara-pick', lib: [] }, { exists: fs.existsSync }), {
    type: 'robotsim', request: 'launch', name: 'Debug pick_and_place.rsp', program: file, stopOnEntry: true,
    cell: 'scara-pick', stimuli: path.join(root, 'examples', 'pick_and_place.stim'),
  });
  const own = debugConfiguration('f.rsp', { cell: 'scara-pick', lib: ['d'] }, { text: '; cell: gantry-cell\n' });
  assert.equal(own.cell, undefined);
  assert.deepEqual(own.lib, ['d']);
});

test('robotsim dap runs the launch configuration: a breakpoint and a step back', () => {
  const file = path.join(root, 'examples', 'nested_subroutines.rsp');
  const config = debugConfiguration(file, { cell: '', lib: [] }, { exists: fs.existsSync });
  // Line 38 is grip's first line: the gripper closes there, first after
  // 0.5 s (pick slides down first), and GRIPS counts the grips.
  const messages = dapSession([
    { command: 'initialize', arguments: { adapterID: 'robotsim' } },
    { command: 'launch', arguments: { ...config, stopOnEntry: false } },
    { command: 'setBreakpoints', arguments: { source: { path: file }, breakpoints: [{ line: 38 }] } },
    { command: 'configurationDone' },
    { command: 'evaluate', arguments: { expression: 'clock' } },
    { command: 'stepBack', arguments: { threadId: 1 } },
    { command: 'stackTrace', arguments: { threadId: 1 } },
    { command: 'disconnect' },
  ]);
  const initialize = messages.find((m) => m.type === 'response' && m.command === 'initialize');
  assert.equal(initialize.body.supportsStepBack, true);
  assert.ok(messages.every((m) => m.type !== 'response' || m.success), JSON.stringify(messages));
  const stops = messages.filter((m) => m.event === 'stopped').map((m) => m.body.reason);
  assert.deepEqual(stops, ['breakpoint', 'step']);
  assert.equal(messages.find((m) => m.command === 'evaluate').body.result, '0.500 s');
  const trace = messages.find((m) => m.command === 'stackTrace').body.stackFrames;
  assert.equal(trace[0].line, 28);  // back before GOSUB grip
  assert.equal(trace[0].source.path, file);
});

test('the grammars pass their token tests', () => {
  const bin = path.join(here, 'node_modules', '.bin', 'vscode-tmgrammar-test');
  const grammars = manifest.contributes.grammars.flatMap((g) => ['-g', path.join(here, g.path)]);
  const r = spawnSync(bin, [...grammars, path.join(here, 'test', 'grammar', '*.test.*')], { encoding: 'utf8' });
  assert.equal(r.status, 0, r.stdout + r.stderr);
  assert.equal((r.stdout.match(/run successfuly/g) || []).length, 3, r.stdout);
});

test('package.sh builds a .vsix with the server client and without the tests', () => {
  // Into a temporary directory: the source tree stays as it was.
  const vsix = path.join(tmp, `robotsim-${manifest.version}.vsix`);
  const r = spawnSync('bash', [path.join(here, 'package.sh'), vsix], { encoding: 'utf8' });
  assert.equal(r.status, 0, r.stdout + r.stderr);
  assert.match(r.stdout, new RegExp(`wrote ${vsix.replace(/[.]/g, '\\.')}`));
  const unzip = spawnSync('unzip', ['-Z1', vsix], { encoding: 'utf8' });
  assert.equal(unzip.status, 0, `unzip -Z1 (Debian's unzip): ${unzip.error || unzip.stderr}`);
  const list = unzip.stdout.split('\n');
  for (const f of ['extension/package.json', 'extension/src/extension.js', 'extension/src/commands.js',
                   'extension/syntaxes/robotsim-program.tmLanguage.json',
                   'extension/node_modules/vscode-languageclient/package.json'])
    assert.ok(list.includes(f), `${f} missing from the .vsix`);
  assert.ok(!list.some((f) => f.startsWith('extension/test/')), 'tests packaged');
  fs.rmSync(vsix);
});
