#include "tools/lsp/params.h"

#include <fmt/format.h>

#include <limits>

namespace rs::lsp {

namespace {

constexpr std::int64_t kMaxLspInteger = std::numeric_limits<std::int32_t>::max();
constexpr std::int64_t kMinLspInteger = std::numeric_limits<std::int32_t>::min();

}  // namespace

std::string_view jsonTypeName(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned: return "an integer";
    case Json::value_t::number_float: return "a number with a fraction";
    case Json::value_t::string: return "a string";
    case Json::value_t::array: return "an array";
    case Json::value_t::object: return "an object";
    case Json::value_t::binary:
    case Json::value_t::discarded: break;
  }
  return "something else";
}

void Field::wrong(std::string_view expected) const {
  throw BadParams(fmt::format("{}: expected {}, found {}", path_, expected,
                              value_ ? jsonTypeName(*value_) : std::string_view("nothing (it is required)")));
}

const Json& Field::required(std::string_view expected) const {
  if (!value_) wrong(expected);
  return *value_;
}

Field Field::operator[](std::string_view key) const {
  std::string path = fmt::format("{}.{}", path_, key);
  if (!value_) return Field(nullptr, std::move(path));
  if (!value_->is_object()) wrong("an object");
  const auto it = value_->find(key);
  if (it == value_->end() || it->is_null()) return Field(nullptr, std::move(path));
  return Field(&*it, std::move(path));
}

std::string Field::string() const {
  const Json& v = required("a string");
  if (!v.is_string()) wrong("a string");
  return v.get<std::string>();
}

std::string Field::string(std::string_view fallback) const {
  return value_ ? string() : std::string(fallback);
}

std::int32_t Field::integer() const {
  const Json& v = required("an integer");
  // A number with a fraction is not an integer, even 1.0: the protocol's
  // integers are written without one.
  if (v.is_number_unsigned() && v.get<std::uint64_t>() <= static_cast<std::uint64_t>(kMaxLspInteger))
    return static_cast<std::int32_t>(v.get<std::uint64_t>());
  if (v.is_number_integer() && !v.is_number_unsigned() && v.get<std::int64_t>() >= kMinLspInteger &&
      v.get<std::int64_t>() <= kMaxLspInteger)
    return static_cast<std::int32_t>(v.get<std::int64_t>());
  wrong("an integer (-2147483648 to 2147483647)");
}

std::optional<std::int32_t> Field::optionalInteger() const {
  if (!value_) return std::nullopt;
  return integer();
}

std::uint32_t Field::uinteger() const {
  const Json& v = required("an unsigned integer");
  if (v.is_number_unsigned() && v.get<std::uint64_t>() <= static_cast<std::uint64_t>(kMaxLspInteger))
    return static_cast<std::uint32_t>(v.get<std::uint64_t>());
  if (v.is_number_integer() && !v.is_number_unsigned() && v.get<std::int64_t>() >= 0 &&
      v.get<std::int64_t>() <= kMaxLspInteger)
    return static_cast<std::uint32_t>(v.get<std::int64_t>());
  wrong("an unsigned integer (0 to 2147483647)");
}

bool Field::boolean() const {
  const Json& v = required("a boolean");
  if (!v.is_boolean()) wrong("a boolean");
  return v.get<bool>();
}

bool Field::boolean(bool fallback) const { return value_ ? boolean() : fallback; }

std::size_t Field::size(bool isRequired) const {
  if (!value_ && !isRequired) return 0;
  const Json& v = required("an array");
  if (!v.is_array()) wrong("an array");
  return v.size();
}

Field Field::element(std::size_t i) const {
  std::string path = fmt::format("{}[{}]", path_, i);
  // An element is there even when it is null (a null in a list of strings
  // is a wrong element, not a missing one).
  if (!value_ || !value_->is_array() || i >= value_->size()) return Field(nullptr, std::move(path));
  return Field(&(*value_)[i], std::move(path));
}

const Json& Field::object() const {
  const Json& v = required("an object");
  if (!v.is_object()) wrong("an object");
  return v;
}

const Json& Field::any() const { return required("a value"); }

}  // namespace rs::lsp
