#include "launch/confined_path.h"

namespace rs::launch {

namespace fs = std::filesystem;

// By components, so that /a/bc is not taken to be inside /a/b.
bool isInside(const fs::path& folder, const fs::path& path) {
  auto f = folder.begin(), p = path.begin();
  for (; f != folder.end(); ++f, ++p) {
    if (f->empty()) continue;  // the trailing "" of "/a/b/"
    if (p == path.end() || *f != *p) return false;
  }
  return true;
}

diag::Result<fs::path> resolve(const fs::path& path, bool mustExist) {
  std::error_code ec;
  fs::path target;
  // Absolute first: of a relative path none of whose parts exists,
  // weakly_canonical gives back the relative path.
  const fs::path absolute = fs::absolute(path, ec);
  if (!ec) target = mustExist ? fs::canonical(absolute, ec) : fs::weakly_canonical(absolute, ec);
  if (ec) return diag::refusal(ec.message());
  return target;
}

}  // namespace rs::launch
