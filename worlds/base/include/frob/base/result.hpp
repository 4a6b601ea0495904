#pragma once
/// The result of every step of the house that can fail on outside data (files, sizes, paths, world
/// files, rubrics, compiles): a value or a readable message saying what went wrong and with which
/// file. Nothing of ours throws for such failures; they come back as these.

#include "frob/assert.hpp"

#include <optional>
#include <string>
#include <utility>

namespace frob {

/// Success, or a readable message saying what went wrong and with which file.
class Status {
 public:
  Status() = default;  ///< success
  /// A failure carrying `message`.
  [[nodiscard]] static Status failure(std::string message) { return Status(std::move(message)); }
  /// True when nothing went wrong.
  [[nodiscard]] bool ok() const { return !failed_; }
  /// True when nothing went wrong.
  explicit operator bool() const { return ok(); }
  /// The message; empty on success.
  [[nodiscard]] const std::string& error() const { return message_; }

 private:
  explicit Status(std::string message) : message_(std::move(message)), failed_(true) {}
  std::string message_;
  bool failed_ = false;
};

/// A value of type T, or the readable message of why there is none.
template <class T>
class Result {
 public:
  /// A success holding `value`.
  Result(T value) : value_(std::move(value)) {}  // NOLINT(google-explicit-constructor)
  /// A failure carrying the message of `status` (which must have failed).
  Result(Status status) : status_(std::move(status)) {  // NOLINT(google-explicit-constructor)
    FROB_ASSERT(!status_.ok(), "a Result made from a Status that did not fail");
  }
  /// True when a value is held.
  [[nodiscard]] bool ok() const { return value_.has_value(); }
  /// True when a value is held.
  explicit operator bool() const { return ok(); }
  /// The value; asking for it after a failure is a programmer's mistake (FROB_ASSERT).
  [[nodiscard]] T& value() { return checked(), *value_; }
  /// The value; asking for it after a failure is a programmer's mistake (FROB_ASSERT).
  [[nodiscard]] const T& value() const { return checked(), *value_; }
  /// As value().
  [[nodiscard]] const T& operator*() const { return checked(), *value_; }
  /// As value().
  [[nodiscard]] const T* operator->() const { return checked(), &*value_; }
  /// The message; empty on success.
  [[nodiscard]] const std::string& error() const { return status_.error(); }
  /// The outcome without the value.
  [[nodiscard]] const Status& status() const { return status_; }

 private:
  void checked() const { FROB_ASSERT(value_.has_value(), "the value of a failed Result was asked for"); }
  std::optional<T> value_;
  Status status_;
};

}  // namespace frob
