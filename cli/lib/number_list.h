// A list of numbers given as one option's value ("76,72,-90"), shared by
// the commands that take joint values, encoder counts or a direction.
#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace rs::cli {

/// The numbers of `text`, separated by commas, into `out` (cleared first).
/// An item that is no finite number is reported on `err` as
/// "robotsim: error: OPTION: value N 'ITEM' is not a number" and gives false.
bool parseNumberList(const std::string& text, std::string_view option, std::vector<double>& out, std::ostream& err);

}  // namespace rs::cli
