#include "tools/cli/lib/gen_docs.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>

#include "base/file_write.h"
#include "tools/cli/lib/bash_completion.h"
#include "tools/cli/lib/commands.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/fish_completion.h"
#include "tools/cli/lib/man_page.h"
#include "tools/cli/lib/zsh_completion.h"

namespace rs::cli {

namespace {

bool writeDocFile(const std::string& path, const std::string& bytes, std::ostream& err) {
  std::string error;
  if (base::writeFileAtomically(path, bytes, error)) return true;
  err << "robotsim_gen_docs: error: " << error << '\n';
  return false;
}

}  // namespace

int genDocsCommand(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{"Write robotsim's man pages and its bash, zsh and fish completions from its command table"};
  app.name("robotsim_gen_docs");
  std::string manDir, bashFile, zshFile, fishFile;
  app.add_option("--man", manDir, "Write robotsim.1 and robotsim-COMMAND.1 for every command into this folder")
      ->check(CLI::ExistingDirectory);
  app.add_option("--bash", bashFile, "Write the bash completion script to this file (installed as robotsim)");
  app.add_option("--zsh", zshFile, "Write the zsh completion function to this file (installed as _robotsim)");
  app.add_option("--fish", fishFile, "Write the fish completions to this file (installed as robotsim.fish)");
  app.footer("At least one of --man, --bash, --zsh and --fish; existing files are replaced whole, never half-written.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e, out, err) == 0 ? kExitOk : kExitBadInput;
  }
  if (manDir.empty() && bashFile.empty() && zshFile.empty() && fishFile.empty()) {
    err << "robotsim_gen_docs: error: nothing to write\n  give --man DIR, --bash FILE, --zsh FILE or --fish FILE\n";
    return kExitBadInput;
  }
  const CommandLine commandLine;
  if (!manDir.empty()) {
    const std::filesystem::path dir(manDir);
    if (!writeDocFile((dir / manPageFileName("")).string(), robotsimManPage(commandLine), err))
      return kExitBadInput;
    const auto table = commandTable();
    for (std::size_t i = 0; i < table.size(); ++i)
      if (!writeDocFile((dir / manPageFileName(table[i].name)).string(), commandManPage(commandLine, i), err))
        return kExitBadInput;
  }
  if (!bashFile.empty() && !writeDocFile(bashFile, bashCompletion(commandLine), err)) return kExitBadInput;
  if (!zshFile.empty() && !writeDocFile(zshFile, zshCompletion(commandLine), err)) return kExitBadInput;
  if (!fishFile.empty() && !writeDocFile(fishFile, fishCompletion(commandLine), err)) return kExitBadInput;
  return kExitOk;
}

}  // namespace rs::cli
