#include "tools/cli/lib/commands.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "tools/cli/lib/cell_programs.h"
#include "tools/cli/lib/dap_command.h"
#include "tools/cli/lib/describe_command.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/serial_commands.h"
#include "tools/cli/lib/help.h"
#include "tools/cli/lib/teach_tui_command.h"

namespace rs::cli {

namespace {

using Values = CommandValues;
using Io = CommandStreams;

// --trace takes an optional value, which CLI11 cannot check as it reads it.
int runHandler(const Values& v, const Io& io) {
  if (!v.run.trace.empty() && v.run.trace != "text" && v.run.trace != "json") {
    io.err << fmt::format("robotsim: error: --trace takes text or json, not '{}'\n", v.run.trace);
    return kExitBadInput;
  }
  return runOrCheck(v.run, false, io.out, io.err);
}

// The rows run by a helper name their functions through RS_IN_HELPER. The
// main binary compiles its own copy of this file with
// ROBOTSIM_MAIN_COMMAND_TABLE, where those are null: nothing there refers to
// the renderer, the HTTP server, ncurses or libedit, so they are not linked
// (the helpers link this library's copy, with every function).
#ifdef ROBOTSIM_MAIN_COMMAND_TABLE
#define RS_IN_HELPER(...) nullptr
#else
#define RS_IN_HELPER(...) __VA_ARGS__
#endif

// The rows, in `robotsim --help`'s order. The lambdas only pick the
// command's options out of CommandValues.
constexpr std::array kCommands{
    Command{"run", "Run a program (.rsp source or .rsb image) in simulation",
            [](CLI::App* c, Values& v) { addRunCommandOptions(c, v.run); }, runHandler},
    Command{"check", "Compile, verify and simulate; exit 0 only if all is well",
            [](CLI::App* c, Values& v) { addCheckCommandOptions(c, v.run); },
            [](const Values& v, const Io& io) {
              return v.run.program.file.empty() ? checkCellPrograms(v.run, io.out, io.err)
                                                : runOrCheck(v.run, true, io.out, io.err);
            }},
    Command{"compile", "Compile a program to a bytecode image",
            [](CLI::App* c, Values& v) { addCompileOptions(c, v.program); },
            [](const Values& v, const Io& io) {
              return v.program.program.file.empty() ? compileCellPrograms(v.program, io.out, io.err)
                                                     : compileCommand(v.program, io.out, io.err);
            }},
    Command{"disasm", "List the bytecode of a program or image",
            [](CLI::App* c, Values& v) { addDisasmOptions(c, v.program); },
            [](const Values& v, const Io& io) { return disasmCommand(v.program, io.out, io.err); }},
    Command{"tokens", "Show the tokens the lexer produces",
            [](CLI::App* c, Values& v) { addTokensOptions(c, v.program); },
            [](const Values& v, const Io& io) { return tokensCommand(v.program, io.out, io.err); }},
    Command{"ast", "Show the abstract syntax tree", [](CLI::App* c, Values& v) { addAstOptions(c, v.program); },
            [](const Values& v, const Io& io) { return astCommand(v.program, io.out, io.err); }},
    Command{"table", "Print a robot's D-H table (the paper's TABLE, Fig. 6)",
            [](CLI::App* c, Values& v) { addTableOptions(c, v.robot); },
            [](const Values& v, const Io& io) { return tableCommand(v.robot, io.out, io.err); }},
    Command{"matrix", "Print the matrix taking frame J coordinates to frame I (the paper's MATRIX)",
            [](CLI::App* c, Values& v) { addMatrixOptions(c, v.robot); },
            [](const Values& v, const Io& io) { return matrixCommand(v.robot, io.out, io.err); }},
    Command{"where",
            "Print the tool centre point for given encoder values: in a workcell's world coordinates for a CELL, in "
            "a robot's design coordinates for a ROBOT",
            [](CLI::App* c, Values& v) { addWhereOptions(c, v.robot); },
            [](const Values& v, const Io& io) { return whereCommand(v.robot, io.out, io.err); }},
    Command{"describe",
            "Describe a workcell (or a robot alone): motors, ranges, speeds, reach, every object's box, centre and "
            "what it stands on, inputs and outputs",
            [](CLI::App* c, Values& v) { addDescribeOptions(c, v.robot); },
            [](const Values& v, const Io& io) { return describeCommand(v.robot, io.out, io.err); }},
    Command{"ik", "Encoder counts that put the tool at a pose (inverse kinematics), as a POINTS line",
            [](CLI::App* c, Values& v) { addIkOptions(c, v.ik); },
            [](const Values& v, const Io& io) { return ikCommand(v.ik, io.out, io.err); }},
    Command{"export", "Write a robot as URDF (the Robot Description Format of ROS: RViz, MoveIt, Gazebo, KDL)",
            [](CLI::App* c, Values& v) { addExportOptions(c, v.exporting); },
            [](const Values& v, const Io& io) { return exportCommand(v.exporting, io.out, io.err); }},
    Command{"convert", "Write a URDF robot as a robotsim description (.rsd)",
            [](CLI::App* c, Values& v) { addConvertOptions(c, v.convert); },
            [](const Values& v, const Io& io) { return convertCommand(v.convert, io.out, io.err); }},
    Command{"list", "List the library: robots, grippers, objects and workcells, and the path searched for them",
            [](CLI::App* c, Values& v) { addListOptions(c, v.list); },
            [](const Values& v, const Io& io) { return listCommand(v.list, io.out, io.err); }},
    Command{"ports", "List the serial devices a Rhino controller may be on",
            [](CLI::App* c, Values& v) { addPortsOptions(c, v.ports); },
            [](const Values& v, const Io& io) { return portsCommand(v.ports, io.out, io.err); }},
    Command{"emulate",
            "Play a Rhino controller on a pseudo-terminal: run programs with --device on it, no robot needed",
            [](CLI::App* c, Values& v) { addEmulateOptions(c, v.emulate); },
            [](const Values& v, const Io& io) { return emulateCommand(v.emulate, io.out, io.err); }},
    Command{"render", "Draw a workcell (PNG or SVG), at its placed pose or during a run",
            RS_IN_HELPER([](CLI::App* c, Values& v) { addRenderOptions(c, v.render); }),
            RS_IN_HELPER([](const Values& v, const Io& io) { return renderCommand(v.render, io.out, io.err); }), true},
    Command{"animate", "Write a self-contained HTML page that replays a program's run",
            RS_IN_HELPER([](CLI::App* c, Values& v) { addAnimateOptions(c, v.render); }),
            RS_IN_HELPER([](const Values& v, const Io& io) { return animateCommand(v.render, io.out, io.err); }), true},
    Command{"plot", "Chart a program's run over time (SVG or PNG), or write its samples as CSV",
            RS_IN_HELPER([](CLI::App* c, Values& v) { addPlotOptions(c, v.plot); }),
            RS_IN_HELPER([](const Values& v, const Io& io) { return plotCommand(v.plot, io.out, io.err); }), true},
    Command{"teach", "Jog the robot in its workcell on a live page and teach points into the program's POINTS section",
            RS_IN_HELPER([](CLI::App* c, Values& v) { addTeachOptions(c, v.teach); }),
            RS_IN_HELPER([](const Values& v, const Io& io) {
              if (refuseSeveralDevices(v.teach.request.serial, io.err)) return int{kExitBadInput};
              return v.teach.tui ? teachTuiCommand(v.teach, io.out, io.err) : teachCommand(v.teach, io.out, io.err);
            }),
            true},
    Command{"test", "Check programs against the expectations written in them (folders: every .rsp, recursively)",
            [](CLI::App* c, Values& v) { addTestOptions(c, v.test); },
            [](const Values& v, const Io& io) { return testCommand(v.test, io.out, io.err); }},
    Command{"lsp", "Run the language server (LSP 3.17) on stdin/stdout, for editors",
            [](CLI::App* c, Values& v) { addLspOptions(c, v.lsp); },
            [](const Values& v, const Io& io) { return lspCommand(v.lsp, io.err); }},
    Command{"debug", "Debug a program: breakpoints, stepping, and stepping backwards",
            RS_IN_HELPER([](CLI::App* c, Values& v) { addDebugOptions(c, v.debug); }),
            RS_IN_HELPER([](const Values& v, const Io& io) { return debugCommand(v.debug, io.in, io.out, io.err); }),
            true},
    Command{"dap", "Run the debug adapter (Debug Adapter Protocol) on stdin/stdout, for editors",
            [](CLI::App* c, Values&) { addDapOptions(c); }, [](const Values&, const Io& io) { return dapCommand(io.err); }},
    Command{"help", "Explain the instruction set, or one instruction",
            [](CLI::App* c, Values& v) { addHelpOptions(c, v.helpTopic); },
            [](const Values& v, const Io& io) { return helpCommand(v.helpTopic, io.out, io.err); }},
    Command{"version", "Print the version, the commit and build type, and where the library of robots and cells is",
            [](CLI::App* c, Values& v) { addVersionOptions(c, v.versionFormat); },
            [](const Values& v, const Io& io) { return versionCommand(v.versionFormat, io.out); }},
};
#undef RS_IN_HELPER

}  // namespace

std::span<const Command> commandTable() { return kCommands; }

namespace {

// CLI11 keeps an option's Needs and Excludes as sets of pointers, so its
// help lists them in the order of their addresses, which differs between
// processes ("Excludes: --open --listen" in one, "--listen --open" in the
// next). Listed by name, the help is the same bytes every time.
class NamesInOrderFormatter : public CLI::Formatter {
 public:
  std::string make_option_opts(const CLI::Option* opt) const override {
    std::string text = CLI::Formatter::make_option_opts(opt);
    for (const std::string& label : {get_label("Needs"), get_label("Excludes")}) {
      const std::string head = " " + label + ":";
      const std::size_t at = text.find(head);
      if (at == std::string::npos) continue;
      const std::size_t from = at + head.size();
      // The names run to the next label or the end; each is " --name".
      std::size_t to = text.size();
      for (const std::string& other : {get_label("Needs"), get_label("Excludes")})
        if (const std::size_t next = text.find(" " + other + ":", from); next != std::string::npos) to = std::min(to, next);
      std::vector<std::string> names;
      std::istringstream words(text.substr(from, to - from));
      for (std::string w; words >> w;) names.push_back(w);
      std::sort(names.begin(), names.end());
      std::string sorted;
      for (const std::string& n : names) sorted += " " + n;
      text.replace(from, to - from, sorted);
    }
    return text;
  }
};

}  // namespace

CommandLine::CommandLine() : CommandLine({}, true) {}

CommandLine::CommandLine(std::string_view command) : CommandLine(command, false) {}

CommandLine::CommandLine(std::string_view command, bool everyRow) : app_{std::string(kRobotsimHelp)} {
  app_.name("robotsim");
  app_.formatter(std::make_shared<NamesInOrderFormatter>());  // subcommands take it as they are added
  app_.require_subcommand(1);
  app_.footer("robotsim --version (or robotsim version) prints the version and where the library of robots and "
              "cells is.");
  for (const Command& row : kCommands) {
    CLI::App* cmd = app_.add_subcommand(std::string(row.name), std::string(row.help));
    if (row.addOptions != nullptr && (everyRow || command == row.name)) row.addOptions(cmd, values_);
    subcommands_.push_back(cmd);
  }
}

const Command* CommandLine::parsedCommand() const {
  for (std::size_t i = 0; i < subcommands_.size(); ++i)
    if (subcommands_[i]->parsed()) return &kCommands[i];
  return nullptr;
}

}  // namespace rs::cli
