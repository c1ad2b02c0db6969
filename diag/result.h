// What every function that reads or resolves input answers: its value, or
// the diagnostics that say why there is none. It lives in diag/, the lowest
// layer that knows Diagnostic; base/ stays below it and reports the system's
// reason as a sentence (base::FileRead), which read_input.h turns into a
// Diagnostic in one place.
#pragma once

#include <cassert>
#include <optional>
#include <utility>
#include <vector>

#include "diag/diagnostic.h"

namespace rs::diag {

/// A value, or one diagnostic (or several, where a reader reports every
/// mistake it finds), never both and never neither.
template <class T>
class Result {
 public:
  Result(T value) : value_(std::move(value)) {}  // NOLINT: a value is a result
  Result(Diagnostic failure) { failures_.push_back(std::move(failure)); }  // NOLINT: so is a failure
  /// Several failures: there must be at least one.
  explicit Result(std::vector<Diagnostic> failures) : failures_(std::move(failures)) { assert(!failures_.empty()); }

  bool ok() const { return value_.has_value(); }
  explicit operator bool() const { return ok(); }

  T& value() & { return *value_; }
  const T& value() const& { return *value_; }
  T&& value() && { return std::move(*value_); }
  T& operator*() & { return *value_; }
  const T& operator*() const& { return *value_; }
  T* operator->() { return &*value_; }
  const T* operator->() const { return &*value_; }

  /// Why there is no value (empty when there is one).
  const std::vector<Diagnostic>& failures() const& { return failures_; }
  std::vector<Diagnostic>&& failures() && { return std::move(failures_); }
  /// The first of them: most readers report exactly one.
  const Diagnostic& failure() const { return failures_.front(); }

 private:
  std::optional<T> value_;
  std::vector<Diagnostic> failures_;
};

/// A failure that concerns no file and no place in one: what a command
/// refuses about its own input (a debugger's expression, a breakpoint's
/// place). Printed as the message alone.
inline Diagnostic refusal(std::string message) { return {{}, {}, Severity::Error, std::move(message)}; }

}  // namespace rs::diag
