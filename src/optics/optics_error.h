// OpticsError: the one exception type of the optics library. Thrown only while building or
// validating a system (bad prescription, bad options, unreadable lens file), never per ray:
// the tracer reports ray failures as a TraceStatus instead.
#pragma once

#include <stdexcept>
#include <string>

namespace eyetrace::optics {

// option(): the eye option the error concerns ("pupildiameter", ...), empty when none; message()
// is the text without it, so callers name the option in their own terms without parsing what().
class OpticsError : public std::runtime_error {
 public:
  explicit OpticsError(const std::string& message) : std::runtime_error(message), message_(message) {}
  OpticsError(std::string option, const std::string& message)
      : std::runtime_error("eye option '" + option + "': " + message), option_(std::move(option)), message_(message) {}
  const std::string& option() const { return option_; }
  const std::string& message() const { return message_; }

 private:
  std::string option_;
  std::string message_;
};

}  // namespace eyetrace::optics
