#include "vm/opcodes.h"

#include <cstdint>

#include "base/ascii.h"

namespace rs::vm {

namespace {

// A name of up to 8 characters packed into one integer, upper-cased: the
// lookup compares 20 integers instead of 20 strings (it runs for every
// instruction and every name a program defines).
constexpr std::uint64_t packUpper(std::string_view name) {
  std::uint64_t key = 0;
  for (std::size_t i = 0; i < name.size(); ++i)
    key |= std::uint64_t{static_cast<unsigned char>(base::asciiUpper(name[i]))} << (8 * i);
  return key;
}

constexpr std::size_t kMaxMnemonic = 8;

constexpr bool mnemonicsFit() {
  for (const OpInfo& op : kOps)
    if (op.name.empty() || op.name.size() > kMaxMnemonic) return false;
  return true;
}
static_assert(mnemonicsFit(), "mnemonics must have 1 to 8 characters for opByName's packed keys");

constexpr auto kKeys = [] {
  std::array<std::uint64_t, kOpCount> keys{};
  for (std::size_t i = 0; i < kOps.size(); ++i) keys[i] = packUpper(kOps[i].name);
  return keys;
}();

}  // namespace

std::optional<Op> opByName(std::string_view name) {
  if (name.empty() || name.size() > kMaxMnemonic) return std::nullopt;
  // A zero byte would pack like a shorter name: only letters, digits and '_' reach here, but be exact anyway.
  if (name.find('\0') != std::string_view::npos) return std::nullopt;
  const std::uint64_t key = packUpper(name);
  for (std::size_t i = 0; i < kKeys.size(); ++i)
    if (kKeys[i] == key) return kOps[i].op;
  return std::nullopt;
}

bool isReservedWord(std::string_view word) {
  return opByName(word).has_value() || base::sameName(word, "ON") || base::sameName(word, "OFF") ||
         base::sameName(word, "POINTS");
}

}  // namespace rs::vm
