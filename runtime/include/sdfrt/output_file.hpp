#pragma once
// Output files outside the image writers (kernels, text): written whole
// through a temp file and a rename like every image, with the same rules
// for devices, FIFOs, symlinks and inputs (see docs/security.md).
#include <string>
#include <string_view>

namespace sdfrt {

// Writes `bytes` to `path` (a device or FIFO in place, a symlink's target);
// throws IoError.
void write_output_file(const std::string& path, std::string_view bytes);

// Marks a file the command reads (the scene, a kernel, a compared image):
// writing any output onto it is refused with an IoError.
void protect_input(const std::string& path);

}  // namespace sdfrt
