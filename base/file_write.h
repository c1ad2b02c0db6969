// Writing what a command produces to the path a user named, without ever
// damaging what is there:
//
//   - a regular file (or a new one) is replaced atomically: a temporary
//     file is created exclusively beside it (O_EXCL: a link planted at its
//     name is never followed), given the mode and, where the system lets
//     us, the owner of the file it replaces, written, flushed to disk
//     (fsync) and renamed over it; on any failure the file is untouched;
//   - a symbolic link is written through: its final target is replaced as
//     above, in the target's folder, keeping the target's mode, and the
//     link stays a link;
//   - a device, a FIFO or a socket is written in place, never renamed over
//     (`-o /dev/null` discards, `-o /dev/pts/3` prints, a FIFO feeds its
//     reader; a FIFO nobody reads is an error, not a hang);
//   - `-` is standard output.
//
// A directory is refused. The rules are docs/cli.md's "Output files".
#pragma once

#include <sys/stat.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace rs::base {

struct WriteOptions {
  /// The permission bits of the file written. Unset: those of the file it
  /// replaces, or, for a new file, 0666 less the umask.
  std::optional<unsigned> mode;
  /// false: a link at `path` is replaced itself, never followed (for the
  /// names robotsim makes up, like PROG.rsp.bak, where a link someone
  /// planted must not send the write elsewhere).
  bool followLinks = true;
};

/// Writes all bytes or nothing; on failure returns false and sets `error`
/// (the system's reason, with the folder or file it concerns).
bool writeFileAtomically(const std::string& path, std::string_view bytes, std::string& error,
                         const WriteOptions& options = {});
bool writeFileAtomically(const std::string& path, const std::vector<std::uint8_t>& bytes, std::string& error,
                         const WriteOptions& options = {});
/// The same, with the bytes written by `write` as it makes them (never held
/// whole); `write` returns false when it failed.
bool writeFileAtomically(const std::string& path, const std::function<bool(std::ostream&)>& write, std::string& error,
                         const WriteOptions& options = {});

/// Where a write of `path` lands: `path` itself, or the final target of the
/// symbolic link(s) it names (a relative link read from the link's folder).
/// Empty, with `error` set, for a loop of links.
std::string finalTarget(const std::string& path, std::string& error);

/// A fresh file created exclusively (O_EXCL, never through a link) beside
/// `target`, named `.NAME.XXXXXX.tmp`, with `mode` (the umask applies);
/// its descriptor, its path in `tmpPath`, or -1 with `error` set.
int createTemporaryBeside(const std::string& target, unsigned mode, std::string& tmpPath, std::string& error);

/// Gives the file open as `fd` the owner (where the system lets us) and the
/// mode of the file `like` was stat'ed from, or `mode` when set; "" when
/// done, else why not.
std::string takeOwnerAndMode(int fd, const struct stat& like, std::optional<unsigned> mode = {});

/// fsync of the folder holding `path`, so that a rename in it survives a
/// power cut (best effort: some file systems refuse it).
void syncFolderOf(const std::string& path);

}  // namespace rs::base
