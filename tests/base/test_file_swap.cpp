// base::replaceFileIfUnchanged, teach's compare-and-write: written only
// while the file holds what the caller saw, refused (and untouched) when it
// changed or another program has it open for writing; the mode, the owner
// and a link kept; a read that waits for a save in progress to end. The
// race with a real editor is tests/teach/test_program_file_race.cpp.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <thread>

#include "base/file_swap.h"
#include "tests/cli/cli_support.h"

namespace {

namespace fs = std::filesystem;
using rs::base::replaceFileIfUnchanged;
using rs::base::SwapOutcome;
using rs::testing::readBytes;

std::vector<std::string> filesIn(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(folder)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

TEST_CASE("compare-and-write: written while unchanged, refused when changed", "[base][swap]") {
  const rs::testing::TempDir dir;
  const std::string path = dir.write("p.rsp", "v1\n");
  REQUIRE(::chmod(path.c_str(), 0600) == 0);
  CHECK(replaceFileIfUnchanged(path, "v1\n", "v2\n").outcome == SwapOutcome::kWritten);
  CHECK(readBytes(path) == "v2\n");
  struct stat st {};
  REQUIRE(::stat(path.c_str(), &st) == 0);
  CHECK((st.st_mode & 07777) == 0600);
  // What the caller saw is gone: nothing written, the file as the other program left it.
  CHECK(replaceFileIfUnchanged(path, "v1\n", "v3\n").outcome == SwapOutcome::kChanged);
  CHECK(replaceFileIfUnchanged(path, "v2", "v3\n").outcome == SwapOutcome::kChanged);      // a prefix is not it
  CHECK(replaceFileIfUnchanged(path, "v2\n\n", "v3\n").outcome == SwapOutcome::kChanged);  // nor a longer text
  CHECK(readBytes(path) == "v2\n");
  CHECK(filesIn(dir.path()) == std::vector<std::string>{"p.rsp"});
  // A file that is not there any more, and one that is not a regular file.
  CHECK(replaceFileIfUnchanged(dir.file("gone.rsp"), "", "x").outcome == SwapOutcome::kFailed);
  CHECK(replaceFileIfUnchanged(dir.path().string(), "", "x").outcome == SwapOutcome::kFailed);
}

TEST_CASE("compare-and-write through a link replaces its target and keeps the link", "[base][swap]") {
  const rs::testing::TempDir dir;
  fs::create_directories(dir.path() / "real");
  const std::string target = dir.write("real/p.rsp", "v1\n");
  fs::create_symlink("real/p.rsp", dir.file("p.rsp"));
  CHECK(replaceFileIfUnchanged(dir.file("p.rsp"), "v1\n", "v2\n").outcome == SwapOutcome::kWritten);
  CHECK(fs::is_symlink(dir.file("p.rsp")));
  CHECK(readBytes(target) == "v2\n");
  CHECK(filesIn(dir.path() / "real") == std::vector<std::string>{"p.rsp"});
}

TEST_CASE("compare-and-write gives way to a program that has the file open for writing", "[base][swap]") {
  // An editor in the middle of a save in place: the file is open for
  // writing, perhaps cut short. Nothing is written while it is.
  const rs::testing::TempDir dir;
  const std::string path = dir.write("p.rsp", "v1\n");
  const int editor = ::open(path.c_str(), O_WRONLY);
  REQUIRE(editor >= 0);
  const auto t0 = std::chrono::steady_clock::now();
  CHECK(replaceFileIfUnchanged(path, "v1\n", "v2\n").outcome == SwapOutcome::kBusy);
  CHECK(std::chrono::steady_clock::now() - t0 >= std::chrono::milliseconds(400));  // it waited for the save to end
  CHECK(readBytes(path) == "v1\n");
  // Once the editor closes it, the write goes through.
  std::thread closer([editor] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    ::close(editor);
  });
  CHECK(replaceFileIfUnchanged(path, "v1\n", "v2\n").outcome == SwapOutcome::kWritten);
  closer.join();
  CHECK(readBytes(path) == "v2\n");
  CHECK(filesIn(dir.path()) == std::vector<std::string>{"p.rsp"});
}

TEST_CASE("a read that waits for a save in place to end gets the whole file", "[base][swap]") {
  const rs::testing::TempDir dir;
  const std::string path = dir.write("p.rsp", "old text\n");
  // The editor truncates, then writes the new text 150 ms later.
  const int editor = ::open(path.c_str(), O_WRONLY | O_TRUNC);
  REQUIRE(editor >= 0);
  std::atomic<bool> wrote{false};
  std::thread finish([editor, &wrote] {  // no Catch2 macro on another thread
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    wrote = ::write(editor, "new text\n", 9) == 9;
    ::close(editor);
  });
  const rs::base::FileRead read = rs::base::readFileWhenQuiet(path, 1 << 20);
  finish.join();
  REQUIRE(wrote);
  REQUIRE(read.bytes);
  CHECK(*read.bytes == "new text\n");  // never the empty file of the moment
}
