#include "cli/lib/app.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <iostream>
#include <optional>

#include "base/near_names.h"
#include "base/text.h"
#include "cli/lib/dap_command.h"
#include "cli/lib/debug_command.h"
#include "cli/lib/describe_command.h"
#include "cli/lib/help.h"
#include "cli/lib/ik_command.h"
#include "cli/lib/lsp_command.h"
#include "cli/lib/number_args.h"
#include "cli/lib/options.h"
#include "cli/lib/program_commands.h"
#include "cli/lib/render_commands.h"
#include "cli/lib/robot_commands.h"
#include "cli/lib/run_command.h"
#include "cli/lib/serial_commands.h"
#include "cli/lib/teach_command.h"
#include "cli/lib/teach_tui_command.h"
#include "cli/lib/test_command.h"

namespace rs::cli {

namespace {

int helpCommand(const std::string& topic, std::ostream& out, std::ostream& err) {
  if (topic.empty()) {
    out << instructionSummary();
    return kExitOk;
  }
  if (auto text = instructionHelp(topic)) {
    out << *text;
    return kExitOk;
  }
  err << "robotsim: error: " << unknownInstructionMessage(topic) << '\n';
  return kExitBadInput;
}

// run and check share everything but --trace and --strict.
CLI::App* addRunLike(CLI::App& app, const char* name, const char* what, RunCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(name, what);
  cmd->add_option("file", o.program.file, "Program source or compiled image")->required();
  return cmd;
}

void addRunLikeOptions(CLI::App* cmd, RunCommandOptions& o) {
  addCellOptions(cmd, o.program);
  addMaxErrorsOption(cmd, o.program);
  cmd->add_option("--format", o.format, "Summary format: text or json")->check(CLI::IsMember({"text", "json"}));
  addRunOptions(cmd, o.run);
  addSerialOptions(cmd, o.serial);
}

// "robotsim frobnicate": CLI11 would only say that a subcommand is required.
std::optional<int> unknownCommand(CLI::App& app, int argc, const char* const* argv, std::ostream& err) {
  if (argc < 2 || argv[1][0] == '-' || argv[1][0] == '\0') return std::nullopt;
  const std::string_view word = argv[1];
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    if (sub->get_name() == word) return std::nullopt;
    names.push_back(sub->get_name());
  }
  // The word as typed, control bytes escaped.
  std::string shown = base::safeText(word.substr(0, 64));
  if (word.size() > 64) shown += "...";
  const std::string_view near = base::nearestName(word, names);
  err << fmt::format("robotsim: error: unknown command '{}'{}\n", shown,
                     near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near));
  err << fmt::format("  commands: {}\n  robotsim --help says what each does\n", fmt::join(names, ", "));
  return kExitBadInput;
}

}  // namespace

int runCommand(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{"robotsim: compile, check, run and inspect ROBOTSIM robot programs"};
  app.name("robotsim");
  app.require_subcommand(1);

  RunCommandOptions ro;
  CLI::App* run = addRunLike(app, "run", "Run a program (.rsp source or .rsb image) in simulation", ro);
  run->add_flag("--trace{text}", ro.trace, "Print each executed instruction: --trace (text) or --trace=json");
  run->add_flag("--profile", ro.profile,
                "Where the time went: by source line, label and subroutine, moving vs waiting vs gripper, the "
                "slowest moves (with --format=json: a \"profile\" member); --max-steps then defaults to 10000000");
  addRunLikeOptions(run, ro);
  CLI::App* check = addRunLike(app, "check", "Compile, verify and simulate; exit 0 only if all is well", ro);
  check->add_flag("--strict", ro.strict,
                  "Every warning fails the check: the compile's and the cell's (exit 2, nothing runs), the run's "
                  "(exit 1)");
  addRunLikeOptions(check, ro);

  ProgramCommandOptions po;
  CLI::App* compile = app.add_subcommand("compile", "Compile a program to a bytecode image");
  compile->add_option("file", po.program.file, "Program source")->required();
  compile
      ->add_option("-o,--output", po.output,
                   "Image file to write (.rsb; - for standard output; a device or FIFO is written in place)")
      ->required();
  addCellOptions(compile, po.program);
  addMaxErrorsOption(compile, po.program);
  CLI::App* disasm = app.add_subcommand("disasm", "List the bytecode of a program or image");
  disasm->add_option("file", po.program.file, "Program source or compiled image")->required();
  addCellOptions(disasm, po.program);
  addMaxErrorsOption(disasm, po.program);
  CLI::App* tokens = app.add_subcommand("tokens", "Show the tokens the lexer produces");
  tokens->add_option("file", po.program.file, "Program source")->required();
  addMaxErrorsOption(tokens, po.program);
  CLI::App* ast = app.add_subcommand("ast", "Show the abstract syntax tree");
  ast->add_option("file", po.program.file, "Program source")->required();
  ast->add_flag("--tree", po.tree, "Also print ANTLR's parse tree");
  addCellOptions(ast, po.program);
  addMaxErrorsOption(ast, po.program);

  RobotQuery rq;
  const auto robotArgs = [&](CLI::App* cmd,
                             const char* what = "Robot description file (.rsd) or library name, e.g. scorobot") {
    cmd->add_option("robot", rq.robot, what)->required();
    cmd->add_option("--lib", rq.libDirs, "Also look up names in this directory (repeatable)")->allow_extra_args(false);
    cmd->add_flag("--json", rq.json, "Print one JSON object");
  };
  CLI::App* table = app.add_subcommand("table", "Print a robot's D-H table (the paper's TABLE, Fig. 6)");
  robotArgs(table);
  CLI::App* matrix =
      app.add_subcommand("matrix", "Print the matrix taking frame J coordinates to frame I (the paper's MATRIX)");
  robotArgs(matrix);
  matrix->add_option("i", rq.from, "Frame I (0 = base)")->required()->transform(numberArg(rules::kFrameNumber));
  matrix->add_option("j", rq.to, "Frame J")->required()->transform(numberArg(rules::kFrameNumber));
  const auto jointOptions = [&rq](CLI::App* cmd) {
    cmd->add_option("--theta", rq.theta, "Joint values v,v,... (degrees; a prismatic joint's d)")
        ->transform(numberListArg(rules::kJointValue));
    cmd->add_option("--encoders", rq.encoders, "Encoder counts v,v,... (default: the home position)")
        ->transform(numberListArg(rules::kEncoderCount));
  };
  jointOptions(matrix);
  CLI::App* where = app.add_subcommand(
      "where",
      "Print the tool centre point for given encoder values: in a workcell's world coordinates for a CELL, in a "
      "robot's design coordinates for a ROBOT");
  robotArgs(where, "Workcell or robot: description file (.rsd) or library name, e.g. scara-pick or scorobot");
  jointOptions(where);

  CLI::App* describe = app.add_subcommand(
      "describe",
      "Describe a workcell (or a robot alone): motors, ranges, speeds, reach, every object's box, centre and what it "
      "stands on, inputs and outputs");
  robotArgs(describe, "Workcell or robot: description file (.rsd) or library name, e.g. scara-pick");
  IkOptions ikOptions;
  CLI::App* ik = addIkCommand(app, ikOptions);

  PortsOptions portsOptions;
  CLI::App* ports = addPortsCommand(app, portsOptions);
  EmulateOptions emulateOptions;
  CLI::App* emulate = addEmulateCommand(app, emulateOptions);

  const RenderCommands renderCommands(app);  // render, animate
  TeachOptions teachOptions;
  CLI::App* teach = addTeachCommand(app, teachOptions);
  TestOptions testOptions;
  CLI::App* test = addTestCommand(app, testOptions);
  LspOptions lspOptions;
  CLI::App* lsp = addLspCommand(app, lspOptions);
  DebugOptions debugOptions;
  CLI::App* debug = addDebugCommand(app, debugOptions);
  CLI::App* dap = addDapCommand(app);
  std::string helpTopic;
  CLI::App* help = app.add_subcommand("help", "Explain the instruction set, or one instruction");
  help->add_option("instruction", helpTopic, "Instruction name, e.g. JMPVAR");

  if (const std::optional<int> code = unknownCommand(app, argc, argv, err)) return *code;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e, out, err);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  if (!ro.trace.empty() && ro.trace != "text" && ro.trace != "json") {
    err << fmt::format("robotsim: error: --trace takes text or json, not '{}'\n", ro.trace);
    return kExitBadInput;
  }
  if (const std::optional<int> code = renderCommands.run(out, err)) return *code;
  if (test->parsed()) return testCommand(testOptions, out, err);
  if (lsp->parsed()) return lspCommand(lspOptions, err);
  if (debug->parsed()) return debugCommand(debugOptions, std::cin, out, err);
  if (dap->parsed()) return dapCommand(err);
  if (teach->parsed())
    return teachOptions.tui ? teachTuiCommand(teachOptions, out, err) : teachCommand(teachOptions, out, err);
  if (run->parsed()) return runOrCheck(ro, false, out, err);
  if (check->parsed()) return runOrCheck(ro, true, out, err);
  if (compile->parsed()) return compileCommand(po, out, err);
  if (disasm->parsed()) return disasmCommand(po, out, err);
  if (tokens->parsed()) return tokensCommand(po, out, err);
  if (ast->parsed()) return astCommand(po, out, err);
  if (table->parsed()) return tableCommand(rq, out, err);
  if (matrix->parsed()) return matrixCommand(rq, out, err);
  if (where->parsed()) return whereCommand(rq, out, err);
  if (describe->parsed()) return describeCommand(rq, out, err);
  if (ik->parsed()) return ikCommand(ikOptions, out, err);
  if (ports->parsed()) return portsCommand(portsOptions, out, err);
  if (emulate->parsed()) return emulateCommand(emulateOptions, out, err);
  return helpCommand(helpTopic, out, err);
}

}  // namespace rs::cli
