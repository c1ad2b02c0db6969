// The programs `robotsim test --spec` grades: the `.rsp` files under the
// folders named (at any depth) and the files named. A submission is
// confined to the folder it is graded in (the folder named; for a file
// named, its own folder): a symbolic link that leads out of it (to
// /etc/passwd, to another student's home) or to nowhere is refused by name
// and never read, and the others are graded. A link that stays inside is
// followed for a file; a folder reached through a link is not walked again
// (what it holds inside the folder is walked where it is).
#pragma once

#include <string>
#include <vector>

#include "diag/diagnostic.h"

namespace rs::testrun {

/// A path found in a walk and not graded: a link that leads out of the
/// folder (or cannot be followed).
struct RefusedLink {
  std::string path;    ///< the link, as found
  std::string target;  ///< where it leads, when it can be followed
  std::string folder;  ///< the folder it had to stay in
  std::string reason;  ///< why it cannot be followed (a loop, nothing there), or ""
};

struct SubmissionWalk {
  std::vector<std::string> files;        ///< regular files inside their folder, sorted, each once
  std::vector<RefusedLink> refused;      ///< sorted by path
  std::vector<diag::Diagnostic> errors;  ///< paths that do not exist or cannot be listed
};

SubmissionWalk findSubmissions(const std::vector<std::string>& paths);

/// The problem a refused link is reported as: its name, where it leads,
/// the folder it left.
diag::Diagnostic refusalOf(const RefusedLink& link);

}  // namespace rs::testrun
