// robotsim version (also robotsim --version): the version, the commit and
// build type it was built from, and where its library of robots and cells
// was found (docs/cli.md, "version").
#pragma once

#include <CLI/CLI.hpp>

#include <iosfwd>
#include <string>

namespace rs::cli {

void addVersionOptions(CLI::App* cmd, std::string& format);
int versionCommand(const std::string& format, std::ostream& out);

}  // namespace rs::cli
