// libFuzzer target through emission: YAML text -> IR -> passes -> the OpenCL
// kernel at the SIMD width the input's first byte picks (the precision is
// the scene's own render.precision). A SceneError is the expected
// outcome for bad input. Every kernel emitted must hold only printable ASCII
// and no text of the input outside kernel_text()'s escaping: the file name
// carries a preprocessor line that must never start a line of the kernel.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "kernel_text.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/source/yaml_loader.hpp"

namespace {

// A file name full of what must never reach kernel source raw.
const std::string kFileName = "fz\n#error injected\r*/?\?/\\.yaml";

void check_kernel(const std::string& src) {
  if (!sdfc::codegen::kernel_source_is_plain(src)) std::abort();
  // Escaped, the line stays inside its comment; raw, it would start a line.
  if (src.find("\n#error injected") != std::string::npos) std::abort();
}

}  // namespace

// The first byte picks the SIMD width and precision; the rest is the scene.
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const int kWidths[] = {1, 4, 8, 16};
  const int width = kWidths[data[0] & 3];
  std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    sdfc::SourceValue doc = sdfc::load_yaml_text(text, kFileName);
    sdfc::ir::Module m = sdfc::build_module(doc, kFileName);
    sdfc::codegen::EmitOptions opt;
    opt.simd_width = width;
    opt.aovs = (data[0] & 4) != 0;
    check_kernel(sdfc::codegen::emit_opencl(m, opt).source);
  } catch (const sdfc::SceneError&) {
    // Bad input reported properly: the expected path.
  }
  return 0;
}
