#pragma once
// Exception types of the runtime. Every message is meant to be shown to a
// user as-is: OpenCL codes are always translated to their names.
#include <stdexcept>
#include <string>

namespace sdfrt {

// Name of an OpenCL status code, e.g. -5 -> "CL_OUT_OF_RESOURCES".
// Unknown codes give "unknown OpenCL error <n>".
std::string cl_error_name(int code);

// Anything that went wrong talking to OpenCL: no platform, no device,
// an unknown device id, a failed API call.
class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The kernel source did not compile. what() holds the build log and the
// generated source lines around every reported error.
class BuildError : public DeviceError {
 public:
  BuildError(const std::string& message, std::string build_log)
      : DeviceError(message), build_log_(std::move(build_log)) {}
  const std::string& build_log() const noexcept { return build_log_; }

 private:
  std::string build_log_;
};

// A file could not be written; the message names the path and strerror.
class IoError : public std::runtime_error {
 public:
  IoError(const std::string& message, std::string path, int errno_value)
      : std::runtime_error(message), path_(std::move(path)), errno_value_(errno_value) {}
  const std::string& path() const noexcept { return path_; }
  int errno_value() const noexcept { return errno_value_; }

 private:
  std::string path_;
  int errno_value_;
};

// A render was stopped through its cancel flag.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("render cancelled") {}
};

}  // namespace sdfrt
