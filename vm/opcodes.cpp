#include "vm/opcodes.h"

namespace rs::vm {

namespace {
char upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }
}  // namespace

std::optional<Op> opByName(std::string_view name) {
  for (const OpInfo& op : kOps) {
    if (op.name.size() != name.size()) continue;
    bool same = true;
    for (std::size_t i = 0; i < name.size() && same; ++i) same = upper(name[i]) == op.name[i];
    if (same) return op.op;
  }
  return std::nullopt;
}

}  // namespace rs::vm
