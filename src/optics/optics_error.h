// OpticsError: the one exception type of the optics library. Thrown only while building or
// validating a system (bad prescription, bad options, unreadable lens file), never per ray:
// the tracer reports ray failures as a TraceStatus instead.
#pragma once

#include <stdexcept>
#include <string>

namespace eyetrace::optics {

class OpticsError : public std::runtime_error {
public:
    explicit OpticsError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace eyetrace::optics
