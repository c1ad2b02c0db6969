// The program file a teach session edits: read once, its points edited in
// memory (points_edit.h), written back after every change. Someone may
// edit the file in an editor meanwhile: every write replaces the file only
// while it holds exactly the text the session loaded or last wrote
// (base/file_swap.h: compared under a lease, exchanged, checked, undone
// when an editor saved in between), so their change is never lost; the
// write is refused, and says why, when the file changed or an editor is
// saving it. The file keeps its mode; the first write of a session keeps
// the file as it was in PROG.rsp.bak, with the program's mode.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "diag/result.h"
#include "tools/teach/points_edit.h"

namespace rs::teach {

/// FNV-1a, 64 bits: the file's fingerprint (not a defence against an
/// attacker, who could write the file anyway; a check that nobody did).
std::uint64_t textHash(std::string_view bytes);

class ProgramFile {
 public:
  /// Reads `path`; when it cannot be read, a diagnostic for the whole
  /// command ("robotsim: error: cannot read PATH: REASON").
  static diag::Result<ProgramFile> load(const std::string& path);

  const std::string& path() const { return path_; }
  const PointsText& points() const { return points_; }
  /// The hash of the text on disk as this session last saw it.
  std::uint64_t hash() const { return hash_; }

  /// Applies `edit` to a copy of the points and writes it; "" when written,
  /// else why not (the edit's refusal, the file changed on disk, the
  /// system's error), and nothing changes.
  template <typename Edit>
  std::string change(Edit&& edit) {
    PointsText next = points_;
    if (std::string why = edit(next); !why.empty()) return why;
    return write(std::move(next));
  }
  /// Reads the file again (after someone edited it): its points become the session's.
  std::string reload();

 private:
  std::string write(PointsText next);

  std::string path_;
  PointsText points_{""};
  std::uint64_t hash_ = 0;
  bool backedUp_ = false;
};

}  // namespace rs::teach
