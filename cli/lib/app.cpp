#include "cli/lib/app.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/lib/help.h"
#include "cli/lib/program_file.h"
#include "cli/lib/render_commands.h"
#include "cli/lib/report.h"
#include "cli/lib/robot_commands.h"
#include "cli/lib/serial_commands.h"
#include "cli/lib/trace.h"
#include "compiler/library.h"
#include "runtime/sim_machine.h"
#include "model/workcell/cell_file.h"
#include "model/workcell/tool_tracker.h"
#include "runtime/stimuli.h"
#include "runtime/stimuli_text.h"
#include "vm/disasm.h"
#include "vm/image_file.h"

namespace rs::cli {

namespace {

struct Options {
  std::string file;
  std::string output;
  std::string format = "text";
  std::string trace;  // "", "text" or "json"
  std::vector<std::string> inputs;
  std::string stimuliFile;
  std::uint64_t maxSteps = vm::RunLimits{}.maxSteps;
  std::string maxTime = "3600";
  bool strict = false;
  bool tree = false;
  std::string cell;                  // --cell
  std::vector<std::string> libDirs;  // --lib
  SerialOptions serial;              // --device, --dialect, --log-serial, ...
};

// --cell's workcell from the library (with --lib), its library kept in
// `into` for messages; nullopt, with the diagnostics in `into`, when it
// cannot be loaded or has no robot to run a program.
std::optional<workcell::Workcell> openCell(const Options& o, LoadedProgram& into) {
  auto library = std::make_shared<compiler::Library>(compiler::librarySearchPath(o.libDirs));
  into.descriptions = library;
  std::optional<workcell::Workcell> cell = library->workcell(o.cell);
  if (cell && !cell->robots.empty()) return cell;
  into.diagnostics = library->diagnostics();
  if (cell) into.diagnostics.push_back({o.cell, {}, diag::Severity::Error, "the workcell has no robot to run the program"});
  return std::nullopt;
}

// The program, compiled for --cell's robot when given; the image then
// carries the cell.
LoadedProgram loadWithCell(const Options& o) {
  if (o.cell.empty()) return loadProgram(o.file, defaultTarget());
  LoadedProgram failed;
  const std::optional<workcell::Workcell> cell = openCell(o, failed);
  if (!cell) return failed;
  LoadedProgram program = loadProgram(o.file, cellTarget(*cell));
  program.descriptions = failed.descriptions;
  if (program.image && !program.source) {
    program.image.reset();
    program.diagnostics.push_back({o.file, {}, diag::Severity::Error,
                                   "--cell applies to program sources: a compiled image carries its own cell"});
  }
  if (program.image) program.image->cell = workcell::encodeCell(*cell);
  return program;
}

// --strict: a warning fails the check like an error, before anything runs.
void promoteWarnings(LoadedProgram& program) {
  bool promoted = false;
  for (diag::Diagnostic& d : program.diagnostics)
    if (d.severity == diag::Severity::Warning) {
      d.severity = diag::Severity::Error;
      d.message += " [--strict]";
      promoted = true;
    }
  if (promoted) program.image.reset();
}

int runOrCheck(const Options& o, bool check, std::ostream& out, std::ostream& err) {
  const bool json = o.format == "json";
  LoadedProgram program = loadWithCell(o);
  if (check && o.strict) promoteWarnings(program);
  std::optional<workcell::Workcell> cell;
  if (program.image && !program.image->cell.empty()) {
    std::string error = decodeImageCell(*program.image, cell);
    if (!error.empty()) {
      program.diagnostics.push_back({o.file, {}, diag::Severity::Error, "image rejected: " + error});
      program.image.reset();
    }
  }
  RunReport report;
  report.diagnostics = program.diagnostics;
  runtime::Stimuli stimuli;
  const runtime::text::SecondsParse maxTime = runtime::text::parseSeconds(o.maxTime);
  if (!maxTime.error.empty())
    report.diagnostics.push_back({"--max-time", {}, diag::Severity::Error, maxTime.error});
  const bool stimuliOk = loadStimuli(o.stimuliFile, o.inputs, stimuli, report.diagnostics);
  if (!program.ok() || !stimuliOk || !maxTime.error.empty()) {
    printDiagnostics(err, report.diagnostics, program);
    if (json) printJsonSummary(out, report);
    return kExitBadInput;
  }
  printDiagnostics(err, program.diagnostics, program);  // warnings

  const vm::Image& image = *program.image;
  const vm::RunLimits limits{o.maxSteps, maxTime.micros};
  std::unique_ptr<vm::Machine> machine;
  if (o.serial.active()) {
    std::string error;
    machine = openRhino(o.serial, image.motors, limits.maxTime, error);
    if (!machine) {
      err << fmt::format("robotsim: error: {}\n", error);
      return kExitRunFailed;
    }
  } else {
    machine = std::make_unique<runtime::SimMachine>(image.motors, std::move(stimuli));
  }
  vm::Interpreter interpreter(image, *machine);
  report.realTime = o.serial.active();
  std::optional<workcell::ToolTracker> tool;
  if (cell) tool.emplace(cell->robots.front());
  runtime::ObjectsInGripper objects(cell ? &*cell : nullptr, machine->positions());
  report.tool = tool ? &*tool : nullptr;
  report.grasping = objects.grasping();
  report.cell = cell ? &*cell : nullptr;
  // Observers in a chain: the objects follow the gripper first, then the trace shows the step.
  std::optional<TraceWriter> trace;
  if (!o.trace.empty())
    trace.emplace(out, o.trace == "json" ? TraceFormat::Json : TraceFormat::Text, report.tool, objects.observer(),
                  report.cell);
  report.outcome = interpreter.run(limits, objects.chain(trace ? &*trace : nullptr));
  report.image = &image;
  report.vm = &interpreter;
  if (!report.outcome->ok()) {
    const diag::Diagnostic d = runtimeDiagnostic(image, *report.outcome, image.sourceName);
    printDiagnostics(err, {d}, program);
    report.diagnostics.push_back(d);
  }
  if (json) printJsonSummary(out, report);
  else if (!check || !report.ok()) printTextSummary(out, report);
  else out << fmt::format("{}: ok ({} instructions executed, {} s simulated)\n", image.sourceName,
                          report.outcome->steps, vm::formatSeconds(machine->now()));
  if (!report.outcome->ok()) return kExitRunFailed;
  return kExitOk;
}

int compileCommand(const Options& o, std::ostream& out, std::ostream& err) {
  LoadedProgram program = loadWithCell(o);
  printDiagnostics(err, program.diagnostics, program);
  if (!program.ok()) return kExitBadInput;
  std::string error;
  if (!base::writeFileAtomically(o.output, vm::writeImage(*program.image), error)) {
    err << fmt::format("{}: error: cannot write: {}\n", o.output, error);
    return kExitBadInput;
  }
  out << fmt::format("{} -> {} ({} instructions)\n", o.file, o.output, program.image->code.size());
  return kExitOk;
}

int disasmCommand(const Options& o, std::ostream& out, std::ostream& err) {
  LoadedProgram program = loadWithCell(o);
  printDiagnostics(err, program.diagnostics, program);
  if (!program.ok()) return kExitBadInput;
  out << vm::disassemble(*program.image);
  return kExitOk;
}

// tokens / ast: teaching views of the front end; they read source only.
template <typename Dump>
int sourceView(const Options& o, std::ostream& out, std::ostream& err, Dump dump) {
  base::FileRead text = base::readFile(o.file, kMaxInputBytes);
  if (!text.bytes) {
    err << fmt::format("{}: error: cannot read file: {}\n", o.file, text.error);
    return kExitBadInput;
  }
  if (vm::looksLikeImage(*text.bytes)) {
    err << fmt::format("{}: error: this is a compiled image; try robotsim disasm\n", o.file);
    return kExitBadInput;
  }
  const diag::SourceFile source(o.file, std::move(*text.bytes));
  std::vector<diag::Diagnostic> diags;
  out << dump(source, diags);
  for (const diag::Diagnostic& d : diags) err << diag::render(d, &source);
  return diag::hasErrors(diags) ? kExitBadInput : kExitOk;
}

int helpCommand(const std::string& topic, std::ostream& out, std::ostream& err) {
  if (topic.empty()) {
    out << instructionSummary();
    return kExitOk;
  }
  if (auto text = instructionHelp(topic)) {
    out << *text;
    return kExitOk;
  }
  err << fmt::format("robotsim: error: no instruction named '{}' (robotsim help lists them)\n", topic);
  return kExitBadInput;
}

void addCellOptions(CLI::App* cmd, Options& o) {
  cmd->add_option("--cell", o.cell, "Workcell (or robot) description file or library name to run on");
  cmd->add_option("--lib", o.libDirs, "Also look up description names in this directory (repeatable)")
      ->allow_extra_args(false);
}

void addRunOptions(CLI::App* cmd, Options& o) {
  addCellOptions(cmd, o);
  cmd->add_option("--format", o.format, "Summary format: text or json")->check(CLI::IsMember({"text", "json"}));
  cmd->add_option("--input", o.inputs, "Input change N=ON@SECONDS or N=OFF@SECONDS (repeatable)")
      ->allow_extra_args(false);
  cmd->add_option("--stimuli", o.stimuliFile, "Stimuli file: timed input changes and reactive rules");
  cmd->add_option("--max-steps", o.maxSteps, "Stop after this many instructions (default 100000000)")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 62));
  cmd->add_option("--max-time", o.maxTime, "Stop at this simulated time in seconds (default 3600)");
}

}  // namespace

int runCommand(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{"robotsim: compile, check, run and inspect ROBOTSIM robot programs"};
  app.name("robotsim");
  app.require_subcommand(1);
  Options o;
  std::string helpTopic;

  CLI::App* run = app.add_subcommand("run", "Run a program (.rsp source or .rsb image) in simulation");
  run->add_option("file", o.file, "Program source or compiled image")->required();
  run->add_flag("--trace{text}", o.trace, "Print each executed instruction: --trace (text) or --trace=json");
  addRunOptions(run, o);
  addSerialOptions(run, o.serial);

  CLI::App* check = app.add_subcommand("check", "Compile, verify and simulate; exit 0 only if all is well");
  check->add_option("file", o.file, "Program source or compiled image")->required();
  check->add_flag("--strict", o.strict, "Warnings fail the check too");
  addRunOptions(check, o);
  addSerialOptions(check, o.serial);

  CLI::App* compile = app.add_subcommand("compile", "Compile a program to a bytecode image");
  compile->add_option("file", o.file, "Program source")->required();
  compile->add_option("-o,--output", o.output, "Image file to write (.rsb)")->required();
  addCellOptions(compile, o);

  CLI::App* disasm = app.add_subcommand("disasm", "List the bytecode of a program or image");
  disasm->add_option("file", o.file, "Program source or compiled image")->required();
  addCellOptions(disasm, o);

  CLI::App* tokens = app.add_subcommand("tokens", "Show the tokens the lexer produces");
  tokens->add_option("file", o.file, "Program source")->required();

  CLI::App* ast = app.add_subcommand("ast", "Show the abstract syntax tree");
  ast->add_option("file", o.file, "Program source")->required();
  ast->add_flag("--tree", o.tree, "Also print ANTLR's parse tree");
  addCellOptions(ast, o);

  RobotQuery rq;
  const auto robotArgs = [&](CLI::App* cmd) {
    cmd->add_option("robot", rq.robot, "Robot description file (.rsd) or library name, e.g. scorobot")->required();
    cmd->add_option("--lib", rq.libDirs, "Also look up names in this directory (repeatable)")->allow_extra_args(false);
    cmd->add_flag("--json", rq.json, "Print one JSON object");
  };
  CLI::App* table = app.add_subcommand("table", "Print a robot's D-H table (the paper's TABLE, Fig. 6)");
  robotArgs(table);
  CLI::App* matrix =
      app.add_subcommand("matrix", "Print the matrix taking frame J coordinates to frame I (the paper's MATRIX)");
  robotArgs(matrix);
  matrix->add_option("i", rq.from, "Frame I (0 = base)")->required();
  matrix->add_option("j", rq.to, "Frame J")->required();
  matrix->add_option("--theta", rq.theta, "Joint values v,v,... (degrees; a prismatic joint's d)");
  matrix->add_option("--encoders", rq.encoders, "Encoder counts v,v,... (default: the home position)");
  CLI::App* where = app.add_subcommand("where", "Print the tool centre point for given encoder values");
  robotArgs(where);
  where->add_option("--theta", rq.theta, "Joint values v,v,... (degrees; a prismatic joint's d)");
  where->add_option("--encoders", rq.encoders, "Encoder counts v,v,... (default: the home position)");

  PortsOptions portsOptions;
  CLI::App* ports = addPortsCommand(app, portsOptions);
  EmulateOptions emulateOptions;
  CLI::App* emulate = addEmulateCommand(app, emulateOptions);

  const RenderCommands renderCommands(app);  // render, animate
  CLI::App* help = app.add_subcommand("help", "Explain the instruction set, or one instruction");
  help->add_option("instruction", helpTopic, "Instruction name, e.g. JMPVAR");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e, out, err);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  if (!o.trace.empty() && o.trace != "text" && o.trace != "json") {
    err << fmt::format("robotsim: error: --trace takes text or json, not '{}'\n", o.trace);
    return kExitBadInput;
  }
  if (const std::optional<int> code = renderCommands.run(out, err)) return *code;
  if (run->parsed()) return runOrCheck(o, false, out, err);
  if (check->parsed()) return runOrCheck(o, true, out, err);
  if (compile->parsed()) return compileCommand(o, out, err);
  if (disasm->parsed()) return disasmCommand(o, out, err);
  if (tokens->parsed())
    return sourceView(o, out, err, [](const diag::SourceFile& s, auto& d) { return compiler::dumpTokens(s, d); });
  if (ast->parsed()) {
    // Operand counts are checked against the robot: --cell's, or the default.
    compiler::Target target = defaultTarget();
    if (!o.cell.empty()) {
      LoadedProgram descriptions;
      const std::optional<workcell::Workcell> cell = openCell(o, descriptions);
      if (!cell) {
        printDiagnostics(err, descriptions.diagnostics, descriptions);
        return kExitBadInput;
      }
      target = cellTarget(*cell);
    }
    return sourceView(o, out, err, [&](const diag::SourceFile& s, auto& d) {
      return compiler::dumpAst(s, target, o.tree, d);
    });
  }
  if (table->parsed()) return tableCommand(rq, out, err);
  if (matrix->parsed()) return matrixCommand(rq, out, err);
  if (where->parsed()) return whereCommand(rq, out, err);
  if (ports->parsed()) return portsCommand(portsOptions, out, err);
  if (emulate->parsed()) return emulateCommand(emulateOptions, out, err);
  return helpCommand(helpTopic, out, err);
}

}  // namespace rs::cli
