#pragma once
// The one gate for text that comes from outside the compiler (scene names,
// file names, --set values, expression text) on its way into kernel source.
// On PoCL the kernel is compiled to native code inside the sdfc process, so
// a newline, a carriage return or a line-continuing backslash in a comment
// would let a shared scene file run code. Everything such text writes into
// the kernel goes through kernel_text().
#include <string>
#include <string_view>

namespace sdfc::codegen {

// `text` as printable ASCII that is inert inside a `//` or `/* */` comment:
// letters, digits, space and plain punctuation pass; every other byte
// (control characters, NUL, non-ASCII, `\`, `?`, `*`, `%`) becomes %XX. At
// most `max_bytes` of the input are kept, then "...".
std::string kernel_text(std::string_view text, size_t max_bytes = 96);

// True when a whole generated kernel holds only printable ASCII, tabs and
// newlines (no CR, NUL or other control byte). emit_opencl checks its output
// with it, so a text that bypassed kernel_text() fails the compile rather
// than reaching the OpenCL compiler.
bool kernel_source_is_plain(std::string_view source);

}  // namespace sdfc::codegen
