#include "runtime/run/labelled_trace.h"

#include <nlohmann/json.hpp>

#include "base/text.h"

namespace rs::runtime {

bool LabelledTrace::afterStep(const vm::Interpreter& vm, std::uint32_t index) {
  const bool pause = writer_.afterStep(vm, index);
  flush();
  return pause;
}

void LabelledTrace::finish() {
  writer_.finish();
  flush();
}

void LabelledTrace::flush() {
  std::string line;
  std::istringstream lines(buffer_.str());
  while (std::getline(lines, line)) {
    if (json_ && line.starts_with('{'))
      out_ << "{\"robot\":"
           << nlohmann::ordered_json(label_).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)
           << (line.size() > 2 ? "," : "") << line.substr(1) << '\n';
    else out_ << base::safeText(label_) << ": " << line << '\n';
  }
  buffer_.str({});
}

}  // namespace rs::runtime
