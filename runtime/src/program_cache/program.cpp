#include <sdfrt/program.hpp>

#include "device/cl_check.hpp"
#include "program_cache/binary_cache.hpp"
#include "program_cache/build_log_context.hpp"
#include "program_cache/cache_key.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <chrono>
#include <sstream>

namespace sdfrt {
namespace {

std::string build_log_of(cl_program program, cl_device_id device) {
  std::size_t size = 0;
  if (clGetProgramBuildInfo(program, device, CL_PROGRAM_BUILD_LOG, 0, nullptr, &size) !=
          CL_SUCCESS ||
      size == 0) {
    return {};
  }
  std::string log(size, '\0');
  if (clGetProgramBuildInfo(program, device, CL_PROGRAM_BUILD_LOG, size, log.data(), nullptr) !=
      CL_SUCCESS) {
    return {};
  }
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

[[noreturn]] void throw_build_error(const Device& device, cl_int status, const std::string& log,
                                    const std::string& source, const std::string& options) {
  std::string message = fmt::format("OpenCL kernel build failed on {} ({}): {} ({})",
                                    device.info().device_name, device.info().id,
                                    cl_error_name(status), status);
  if (!options.empty()) message += fmt::format("\nbuild options: {}", options);
  message += "\n--- build log ---\n";
  message += log.empty() ? "(the driver gave no build log)" : log;
  if (const std::string quoted = quote_error_lines(log, source); !quoted.empty()) {
    message += "\n--- generated kernel source at the errors ---\n" + quoted;
  } else if (log.find("error") == std::string::npos) {
    // No compiler diagnostic at all: the driver itself failed, not the source.
    message += "\n(no compiler error in the log: the driver itself failed. PoCL does this when it cannot write "
               "its kernel cache: a full disk or a file size limit; the cache is in $POCL_CACHE_DIR or "
               "~/.cache/pocl)";
  }
  throw BuildError(message, log);
}

// The options handed to the driver: the caller's plus -w. PoCL's compiler
// prints "N warnings generated." straight to our stderr, which `-q` cannot
// silence; errors still reach the build log and the BuildError.
std::string driver_options(const std::string& options) {
  return options.empty() ? std::string("-w") : options + " -w";
}

Program build_from_source(Device& device, const std::string& source, const std::string& options,
                          std::string& log_out) {
  const char* text = source.c_str();
  const std::size_t length = source.size();
  cl_int status = CL_SUCCESS;
  ProgramHandle program(clCreateProgramWithSource(device.context(), 1, &text, &length, &status));
  check_cl(status, "clCreateProgramWithSource");
  cl_device_id id = device.id();
  const std::string cl_options = driver_options(options);
  status = clBuildProgram(program.get(), 1, &id, cl_options.c_str(), nullptr, nullptr);
  log_out = build_log_of(program.get(), id);
  if (status != CL_SUCCESS) throw_build_error(device, status, log_out, source, options);
  return Program(std::move(program));
}

// nullopt when the driver rejects the binary; the caller rebuilds from source.
std::optional<Program> build_from_binary(Device& device, const std::vector<unsigned char>& binary,
                                         const std::string& options, std::string& log_out) {
  const unsigned char* data = binary.data();
  const std::size_t size = binary.size();
  cl_device_id id = device.id();
  cl_int binary_status = CL_SUCCESS;
  cl_int status = CL_SUCCESS;
  ProgramHandle program(clCreateProgramWithBinary(device.context(), 1, &id, &size, &data,
                                                  &binary_status, &status));
  if (status != CL_SUCCESS || binary_status != CL_SUCCESS) return std::nullopt;
  const std::string cl_options = driver_options(options);
  if (clBuildProgram(program.get(), 1, &id, cl_options.c_str(), nullptr, nullptr) != CL_SUCCESS) {
    return std::nullopt;
  }
  log_out = build_log_of(program.get(), id);
  return Program(std::move(program));
}

std::vector<unsigned char> binary_of(const Program& program) {
  std::size_t size = 0;
  check_cl(clGetProgramInfo(program.get(), CL_PROGRAM_BINARY_SIZES, sizeof(size), &size, nullptr),
           "clGetProgramInfo(CL_PROGRAM_BINARY_SIZES)");
  std::vector<unsigned char> binary(size);
  unsigned char* data = binary.data();
  check_cl(clGetProgramInfo(program.get(), CL_PROGRAM_BINARIES, sizeof(data), &data, nullptr),
           "clGetProgramInfo(CL_PROGRAM_BINARIES)");
  return binary;
}

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

void Kernel::set_arg_raw(unsigned index, std::size_t size, const void* value) {
  check_cl(clSetKernelArg(handle_.get(), index, size, value),
           fmt::format("clSetKernelArg({}, arg {})", name_, index));
}

std::vector<std::string> Program::kernel_names() const {
  std::size_t size = 0;
  check_cl(clGetProgramInfo(handle_.get(), CL_PROGRAM_KERNEL_NAMES, 0, nullptr, &size),
           "clGetProgramInfo(CL_PROGRAM_KERNEL_NAMES)");
  std::string joined(size, '\0');
  check_cl(clGetProgramInfo(handle_.get(), CL_PROGRAM_KERNEL_NAMES, size, joined.data(), nullptr),
           "clGetProgramInfo(CL_PROGRAM_KERNEL_NAMES)");
  std::vector<std::string> names;
  std::istringstream in(joined.c_str());
  for (std::string name; std::getline(in, name, ';');) {
    if (!name.empty()) names.push_back(name);
  }
  return names;
}

Kernel Program::kernel(const std::string& name) const {
  cl_int status = CL_SUCCESS;
  KernelHandle handle(clCreateKernel(handle_.get(), name.c_str(), &status));
  if (status == CL_INVALID_KERNEL_NAME) {
    throw DeviceError(fmt::format("the program has no kernel named '{}' ({}); it has: {}", name,
                                  cl_error_name(status), fmt::join(kernel_names(), ", ")));
  }
  check_cl(status, fmt::format("clCreateKernel({})", name));
  return Kernel(std::move(handle), name);
}

Program build_program(Device& device, const std::string& source, const std::string& options,
                      BuildStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  BuildStats local;
  BuildStats& s = stats ? *stats : local;
  s = BuildStats{};

  std::optional<std::filesystem::path> cache_file;
  CacheKey key;
  if (!kernel_cache_enabled()) {
    s.cache_note = "kernel cache disabled by SDFC_KERNEL_CACHE";
  } else if (auto dir = kernel_cache_dir()) {
    key = make_cache_key(device.info(), source, options);
    cache_file = *dir / key.file_name();
  } else {
    s.cache_note = "no kernel cache directory (set SDFC_CACHE_DIR or HOME)";
  }

  if (cache_file) {
    if (auto binary = load_cached_binary(*cache_file, key)) {
      if (auto program = build_from_binary(device, *binary, options, s.build_log)) {
        s.cache_hit = true;
        s.cache_path = cache_file->string();
        s.build_ms = ms_since(start);
        return std::move(*program);
      }
      s.cache_note = "cached binary rejected by the driver; rebuilt from source";
    }
  }

  Program program = build_from_source(device, source, options, s.build_log);
  if (cache_file) {
    // A cache that cannot be written must never fail the build.
    try {
      std::filesystem::create_directories(cache_file->parent_path());
      store_cached_binary(*cache_file, key, binary_of(program));
      s.cache_path = cache_file->string();
    } catch (const std::exception& e) {
      s.cache_note = std::string("kernel cache not written: ") + e.what();
    }
  }
  s.build_ms = ms_since(start);
  return program;
}

}  // namespace sdfrt
