// Reading a message's params with every field's type checked. A field of
// another type than the protocol gives it, or missing where the server
// cannot do without it, is the client's mistake: BadParams, with the
// field's path and what was expected
//
//   params.capabilities.textDocument.completion.completionItem.snippetSupport:
//   expected a boolean, found a string
//
// which the dispatcher answers with InvalidParams (a notification's is
// logged), never an exception out of the server. A field the server can do
// without may be absent or null; it then takes its default.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "tools/lsp/json.h"

namespace rs::lsp {

/// A field of the wrong type, or a required one missing.
class BadParams : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One value of a message and its path from "params". A member is absent
/// when it is missing or null; an array's element is there even when null.
/// Reads throw BadParams.
class Field {
 public:
  /// A message's params.
  explicit Field(const Json& params) : Field(&params, "params") {}

  /// A member of an object (absent when this is absent; an error when this
  /// is present and not an object).
  Field operator[](std::string_view key) const;
  bool present() const { return value_ != nullptr; }
  const std::string& path() const { return path_; }

  // Required: absent is an error too.
  std::string string() const;
  /// LSP's integer: -2^31 .. 2^31-1.
  std::int32_t integer() const;
  /// LSP's uinteger: 0 .. 2^31-1.
  std::uint32_t uinteger() const;
  bool boolean() const;
  /// An array's elements (present or not: an absent array has none when
  /// `required` is false).
  std::size_t size(bool required = true) const;
  Field element(std::size_t i) const;
  /// An object (any members): checks the type.
  const Json& object() const;
  /// Any value at all: LSPAny.
  const Json& any() const;

  // Optional: absent gives the default; present of the wrong type is an error.
  std::string string(std::string_view fallback) const;
  std::optional<std::int32_t> optionalInteger() const;
  bool boolean(bool fallback) const;

  /// Throws BadParams for this field: "PATH: expected WHAT, found TYPE".
  [[noreturn]] void wrong(std::string_view expected) const;

 private:
  Field(const Json* value, std::string path) : value_(value), path_(std::move(path)) {}
  const Json& required(std::string_view expected) const;

  const Json* value_;
  std::string path_;
};

/// "a string", "a number", "null", ...: a JSON value's type in words.
std::string_view jsonTypeName(const Json& value);

}  // namespace rs::lsp
