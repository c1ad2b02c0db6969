#include "tools/teach/commands.h"
#include "vm/io_lines.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace rs::teach {

namespace {

using Json = nlohmann::json;

Outcome bad(std::string message) { return {false, std::move(message), true}; }

// A JSON value as a 32-bit integer, or nullopt. nlohmann-json keeps a
// number of 2^63 and above as unsigned: read as a signed one it would wrap
// (18446744073709551615 would be -1), so each kind is checked as itself.
std::optional<std::int32_t> int32Of(const Json& v) {
  if (v.is_number_unsigned()) {
    const std::uint64_t u = v.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max())) return std::nullopt;
    return static_cast<std::int32_t>(u);
  }
  if (!v.is_number_integer()) return std::nullopt;
  const std::int64_t i = v.get<std::int64_t>();
  if (i < std::numeric_limits<std::int32_t>::min() || i > std::numeric_limits<std::int32_t>::max()) return std::nullopt;
  return static_cast<std::int32_t>(i);
}

// The argument `key` as a 32-bit integer, or nullopt.
std::optional<std::int32_t> intArg(const Json& r, const char* key) {
  const auto it = r.find(key);
  if (it == r.end()) return std::nullopt;
  return int32Of(*it);
}

std::optional<std::string> stringArg(const Json& r, const char* key) {
  const auto it = r.find(key);
  if (it == r.end() || !it->is_string()) return std::nullopt;
  return it->get<std::string>();
}

std::optional<bool> boolArg(const Json& r, const char* key) {
  const auto it = r.find(key);
  if (it == r.end() || !it->is_boolean()) return std::nullopt;
  return it->get<bool>();
}

}  // namespace

Outcome applyCommand(Pendant& p, const Json& r) {
  if (!r.is_object()) return bad("a request is a JSON object with an \"op\"");
  const std::optional<std::string> op = stringArg(r, "op");
  if (!op) return bad("a request needs \"op\", a string");
  const auto name = stringArg(r, "name");
  if (*op == "jog" || *op == "set") {
    const auto motor = intArg(r, "motor"), amount = intArg(r, *op == "jog" ? "delta" : "value");
    if (!motor || *motor < 0 || !amount)
      return bad(fmt::format("{} needs \"motor\" (0-based) and \"{}\", whole numbers from -2147483648 to 2147483647",
                             *op, *op == "jog" ? "delta" : "value"));
    return *op == "jog" ? p.jog(static_cast<std::size_t>(*motor), *amount)
                        : p.setMotor(static_cast<std::size_t>(*motor), *amount);
  }
  if (*op == "jogCartesian") {
    const auto frame = stringArg(r, "frame"), axis = stringArg(r, "axis");
    const auto amount = r.find("amount");
    if (!frame || (*frame != "world" && *frame != "tool") || !axis || amount == r.end() || !amount->is_number() ||
        !std::isfinite(amount->get<double>()) || std::abs(amount->get<double>()) > 1e6)
      return bad("jogCartesian needs \"frame\" (\"world\" or \"tool\"), \"axis\" (a name of the state's jogAxes) and "
                 "\"amount\", a number of length units or degrees up to 1000000 either way");
    return p.jogCartesian(*frame == "world" ? workcell::JogFrame::World : workcell::JogFrame::Tool, *axis,
                          amount->get<double>());
  }
  if (*op == "moveTo") {
    const auto it = r.find("values");
    if (it == r.end() || !it->is_array() || it->size() > 64) return bad("moveTo needs \"values\", one per motor");
    std::vector<std::int32_t> values;
    for (const Json& v : *it) {
      const std::optional<std::int32_t> value = int32Of(v);
      if (!value) return bad("moveTo's values are whole numbers from -2147483648 to 2147483647");
      values.push_back(*value);
    }
    return p.moveTo(values);
  }
  if (*op == "gripper") {
    const auto close = boolArg(r, "close");
    if (!close) return bad("gripper needs \"close\", true or false");
    return p.gripper(*close);
  }
  if (*op == "teach" || *op == "reteach" || *op == "delete" || *op == "goTo") {
    if (!name) return bad(fmt::format("{} needs \"name\", a string", *op));
    if (*op == "teach") return p.teach(*name);
    if (*op == "reteach") {
      // "as": how a point written as a tool pose is re-taught ("pose" or "counts").
      if (r.find("as") == r.end()) return p.reteach(*name);
      const auto as = stringArg(r, "as");
      if (!as || (*as != "pose" && *as != "counts")) return bad("reteach's \"as\" is \"pose\" or \"counts\"");
      return p.reteach(*name, *as == "pose" ? Pendant::Reteach::Pose : Pendant::Reteach::Counts);
    }
    if (*op == "delete") return p.remove(*name);
    return p.goTo(*name);
  }
  if (*op == "rename") {
    const auto from = stringArg(r, "from"), to = stringArg(r, "to");
    if (!from || !to) return bad("rename needs \"from\" and \"to\", strings");
    return p.rename(*from, *to);
  }
  if (*op == "input") {
    const auto line = intArg(r, "line");
    if (!line) return bad(fmt::format("input needs \"line\", 1..{}", vm::kIoCount));
    return p.toggleInput(*line);
  }
  if (*op == "output") {
    const auto line = intArg(r, "line");
    const auto on = boolArg(r, "on");
    if (!line || !on) return bad(fmt::format("output needs \"line\", 1..{}, and \"on\", true or false", vm::kIoCount));
    return p.setOutput(*line, *on);
  }
  if (*op == "runCell") {
    const auto seconds = r.find("seconds");
    if (seconds == r.end() || !seconds->is_number())
      return bad(fmt::format("runCell needs \"seconds\", a number above 0 and at most {}", Pendant::kMaxRunCell));
    return p.runCell(seconds->get<double>());
  }
  if (*op == "reset") return p.resetCell();
  if (*op == "readPosition") return p.readPosition();
  if (*op == "reload") return p.reload();
  return bad(fmt::format("unknown op \"{}\"", *op));
}

}  // namespace rs::teach
