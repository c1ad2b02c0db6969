// A page opened in the desktop's browser (xdg-open), for the commands that
// serve one (teach, debug --view).
#pragma once

#include <string>

namespace rs::cli {

/// Starts xdg-open on `url` (its output is not ours); false when it cannot start.
bool openBrowser(const std::string& url);

}  // namespace rs::cli
