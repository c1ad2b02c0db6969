#include "tools/teach/program_file.h"

#include <fmt/format.h>
#include <sys/stat.h>

#include "base/file_swap.h"
#include "diag/read_input.h"

namespace rs::teach {

namespace {
// The compiler's own limit on programs (launch::kMaxInputBytes).
constexpr std::size_t kMaxProgramBytes = std::size_t{256} << 20;
}  // namespace

std::uint64_t textHash(std::string_view bytes) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

diag::Result<ProgramFile> ProgramFile::load(const std::string& path) {
  base::FileRead read = base::readFileWhenQuiet(path, kMaxProgramBytes);
  if (!read.bytes) return diag::fromFileRead("robotsim", std::move(read), "cannot read " + path).failure();
  ProgramFile f;
  f.path_ = path;
  f.points_ = PointsText(*read.bytes);
  f.hash_ = textHash(*read.bytes);
  return f;
}

std::string ProgramFile::reload() {
  diag::Result<ProgramFile> again = load(path_);
  if (!again) return again.failure().message;
  points_ = std::move(again->points_);
  hash_ = again->hash_;
  return {};
}

std::string ProgramFile::write(PointsText next) {
  const std::string expected = points_.text();  // the bytes this session last saw, exactly
  std::string error;
  if (!backedUp_) {
    // The backup is no more readable than the program: it gets its mode.
    struct stat st {};
    base::WriteOptions backup;
    backup.followLinks = false;  // a name teach makes up: a link planted there is replaced, not followed
    if (::stat(path_.c_str(), &st) == 0) backup.mode = static_cast<unsigned>(st.st_mode & 0777);
    if (!base::writeFileAtomically(path_ + ".bak", expected, error, backup))
      return fmt::format("cannot write {}.bak: {}; {} not written", path_, error, path_);
    backedUp_ = true;
  }
  const std::string text = next.text();
  const base::SwapResult written = base::replaceFileIfUnchanged(path_, expected, text);
  switch (written.outcome) {
    case base::SwapOutcome::kWritten:
      points_ = std::move(next);
      hash_ = textHash(text);
      return {};
    case base::SwapOutcome::kChanged:
      return fmt::format(
          "{} changed on disk since teach read it (someone edited it): not written, so their change is kept; "
          "reload the file to teach on top of it",
          path_);
    case base::SwapOutcome::kBusy:
      return fmt::format(
          "{} is being written by another program right now (an editor saving it?): not written, so nothing of "
          "theirs is lost; try again in a moment",
          path_);
    case base::SwapOutcome::kFailed: break;
  }
  return fmt::format("cannot write {}: {}", path_, written.error);
}

}  // namespace rs::teach
