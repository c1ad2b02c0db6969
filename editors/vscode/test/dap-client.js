// `robotsim dap` through a Debug Adapter Protocol client robotsim did not
// write: the DebugClient of @vscode/debugadapter-testsupport (pinned in
// package-lock.json), the library VS Code's own debug adapters are tested
// with. It starts `robotsim dap`, frames and numbers the requests, and
// rejects a request that gets success false. What each test expects is
// worked out from the programs' text and motor speeds (the times of
// examples/nested_subroutines.rsp are in its comments), and what the
// terminal debugger prints is asked of `robotsim debug` itself.
//   node test/dap-client.js --robotsim PATH
'use strict';

const test = require('node:test');
const assert = require('node:assert/strict');
const fs = require('fs');
const os = require('os');
const path = require('path');
const { spawnSync } = require('child_process');
const { DebugClient } = require('@vscode/debugadapter-testsupport');
const { debugConfiguration, gotoTimeRequest } = require('../src/commands');

const here = path.resolve(__dirname, '..');
const root = path.resolve(here, '..', '..');
const at = process.argv.indexOf('--robotsim');
const robotsim = at > 0 ? path.resolve(process.argv[at + 1]) : path.join(root, 'build', 'robotsim');
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'robotsim-dap-client-'));
const nested = path.join(root, 'examples', 'nested_subroutines.rsp');
const nestedLines = fs.readFileSync(nested, 'utf8').split('\n');
const lineOf = (text) => nestedLines.findIndex((l) => l.startsWith(text)) + 1;  // 1-based

// A client on a fresh `robotsim dap` (DebugClient spawns "runtime executable").
async function client() {
  const dc = new DebugClient(robotsim, 'dap', 'robotsim', { cwd: root });
  dc.defaultTimeout = 30000;  // a loaded machine
  await dc.start();
  dc.events = [];
  for (const name of ['stopped', 'exited', 'terminated', 'output', 'initialized'])
    dc.on(name, (e) => dc.events.push(e));
  return dc;
}

// initialize, launch (the `initialized` event after its response), the
// breakpoints, configurationDone; the first stop.
async function started(dc, launch, { initialize = {}, breakpoints = async () => {} } = {}) {
  const init = await dc.initializeRequest({ adapterID: 'robotsim', pathFormat: 'path', ...initialize });
  await Promise.all([dc.waitForEvent('initialized'), dc.launchRequest(launch)]);
  await breakpoints(dc);
  const [stop] = await Promise.all([dc.waitForEvent('stopped'), dc.configurationDoneRequest()]);
  return { capabilities: init.body, stop };
}

// A request that moves the run, and the stop that follows its response.
async function moved(dc, request) {
  const [stop] = await Promise.all([dc.waitForEvent('stopped'), request]);
  return stop;
}

async function evaluate(dc, expression) {
  return (await dc.evaluateRequest({ expression, context: 'repl' })).body;
}

async function top(dc) {
  return (await dc.stackTraceRequest({ threadId: 1 })).body.stackFrames[0];
}

async function scope(dc, name) {
  const scopes = (await dc.scopesRequest({ frameId: 0 })).body.scopes;
  return scopes.find((s) => s.name === name);
}

// What the terminal debugger prints after these commands (its last answer).
function terminal(program, commands, args = []) {
  const r = spawnSync(robotsim, ['debug', program, ...args], { input: commands.join('\n') + '\n', encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  return r.stdout;
}

test('lines and columns from 0 when the client counts so, in breakpoints and the stack trace', async () => {
  const dc = await client();
  try {
    const grip = lineOf('grip:');  // 38
    let answer;
    const { capabilities, stop } = await started(dc, { program: nested }, {
      initialize: { linesStartAt1: false, columnsStartAt1: false },
      breakpoints: async (c) => {
        answer = (await c.setBreakpointsRequest({ source: { path: nested }, breakpoints: [{ line: grip - 1 }] })).body;
      },
    });
    assert.equal(capabilities.supportsFunctionBreakpoints, true);
    assert.deepEqual(answer.breakpoints.map((b) => [b.verified, b.line]), [[true, grip - 1]]);
    assert.equal(stop.body.reason, 'breakpoint');
    const frame = await top(dc);
    assert.equal(frame.line, grip - 1);
    assert.equal(frame.column, nestedLines[grip - 1].indexOf('MOVE'));  // 0-based: the instruction's first letter
    // The GOSUB frames too: pick's GOSUB grip, 0-based.
    const frames = (await dc.stackTraceRequest({ threadId: 1 })).body.stackFrames;
    assert.equal(frames[1].line, lineOf('        GOSUB grip') - 1);
  } finally {
    await dc.stop();
  }
});

test('labels as function breakpoints: one answer per breakpoint, reason function breakpoint', async () => {
  const dc = await client();
  try {
    let answer;
    const { stop } = await started(dc, { program: nested }, {
      breakpoints: async (c) => {
        answer = (await c.setFunctionBreakpointsRequest({
          breakpoints: [{ name: 'pick' }, { name: 'nowhere' }, { name: 'GRIP', hitCondition: '2' }],
        })).body.breakpoints;
      },
    });
    assert.equal(answer.length, 3);
    assert.deepEqual([answer[0].verified, answer[0].line], [true, lineOf('pick:')]);
    assert.equal(answer[1].verified, false);
    assert.match(answer[1].message, /nowhere/);
    assert.deepEqual([answer[2].verified, answer[2].line], [true, lineOf('grip:')]);
    // pick at once (0 s); its grip is only the first, so on to the second serve's pick:
    // after serve (4.2 s) and the 1 s turn, 5.2 s; then the second grip, 0.5 s later.
    assert.equal(stop.body.reason, 'function breakpoint');
    assert.deepEqual(stop.body.hitBreakpointIds, [answer[0].id]);
    assert.equal((await top(dc)).line, lineOf('pick:'));
    assert.equal((await evaluate(dc, 'clock')).result, '0.000 s');
    let next = await moved(dc, dc.continueRequest({ threadId: 1 }));
    assert.equal(next.body.reason, 'function breakpoint');
    assert.equal((await evaluate(dc, 'clock')).result, '5.200 s');
    next = await moved(dc, dc.continueRequest({ threadId: 1 }));
    assert.deepEqual(next.body.hitBreakpointIds, [answer[2].id]);
    assert.equal((await evaluate(dc, 'clock')).result, '5.700 s');
    // A new set replaces the old one: none left, the run goes to its end.
    assert.deepEqual((await dc.setFunctionBreakpointsRequest({ breakpoints: [] })).body.breakpoints, []);
    await Promise.all([dc.waitForEvent('terminated'), dc.continueRequest({ threadId: 1 })]);
  } finally {
    await dc.stop();
  }
});

test('at the end: exited, then terminated', async () => {
  const dc = await client();
  try {
    await dc.initializeRequest();
    await Promise.all([dc.waitForEvent('initialized'), dc.launchRequest({ program: nested, stopOnEntry: false })]);
    await Promise.all([dc.waitForEvent('terminated'), dc.configurationDoneRequest()]);
    const order = dc.events.map((e) => e.event).filter((e) => e === 'exited' || e === 'terminated');
    assert.deepEqual(order, ['exited', 'terminated']);
    assert.equal(dc.events.find((e) => e.event === 'exited').body.exitCode, 0);
  } finally {
    await dc.stop();
  }
});

test('variables paged by start and count', async () => {
  const dc = await client();
  try {
    await started(dc, { program: nested, stopOnEntry: true });
    const io = await scope(dc, 'Inputs/Outputs');
    assert.equal(io.namedVariables, 16);
    const all = (await dc.variablesRequest({ variablesReference: io.variablesReference })).body.variables;
    assert.deepEqual(all.map((v) => v.name).slice(0, 2), ['in 1', 'in 2']);
    const page = (await dc.variablesRequest({ variablesReference: io.variablesReference, start: 3, count: 4 })).body;
    assert.deepEqual(page.variables.map((v) => v.name), ['in 4', 'in 5', 'in 6', 'in 7']);
    const tail = (await dc.variablesRequest({ variablesReference: io.variablesReference, start: 14 })).body;
    assert.deepEqual(tail.variables.map((v) => v.name), ['out 7', 'out 8']);
    const none = (await dc.variablesRequest({ variablesReference: io.variablesReference, start: 99, count: 2 })).body;
    assert.deepEqual(none.variables, []);
  } finally {
    await dc.stop();
  }
});

test('a launch on a cell that does not exist names the cell', async () => {
  const dc = await client();
  try {
    await dc.initializeRequest();
    await assert.rejects(dc.launchRequest({ program: nested, cell: 'no-such-cell' }),
      (e) => /cannot debug .*nested_subroutines\.rsp: cell 'no-such-cell': /.test(e.message));
  } finally {
    await dc.stop();
  }
});

test('setVariable: a variable from now on (replayed going back and forth), and an input as set input', async () => {
  const dc = await client();
  try {
    const add = lineOf('        ADD GRIPS 1');
    await started(dc, { program: nested }, {
      breakpoints: (c) => c.setBreakpointsRequest({ source: { path: nested }, breakpoints: [{ line: add }] }),
    });
    const vars = await scope(dc, 'Variables');
    assert.deepEqual((await dc.variablesRequest({ variablesReference: vars.variablesReference })).body.variables
      .map((v) => [v.name, v.value]), [['GRIPS', '0']]);
    const set = await dc.setVariableRequest({ variablesReference: vars.variablesReference, name: 'GRIPS', value: '10' });
    assert.equal(set.body.value, '10');
    await moved(dc, dc.nextRequest({ threadId: 1 }));
    assert.equal((await evaluate(dc, 'GRIPS')).result, '11');
    // Back before the ADD and over it again: the change is replayed.
    await moved(dc, dc.stepBackRequest({ threadId: 1 }));
    assert.equal((await evaluate(dc, 'GRIPS')).result, '10');
    await moved(dc, dc.nextRequest({ threadId: 1 }));
    assert.equal((await evaluate(dc, 'GRIPS')).result, '11');
    await assert.rejects(dc.setVariableRequest({ variablesReference: vars.variablesReference, name: 'GRIPS', value: 'x' }),
      /'x' is not a whole number/);
    await assert.rejects(dc.setVariableRequest({ variablesReference: vars.variablesReference, name: 'NOPE', value: '1' }),
      /'NOPE' is not a variable of the program/);
    const motors = await scope(dc, 'Motors');
    await assert.rejects(dc.setVariableRequest({ variablesReference: motors.variablesReference, name: 'A', value: '1' }),
      /only variables and inputs can be set/);
  } finally {
    await dc.stop();
  }

  // An input: the program waits for input 1, which nothing turns on but the client.
  const waits = path.join(tmp, 'waits.rsp');
  fs.writeFileSync(waits, '        WAITFOR 1 ON\n        SET N 1\n        END\n');
  const dc2 = await client();
  try {
    await started(dc2, { program: waits, stopOnEntry: true });
    const io = await scope(dc2, 'Inputs/Outputs');
    const on = await dc2.setVariableRequest({ variablesReference: io.variablesReference, name: 'in 1', value: 'on' });
    assert.equal(on.body.value, 'on');
    // With what set it, and when (the session stands at its start).
    assert.equal((await evaluate(dc2, 'in 1')).result, 'on (since 0.000 s: set by the debugger)');
    await assert.rejects(dc2.setVariableRequest({ variablesReference: io.variablesReference, name: 'out 1', value: 'on' }),
      /only inputs can be set/);
    await Promise.all([dc2.waitForEvent('exited'), dc2.continueRequest({ threadId: 1 })]);
    assert.equal(dc2.events.find((e) => e.event === 'exited').body.exitCode, 0);  // not a deadlock
  } finally {
    await dc2.stop();
  }
  // Without it, the same program deadlocks (the exception stop).
  const dc3 = await client();
  try {
    const { stop } = await started(dc3, { program: waits });
    assert.equal(stop.body.reason, 'exception');
    assert.match(stop.body.text, /deadlock/);
  } finally {
    await dc3.stop();
  }
});

test('evaluate takes what the terminal\'s print takes, and answers what it prints', async () => {
  const program = path.join(root, 'examples', 'gantry_pick.rsp');
  const dc = await client();
  try {
    await started(dc, { program, cell: 'gantry-cell', stopOnEntry: true });
    await moved(dc, dc.stepInRequest({ threadId: 1 }));
    await moved(dc, dc.stepInRequest({ threadId: 1 }));
    const printed = terminal(program, ['step', 'step', 'print tcp', 'print motors', 'print objects'], ['--cell', 'gantry-cell']);
    const tcp = await evaluate(dc, 'tcp');
    assert.ok(printed.includes(`tcp = ${tcp.result}\n`), `${tcp.result} not in\n${printed}`);
    const motors = await evaluate(dc, 'motors');
    assert.notEqual(motors.variablesReference, 0);  // the Motors scope, to open
    for (const pair of motors.result.split(', ')) assert.ok(printed.includes(`${pair}\n`), `${pair} not in\n${printed}`);
    const objects = await evaluate(dc, 'objects');
    assert.notEqual(objects.variablesReference, 0);
    const names = [...printed.matchAll(/^(\d+) (\S+) at \(/gm)].map((m) => `${m[1]} ${m[2]}`);
    assert.ok(names.length > 0, printed);
    assert.deepEqual(objects.result.split(', ').map((s) => s.replace(/ \(held\)$/, '')), names);
    assert.match((await evaluate(dc, 'io')).result, /^inputs 1-8:( [01]){8}, outputs 1-8:( [01]){8}$/);
    assert.equal((await evaluate(dc, 'output 1')).result, 'off');
    assert.match((await evaluate(dc, 'clock')).result, /^\d+\.\d{3} s$/);
    await assert.rejects(evaluate(dc, 'nonsense'), /'nonsense' is not a variable of the program/);
  } finally {
    await dc.stop();
  }
  // Without a workcell there is no tool centre point: said, not made up.
  const bare = await client();
  try {
    await started(bare, { program: nested, stopOnEntry: true });
    await assert.rejects(evaluate(bare, 'tcp'), /no tool centre point/);
    assert.equal((await evaluate(bare, 'GRIPS')).result, '0');
    assert.equal((await evaluate(bare, 'variables')).result, 'GRIPS = 0');
  } finally {
    await bare.stop();
  }
});

test('watches as data breakpoints: dataBreakpointInfo, setDataBreakpoints, reason data breakpoint', async () => {
  const dc = await client();
  try {
    await started(dc, { program: nested, stopOnEntry: true });
    const vars = await scope(dc, 'Variables');
    const info = (await dc.dataBreakpointInfoRequest({ variablesReference: vars.variablesReference, name: 'GRIPS' })).body;
    assert.equal(info.dataId, 'GRIPS');
    assert.deepEqual(info.accessTypes, ['write']);
    const motors = await scope(dc, 'Motors');
    const byLetter = (await dc.dataBreakpointInfoRequest({ variablesReference: motors.variablesReference, name: 'E' })).body;
    assert.equal(byLetter.dataId, 'E');
    const expression = (await dc.dataBreakpointInfoRequest({ name: 'output 3' })).body;
    assert.equal(expression.dataId, 'out 3');
    const clock = await scope(dc, 'Clock');
    const none = (await dc.dataBreakpointInfoRequest({ variablesReference: clock.variablesReference, name: 'time' })).body;
    assert.equal(none.dataId, null);
    assert.match(none.description, /cannot be watched/);

    const set = (await dc.setDataBreakpointsRequest({
      breakpoints: [{ dataId: info.dataId, accessType: 'write' }, { dataId: 'NOPE' }, { dataId: 'E', accessType: 'read' }],
    })).body.breakpoints;
    assert.deepEqual(set.map((b) => b.verified), [true, false, false]);
    // GRIPS changes at the first ADD: after pick's slide (0.5 s) and grip's close (0.6 s).
    const stop = await moved(dc, dc.continueRequest({ threadId: 1 }));
    assert.equal(stop.body.reason, 'data breakpoint');
    assert.deepEqual(stop.body.hitBreakpointIds, [set[0].id]);
    assert.match(stop.body.description, /GRIPS changed from 0 to 1/);
    assert.equal((await evaluate(dc, 'clock')).result, '1.100 s');
    // Replaced by an empty set: the run goes to its end.
    await dc.setDataBreakpointsRequest({ breakpoints: [] });
    await Promise.all([dc.waitForEvent('terminated'), dc.continueRequest({ threadId: 1 })]);
  } finally {
    await dc.stop();
  }
});

test('goto-time: the custom request the Go to Time command sends, forwards and back', async () => {
  assert.deepEqual(gotoTimeRequest(' 2.5 '), { command: 'gotoTime', arguments: { time: '2.5' } });
  assert.ok(gotoTimeRequest('soon').problem);
  assert.ok(gotoTimeRequest('-1').problem);
  const dc = await client();
  try {
    const config = debugConfiguration(nested, { cell: '', lib: [] }, { exists: fs.existsSync });
    await started(dc, config);
    const forwards = gotoTimeRequest('2.5');
    // 2.5 s: drop's slide down, from 2.1 s (pick 1.6 s, the elbow 0.5 s) to 2.6 s.
    const stop = await moved(dc, dc.customRequest(forwards.command, forwards.arguments));
    assert.equal(stop.body.reason, 'goto');
    assert.equal((await evaluate(dc, 'clock')).result, '2.500 s');
    assert.equal((await top(dc)).line, lineOf('drop:'));
    const back = gotoTimeRequest('0.25');
    await moved(dc, dc.customRequest(back.command, back.arguments));
    assert.equal((await evaluate(dc, 'clock')).result, '0.250 s');
    assert.equal((await top(dc)).line, lineOf('pick:'));
    await assert.rejects(dc.customRequest('gotoTime', { time: 'soon' }));
    // Past the end: the end, and still a session to go back in.
    const past = await moved(dc, dc.customRequest('gotoTime', { time: 60 }));
    assert.equal(past.body.reason, 'goto');
    assert.match(past.body.description, /the program ended/);
    await moved(dc, dc.customRequest('gotoTime', { time: 1 }));
    assert.equal((await evaluate(dc, 'clock')).result, '1.000 s');
  } finally {
    await dc.stop();
  }
});

test('Debug robot program passes the collisions setting, and the schema has it', () => {
  const manifest = JSON.parse(fs.readFileSync(path.join(here, 'package.json'), 'utf8'));
  const attribute = manifest.contributes.debuggers[0].configurationAttributes.launch.properties.collisions;
  const setting = manifest.contributes.configuration.properties['robotsim.collisions'];
  assert.deepEqual(attribute.enum, setting.enum);
  assert.equal(attribute.default, setting.default);
  const file = path.join(root, 'examples', 'mistakes', 'collision.rsp');
  assert.equal(debugConfiguration(file, { collisions: 'warn' }).collisions, 'warn');
  assert.equal(debugConfiguration(file, { collisions: 'error' }).collisions, undefined);  // the adapter's default
});

test('with collisions warn the run goes on past the collision, and the Collision filter stops there', async () => {
  const file = path.join(root, 'examples', 'mistakes', 'collision.rsp');
  const config = debugConfiguration(file, { collisions: 'warn', cell: '', lib: [] }, { exists: fs.existsSync });
  const dc = await client();
  try {
    const { stop } = await started(dc, { ...config, stopOnEntry: false }, {
      breakpoints: (c) => c.setExceptionBreakpointsRequest({ filters: ['collision'] }),
    });
    assert.equal(stop.body.reason, 'exception');
    assert.match(stop.body.text, /hits/);
  } finally {
    await dc.stop();
  }
});

test('a device breakpoint: a sensor\'s edge stops the run, the stop says when, going back restores the devices', async () => {
  // examples/adept_production.rsp on adept-cell: the infeed carries the
  // first block into the beam at 1.100 s (the program's comments; the
  // terminal debugger's `break sensor eye on` stops there too).
  const program = path.join(root, 'examples', 'adept_production.rsp');
  const dc = await client();
  try {
    let answer;
    const { stop } = await started(dc, { program, cell: 'adept-cell' }, {
      breakpoints: async (c) => {
        answer = (await c.setFunctionBreakpointsRequest({
          breakpoints: [{ name: 'sensor eye on' }, { name: 'sensor nosuch' }],
        })).body.breakpoints;
      },
    });
    assert.equal(answer[0].verified, true);
    assert.equal(answer[1].verified, false);
    assert.match(answer[1].message, /eye/);  // names the cell's sensors
    assert.equal(stop.body.reason, 'function breakpoint');
    assert.match(stop.body.description, /sensor eye ON at 1\.100 s/);
    const printed = terminal(program, ['break sensor eye on', 'continue', 'print devices'], ['--cell', 'adept-cell']);
    assert.match(printed, /sensor eye {9}ON, turned ON 1 time/);
    assert.match((await evaluate(dc, 'devices')).result, /^sensor eye = ON, turned ON 1 time, /);
    // One instruction back: before the one during which the beam broke, the
    // sensor off and never on, as it was then.
    await moved(dc, dc.stepBackRequest({ threadId: 1 }));
    assert.match((await evaluate(dc, 'devices')).result, /^sensor eye = OFF, turned ON 0 times, /);
  } finally {
    await dc.stop();
  }
});

test('a cell of two robots: a thread per robot, every stop stops both, step back for the whole cell', async () => {
  // examples/two_robots/interlock.rsd: right waits for left's output 1
  // (on at 2 s) and then makes its two 1 s moves; right's line 6 is its
  // first MOVE, reached at 2 s, while left waits at its line 10.
  const two = path.join(root, 'examples', 'two_robots');
  const dc = await client();
  try {
    const { stop } = await started(dc, {
      cell: path.join(two, 'interlock.rsd'),
      programs: { left: path.join(two, 'left.rsp'), right: path.join(two, 'right.rsp') },
    }, {
      breakpoints: async (c) => {
        await c.setBreakpointsRequest({ source: { path: path.join(two, 'right.rsp') }, breakpoints: [{ line: 6 }] });
      },
    });
    const threads = (await dc.threadsRequest()).body.threads;
    assert.deepEqual(threads.map((t) => t.name), ['left', 'right']);
    assert.equal(stop.body.reason, 'breakpoint');
    assert.equal(stop.body.allThreadsStopped, true);
    const right = threads[1].id, left = threads[0].id;
    assert.equal(stop.body.threadId, right);
    const rightTop = (await dc.stackTraceRequest({ threadId: right })).body.stackFrames[0];
    const leftTop = (await dc.stackTraceRequest({ threadId: left })).body.stackFrames[0];
    assert.deepEqual([rightTop.source.name, rightTop.line], ['right.rsp', 6]);
    assert.deepEqual([leftTop.source.name, leftTop.line], ['left.rsp', 10]);
    const stepped = await moved(dc, dc.stepInRequest({ threadId: right }));
    assert.equal(stepped.body.allThreadsStopped, true);
    const back = await moved(dc, dc.stepBackRequest({ threadId: right }));
    assert.equal(back.body.threadId, right);
    const again = (await dc.stackTraceRequest({ threadId: right })).body.stackFrames[0];
    assert.equal(again.line, 6);
  } finally {
    await dc.stop();
  }
});

// A cell of several robots with devices (tests/debug/programs/belt_pair.rsd,
// its times worked out at the top of tests/debug/test_debug_cell_devices.cpp):
// the beam's ON edge at 1.5 s, a device function breakpoint, stops the whole
// cell with left's second MOVE at 2 s; the block is then 200 on from x -740;
// left's TURNS, a data breakpoint, changes with its ADD at 4.25 s; going back
// to the beam's stop shows the devices as they were.
test('a cell of several robots with devices: threads, device and data breakpoints, the Devices scope', async () => {
  const two = path.join(root, 'examples', 'two_robots');
  const cell = path.join(root, 'tests', 'debug', 'programs', 'belt_pair.rsd');
  const dc = await client();
  try {
    const { stop } = await started(dc, { cell, programs: { left: path.join(two, 'left.rsp'), right: path.join(two, 'right.rsp') } }, {
      breakpoints: async (c) => {
        const set = (await c.setFunctionBreakpointsRequest({ breakpoints: [{ name: 'sensor eye on' }, { name: 'sensor lamp' }] }))
          .body.breakpoints;
        assert.deepEqual(set.map((b) => b.verified), [true, false]);
      },
    });
    assert.equal(stop.body.reason, 'function breakpoint');
    assert.equal(stop.body.threadId, 1);
    assert.equal(stop.body.allThreadsStopped, true);
    assert.equal(stop.body.description, 'breakpoint 1 (sensor eye ON): sensor eye ON at 1.500 s');
    assert.deepEqual((await dc.threadsRequest()).body.threads.map((t) => t.name), ['left', 'right']);
    const scopes = (await dc.scopesRequest({ frameId: 2000 })).body.scopes;  // right's frame
    const devices = scopes.find((s) => s.name === 'Devices');
    const rows = (await dc.variablesRequest({ variablesReference: devices.variablesReference })).body.variables;
    assert.equal(rows.find((v) => v.name === 'block (object 2)').value, 'at (-540.000, 500.000, 2870.000), riding belt');
    const info = (await dc.dataBreakpointInfoRequest({ variablesReference: 1001, name: 'TURNS' })).body;  // left's Variables
    assert.equal(info.dataId, '1:TURNS');
    await dc.setDataBreakpointsRequest({ breakpoints: [{ dataId: info.dataId }] });
    const watched = await moved(dc, dc.continueRequest({ threadId: 1 }));
    assert.equal(watched.body.reason, 'data breakpoint');
    assert.match(watched.body.description, /TURNS of left changed from 0 to 1/);
    const back = await moved(dc, dc.reverseContinueRequest({ threadId: 1 }));
    assert.equal(back.body.reason, 'function breakpoint');
    assert.deepEqual((await dc.variablesRequest({ variablesReference: devices.variablesReference })).body.variables, rows);
  } finally {
    await dc.stop();
  }
});
