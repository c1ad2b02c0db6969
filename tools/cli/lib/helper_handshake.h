// How robotsim knows that a program at a helper's name is its own helper
// before it hands the command over (issue 32: /bin/true, or anything
// planted there, ran as `robotsim render` and said nothing). The helper is
// run once with a hidden argument, which only a helper of this very build
// answers, with a line naming the build (version, commit, build type); any
// other answer, none, or none in time refuses it. The main binary never
// answers it, so a helper that is a link back to robotsim fails it too
// (helpers.cpp refuses that one earlier, by its file's identity).
#pragma once

#include <string>
#include <string_view>

namespace rs::cli {

/// The hidden argument: `robotsim-render --robotsim-helper-handshake`.
inline constexpr std::string_view kHelperHandshakeWord = "--robotsim-helper-handshake";

/// What a helper of this build answers: "robotsim-helper VERSION COMMIT BUILDTYPE\n".
std::string helperHandshakeLine();

/// Runs the program open as `fd` with the handshake argument (standard
/// input and error on /dev/null, its answer read from a pipe, killed
/// after `seconds`): "" when it answered as a helper of this build, else
/// why not, to follow "it ...": "did not answer robotsim's handshake (it
/// printed nothing and exited with status 0)".
std::string whyNotOurHelper(int fd, double seconds = 10);

}  // namespace rs::cli
