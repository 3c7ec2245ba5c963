#pragma once
// Building OpenCL programs, with a persistent on-disk binary cache.
#include <sdfrt/cl_handle.hpp>
#include <sdfrt/device.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sdfrt {

struct BuildStats {
  bool cache_hit = false;     // program came from the binary cache
  double build_ms = 0.0;      // wall time of the whole build_program call
  std::string cache_path;     // entry used or written; empty when the cache is off
  std::string cache_note;     // why the cache was bypassed/not written, if it was
  std::string build_log;      // compiler output (warnings) of a successful build
};

class Kernel {
 public:
  Kernel(KernelHandle handle, std::string name) : handle_(std::move(handle)), name_(std::move(name)) {}
  cl_kernel get() const noexcept { return handle_.get(); }
  const std::string& name() const noexcept { return name_; }

  // clSetKernelArg; throws DeviceError naming the kernel, index and CL code.
  void set_arg_raw(unsigned index, std::size_t size, const void* value);
  template <typename T>
  void set_arg(unsigned index, const T& value) { set_arg_raw(index, sizeof(T), &value); }

 private:
  KernelHandle handle_;
  std::string name_;
};

class Program {
 public:
  explicit Program(ProgramHandle handle) : handle_(std::move(handle)) {}
  cl_program get() const noexcept { return handle_.get(); }

  std::vector<std::string> kernel_names() const;
  // Throws DeviceError listing the kernels the program does have.
  Kernel kernel(const std::string& name) const;

 private:
  ProgramHandle handle_;
};

// Build `source` for `device`. Throws BuildError with the log and the
// offending source lines on a compile error. Uses the binary cache unless
// SDFC_KERNEL_CACHE=0; a broken cache entry silently falls back to source.
Program build_program(Device& device, const std::string& source, const std::string& options,
                      BuildStats* stats = nullptr);

// Where cached binaries live: $SDFC_CACHE_DIR, else $XDG_CACHE_HOME/sdfc/kernels,
// else $HOME/.cache/sdfc/kernels. nullopt when none of these is set.
std::optional<std::filesystem::path> kernel_cache_dir();

// False when SDFC_KERNEL_CACHE is 0/off/false/no.
bool kernel_cache_enabled();

}  // namespace sdfrt
