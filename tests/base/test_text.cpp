// base::safeText: what every text printer does to a name from a file.
#include <catch2/catch.hpp>

#include <string>

#include "base/text.h"

using rs::base::safeText;

TEST_CASE("safeText keeps printable text as it is", "[base]") {
  CHECK(safeText("") == "");
  CHECK(safeText("prog.rsp") == "prog.rsp");
  CHECK(safeText("dir with spaces/a\\b ~!@#$%^&*()") == "dir with spaces/a\\b ~!@#$%^&*()");
  CHECK(safeText("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\xA4\x96") == "caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\xA4\x96");
}

TEST_CASE("safeText escapes control characters byte by byte as \\xNN", "[base]") {
  CHECK(safeText("\x1b]0;pwned\x07") == "\\x1b]0;pwned\\x07");
  CHECK(safeText("a\tb\nc\rd") == "a\\x09b\\x0ac\\x0dd");
  CHECK(safeText(std::string("a\0b", 3)) == "a\\x00b");
  CHECK(safeText("\x7f") == "\\x7f");
  // C1 controls (U+0080..U+009F), whose UTF-8 form some terminals obey: U+009B is CSI.
  CHECK(safeText("\xC2\x9B" "31m") == "\\xc2\\x9b31m");
  CHECK(safeText("\xC2\xA0") == "\xC2\xA0");  // U+00A0, the first character after them, is kept
  // Bidirectional formatting characters, which reorder what is shown.
  CHECK(safeText("a\xE2\x80\xAE" "b") == "a\\xe2\\x80\\xaeb");  // U+202E
  CHECK(safeText("\xE2\x81\xA6") == "\\xe2\\x81\\xa6");           // U+2066
  CHECK(safeText("\xE2\x80\x8F") == "\\xe2\\x80\\x8f");           // U+200F
}

TEST_CASE("safeText escapes bytes that are not UTF-8", "[base]") {
  CHECK(safeText("\xFF.rsp") == "\\xff.rsp");
  CHECK(safeText("caf\xE9") == "caf\\xe9");                // Latin-1
  CHECK(safeText("\xC3") == "\\xc3");                      // cut short
  CHECK(safeText("\xC0\xAF") == "\\xc0\\xaf");             // overlong '/'
  CHECK(safeText("\xED\xA0\x80") == "\\xed\\xa0\\x80");    // a surrogate
  CHECK(safeText("\xC3" "A") == "\\xc3A");                 // a lead byte without its continuation
}

TEST_CASE("hasControlCharacter", "[base]") {
  CHECK_FALSE(rs::base::hasControlCharacter("rhino-scara"));
  CHECK_FALSE(rs::base::hasControlCharacter("caf\xC3\xA9"));
  CHECK(rs::base::hasControlCharacter("a\tb"));
  CHECK(rs::base::hasControlCharacter("\x1b"));
  CHECK(rs::base::hasControlCharacter("\x7f"));
  CHECK(rs::base::hasControlCharacter(std::string("\0", 1)));
}
