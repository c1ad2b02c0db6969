#include "cli/lib/number_list.h"

#include <charconv>
#include <cmath>
#include <fmt/format.h>

#include "base/text.h"

namespace rs::cli {

bool parseNumberList(const std::string& text, std::string_view option, std::vector<double>& out, std::ostream& err) {
  out.clear();
  std::size_t start = 0;
  for (int item = 1;; ++item) {
    const std::size_t comma = text.find(',', start);
    const std::string piece = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    double v = 0;
    const char* first = piece.data() + (!piece.empty() && piece[0] == '+' ? 1 : 0);
    const auto [ptr, ec] = std::from_chars(first, piece.data() + piece.size(), v);
    if (piece.empty() || ec != std::errc() || ptr != piece.data() + piece.size() || !std::isfinite(v)) {
      err << fmt::format("robotsim: error: {}: value {} '{}' is not a number\n", option, item, base::safeText(piece));
      return false;
    }
    out.push_back(v);
    if (comma == std::string::npos) return true;
    start = comma + 1;
  }
}

}  // namespace rs::cli
