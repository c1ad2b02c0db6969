// A page opened in the desktop's browser (xdg-open), for the commands that
// serve one (teach, debug --view). The page's address carries its secret
// token, and a command line is readable by every local user (ps, /proc):
// so xdg-open is given a file instead, readable by this user only (0600,
// in a folder only this user can enter), that sends the browser on to the
// address. The file goes when the command ends.
#pragma once

#include <string>

namespace rs::cli {

/// The private file handed to the browser; removed with its folder when it goes.
class PageLink {
 public:
  PageLink() = default;
  ~PageLink();
  PageLink(const PageLink&) = delete;
  PageLink& operator=(const PageLink&) = delete;

  const std::string& path() const { return path_; }

 private:
  friend bool openBrowser(const std::string&, PageLink&, std::string&);
  std::string folder_;
  std::string path_;
};

/// Writes `link` for `url` and starts xdg-open on it (its output is not
/// ours); false, with `error` set, when either cannot be done.
bool openBrowser(const std::string& url, PageLink& link, std::string& error);

}  // namespace rs::cli
