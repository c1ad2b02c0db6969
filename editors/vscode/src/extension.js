// The VS Code side of robotsim: starts `robotsim lsp` for .rsp, .rsd and
// .stim files through vscode-languageclient, and adds the Run, Check,
// Test, Render and Animate commands (tasks with robotsim's problem
// matcher; Animate shows robotsim's HTML replay in a webview beside the
// editor), and the debugger: the debug type "robotsim" runs `robotsim dap`
// (the Debug Adapter Protocol, stepping backwards too) and the "Debug
// robot program" command debugs the file in the editor; "Go to Time" takes
// a stopped debug session to a moment of simulated time (the adapter's
// custom request gotoTime, forwards or backwards). What each command
// runs is in commands.js; which robotsim runs it, in locate.js (PATH, then
// the usual install places, else a message naming the setting to change).
'use strict';

const fs = require('fs');
const os = require('os');
const path = require('path');
const { execFile } = require('child_process');
const vscode = require('vscode');
const { LanguageClient, TransportKind } = require('vscode-languageclient/node');
const { commandArgs, debugConfiguration, gotoTimeRequest, animationTitle } = require('./commands');
const { locateRobotsim } = require('./locate');

let client;

// The robotsim command robotsim.path names or locate.js finds; when there
// is none, an error with a button that opens the setting, and undefined.
function robotsimCommand(setting) {
  const folders = vscode.workspace.workspaceFolders;
  const found = locateRobotsim(setting, { base: folders && folders.length ? folders[0].uri.fsPath : process.cwd() });
  if (found.path) return found.path;
  vscode.window.showErrorMessage(found.error, 'Open Settings').then((choice) => {
    if (choice === 'Open Settings') vscode.commands.executeCommand('workbench.action.openSettings', 'robotsim.path');
  });
  return undefined;
}

function settings() {
  const config = vscode.workspace.getConfiguration('robotsim');
  return {
    path: config.get('path', ''),
    cell: config.get('cell', ''),
    lib: config.get('lib', []),
    collisions: config.get('collisions', 'error'),
  };
}

function activeFile() {
  const editor = vscode.window.activeTextEditor;
  if (!editor || editor.document.isUntitled) {
    vscode.window.showErrorMessage('ROBOTSIM: save the file first; robotsim reads it from disk.');
    return undefined;
  }
  return editor.document.uri.fsPath;
}

// run, check, test and render: a task in the terminal, its problems matched.
async function runTask(command) {
  const file = activeFile();
  if (!file) return;
  const document = vscode.window.activeTextEditor.document;
  await document.save();
  const s = settings();
  const robotsim = robotsimCommand(s.path);
  if (!robotsim) return;
  const args = commandArgs(command, file, s, { exists: fs.existsSync, text: document.getText() });
  const task = new vscode.Task({ type: 'robotsim', command, file }, vscode.TaskScope.Workspace,
    `${command} ${path.basename(file)}`, 'robotsim', new vscode.ProcessExecution(robotsim, args), ['$robotsim']);
  await vscode.tasks.executeTask(task);
}

// animate: robotsim writes the self-contained replay page; a webview beside
// the editor shows it (scripts on, no network: the page needs none).
async function animate(context) {
  const file = activeFile();
  if (!file) return;
  const document = vscode.window.activeTextEditor.document;
  await document.save();
  const s = settings();
  const robotsim = robotsimCommand(s.path);
  if (!robotsim) return;
  const out = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'robotsim-')), 'animation.html');
  const args = commandArgs('animate', file, s, { out, exists: fs.existsSync, text: document.getText() });
  execFile(robotsim, args, (error, _stdout, stderr) => {
    if (error) {
      vscode.window.showErrorMessage(`ROBOTSIM animate: ${stderr.trim() || error.message}`);
      return;
    }
    const panel = vscode.window.createWebviewPanel('robotsim.animation', animationTitle(file),
      { viewColumn: vscode.ViewColumn.Beside, preserveFocus: true }, { enableScripts: true });
    panel.webview.html = fs.readFileSync(out, 'utf8');
    context.subscriptions.push(panel);
  });
}

// Debug robot program: the file in the editor, saved, under robotsim dap.
async function debugProgram() {
  const file = activeFile();
  if (!file) return;
  const document = vscode.window.activeTextEditor.document;
  await document.save();
  const config = debugConfiguration(file, settings(), { exists: fs.existsSync, text: document.getText() });
  await vscode.debug.startDebugging(vscode.workspace.getWorkspaceFolder(document.uri), config);
}

// Go to Time: the moment typed, in the robotsim session being debugged.
async function gotoTime() {
  const session = vscode.debug.activeDebugSession;
  if (!session || session.type !== 'robotsim') {
    vscode.window.showErrorMessage('ROBOTSIM: Go to Time needs a robot program being debugged.');
    return;
  }
  const typed = await vscode.window.showInputBox({
    prompt: 'Go to this moment of the run (seconds of simulated time), forwards or backwards',
    placeHolder: '2.5',
    validateInput: (text) => gotoTimeRequest(text).problem,
  });
  if (typed === undefined) return;
  const request = gotoTimeRequest(typed);
  try {
    await session.customRequest(request.command, request.arguments);
  } catch (error) {
    vscode.window.showErrorMessage(`ROBOTSIM: ${error.message}`);
  }
}

function registerDebugger(context) {
  context.subscriptions.push(vscode.debug.registerDebugAdapterDescriptorFactory('robotsim', {
    createDebugAdapterDescriptor: () => {
      const robotsim = robotsimCommand(settings().path);
      return robotsim ? new vscode.DebugAdapterExecutable(robotsim, ['dap']) : undefined;
    },
  }));
  // F5 without a launch.json: debug the program in the editor.
  context.subscriptions.push(vscode.debug.registerDebugConfigurationProvider('robotsim', {
    resolveDebugConfiguration(_folder, config) {
      // A program, or a cell of several robots (cell and programs: one thread per robot).
      if (config.type && (config.program || config.cell)) return config;
      const editor = vscode.window.activeTextEditor;
      if (!editor || editor.document.languageId !== 'robotsim-program' || editor.document.isUntitled) {
        vscode.window.showErrorMessage('ROBOTSIM: open a saved robot program (.rsp) to debug it.');
        return undefined;
      }
      return debugConfiguration(editor.document.uri.fsPath, settings(),
        { exists: fs.existsSync, text: editor.document.getText() });
    },
  }));
  context.subscriptions.push(vscode.commands.registerCommand('robotsim.debug', () => debugProgram()));
  context.subscriptions.push(vscode.commands.registerCommand('robotsim.gotoTime', () => gotoTime()));
}

function activate(context) {
  registerDebugger(context);
  for (const command of ['run', 'check', 'test', 'render'])
    context.subscriptions.push(vscode.commands.registerCommand(`robotsim.${command}`, () => runTask(command)));
  context.subscriptions.push(vscode.commands.registerCommand('robotsim.animate', () => animate(context)));
  registerTasks(context);
  startServer();
  // Set after the message: the server starts then, no reload needed.
  context.subscriptions.push(vscode.workspace.onDidChangeConfiguration((e) => {
    if (e.affectsConfiguration('robotsim.path') && !client) startServer();
  }));
}

// The language server, when there is a robotsim to run it (else the
// message from robotsimCommand).
function startServer() {
  const s = settings();
  const robotsim = robotsimCommand(s.path);
  if (!robotsim) return;
  const serverOptions = { command: robotsim, args: ['lsp'], transport: TransportKind.stdio };
  const clientOptions = {
    documentSelector: [
      { scheme: 'file', language: 'robotsim-program' },
      { scheme: 'file', language: 'robotsim-description' },
      { scheme: 'file', language: 'robotsim-stimuli' },
    ],
    initializationOptions: { cell: s.cell, lib: s.lib, collisions: s.collisions },
    synchronize: { configurationSection: 'robotsim' },
  };
  client = new LanguageClient('robotsim', 'ROBOTSIM', serverOptions, clientOptions);
  client.start();
}

function registerTasks(context) {
  context.subscriptions.push(vscode.tasks.registerTaskProvider('robotsim', {
    provideTasks: () => [],
    resolveTask(task) {
      const file = task.definition.file || activeFile();
      if (!file) return undefined;
      const text = fs.existsSync(file) ? fs.readFileSync(file, 'utf8') : '';
      const robotsim = robotsimCommand(settings().path);
      if (!robotsim) return undefined;
      const args = [...commandArgs(task.definition.command, file, settings(), { exists: fs.existsSync, text }),
                    ...(task.definition.args || [])];
      return new vscode.Task(task.definition, task.scope || vscode.TaskScope.Workspace, task.name, 'robotsim',
        new vscode.ProcessExecution(robotsim, args), ['$robotsim']);
    },
  }));
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
