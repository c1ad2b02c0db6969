#include "teach/program_file.h"

#include <fmt/format.h>

#include "base/file_io.h"

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

std::optional<ProgramFile> ProgramFile::load(const std::string& path, std::string& error) {
  base::FileRead read = base::readFile(path, kMaxProgramBytes);
  if (!read.bytes) {
    error = fmt::format("cannot read {}: {}", path, read.error);
    return std::nullopt;
  }
  ProgramFile f;
  f.path_ = path;
  f.points_ = PointsText(*read.bytes);
  f.hash_ = textHash(*read.bytes);
  return f;
}

std::string ProgramFile::reload() {
  std::string error;
  std::optional<ProgramFile> again = load(path_, error);
  if (!again) return error;
  points_ = std::move(again->points_);
  hash_ = again->hash_;
  return {};
}

std::string ProgramFile::write(PointsText next) {
  base::FileRead now = base::readFile(path_, kMaxProgramBytes);
  if (!now.bytes) return fmt::format("cannot read {} before writing it: {}", path_, now.error);
  if (textHash(*now.bytes) != hash_)
    return fmt::format(
        "{} changed on disk since teach read it (someone edited it): not written, so their change is kept; "
        "reload the file to teach on top of it",
        path_);
  std::string error;
  if (!backedUp_) {
    if (!base::writeFileAtomically(path_ + ".bak", *now.bytes, error))
      return fmt::format("cannot write {}.bak: {}; {} not written", path_, error, path_);
    backedUp_ = true;
  }
  const std::string text = next.text();
  if (!base::writeFileAtomically(path_, text, error)) return fmt::format("cannot write {}: {}", path_, error);
  points_ = std::move(next);
  hash_ = textHash(text);
  return {};
}

}  // namespace rs::teach
