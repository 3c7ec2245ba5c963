#pragma once
// Libraries opened the first time a command needs them, not at start-up.
// FFmpeg (video files) and OpenVDB (meshes) pull in over a hundred shared
// libraries whose loading cost every sdfc process ~130 ms, though most
// commands never write a video or a mesh.
#include <string>

namespace sdfrt {

// dlopen()s `file` (a soname such as "libavcodec.so.59", or a path) for the
// rest of the process. Throws IoError naming `purpose` (the output that
// needs it, which then cannot be written) and the loader's reason.
void* open_library(const std::string& file, const std::string& purpose);

// The address of `name` in a library from open_library; throws as it does.
void* library_symbol(void* library, const char* name, const std::string& purpose);

// Where one of sdfc's own modules (built beside it, e.g. "libsdfc_openvdb.so")
// is: <directory of the running program>/../lib/sdfc/<file> when that exists
// (an installed sdfc), else the build tree's lib/sdfc/<file>.
std::string sdfc_module_path(const std::string& file);

}  // namespace sdfrt
