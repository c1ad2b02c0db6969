// Compare-and-write of a file another program may be editing (the teach
// pendant's program, open in the student's editor): the file is replaced
// only while it holds exactly the bytes the caller last saw, and a byte
// another program wrote is never lost.
//
// How, on Linux (docs/teach.md, "Someone else edits the file"):
//   1. A read lease on the file (fcntl F_SETLEASE): granted only while no
//      one has it open for writing, so an editor saving in place is not in
//      the middle of a save; while it is held, an editor opening the file
//      to write waits (for a few milliseconds) and the lease says so.
//   2. The file read under it and compared with the expected bytes.
//   3. The new text written to a temporary file beside it (file_write.h:
//      exclusive, the mode and owner kept, fsync).
//   4. The temporary and the file exchanged in one step
//      (renameat2 RENAME_EXCHANGE): the old file is then at the temporary's
//      name, not gone, and what was exchanged out can be checked. If it is
//      not the file that was compared (an editor saving atomically renamed
//      its file in meanwhile), or an editor asked to write the old file
//      while it was leased, or it changed, the exchange is undone, so that
//      their file is at the name again, and nothing of ours stays. Our file
//      carries a write lease meanwhile: whoever opens it while it is at the
//      name waits, and then reads the bytes of their file, not ours.
// Where the file system cannot exchange, a plain rename follows a last
// check; where no lease can be had (a file of another owner, a network
// file system), the stat of the file is compared instead.
#pragma once

#include <string>
#include <string_view>

#include "base/file_io.h"

namespace rs::base {

enum class SwapOutcome {
  kWritten,  ///< the file held the expected bytes and now holds the new ones
  kChanged,  ///< the file holds something else: nothing written
  kBusy,     ///< another program was writing it: nothing written; try again
  kFailed,   ///< the system refused (see error): nothing written
};

struct SwapResult {
  SwapOutcome outcome = SwapOutcome::kFailed;
  std::string error;  ///< for kFailed
};

/// Replaces the regular file `path` (a link: its final target) by `bytes`
/// if, and only if, it holds exactly `expected`.
SwapResult replaceFileIfUnchanged(const std::string& path, std::string_view expected, std::string_view bytes);

/// Reads `path` as readFile does, but not while another program has it
/// open for writing (waits up to half a second for it to finish, then reads
/// anyway): a file read in the middle of an editor's save would be cut.
FileRead readFileWhenQuiet(const std::string& path, std::size_t limit);

}  // namespace rs::base
