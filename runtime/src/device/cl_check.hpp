#pragma once
// Internal: turn a failed OpenCL call into a DeviceError with the code's name.
#include <sdfrt/errors.hpp>

#include <CL/cl.h>

#include <string>
#include <string_view>

namespace sdfrt {

// "<what> failed: CL_OUT_OF_RESOURCES (-5)"
std::string cl_failure_message(std::string_view what, cl_int status);

inline void check_cl(cl_int status, std::string_view what) {
  if (status != CL_SUCCESS) throw DeviceError(cl_failure_message(what, status));
}

}  // namespace sdfrt
