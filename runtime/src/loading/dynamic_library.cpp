#include "loading/dynamic_library.hpp"

#include <dlfcn.h>
#include <fmt/format.h>
#include <sdfrt/errors.hpp>

#include <filesystem>
#include <system_error>

namespace sdfrt {

void* open_library(const std::string& file, const std::string& purpose) {
  void* lib = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!lib) {
    const char* why = dlerror();
    throw IoError(fmt::format("{} needs {}, which cannot be loaded: {}", purpose, file, why ? why : "?"), file, 0);
  }
  return lib;
}

void* library_symbol(void* library, const char* name, const std::string& purpose) {
  dlerror();
  void* sym = dlsym(library, name);
  if (!sym) {
    const char* why = dlerror();
    throw IoError(fmt::format("{}: no {} in its library: {}", purpose, name, why ? why : "?"), name, 0);
  }
  return sym;
}

std::string sdfc_module_path(const std::string& file) {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto installed = exe.parent_path().parent_path() / "lib" / "sdfc" / file;
    if (std::filesystem::exists(installed, ec)) return installed.string();
  }
  return (std::filesystem::path(SDFC_BUILD_MODULE_DIR) / file).string();
}

}  // namespace sdfrt
