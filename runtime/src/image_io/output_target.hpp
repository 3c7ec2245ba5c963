#pragma once
// Internal: what an output path really names before AtomicFile writes it.
// A symlink is followed to the file it points at (as cp does), a device or
// FIFO is written in place (so `-o /dev/null` stays a device), anything else
// that is not a regular file is refused, and so is a file the process has
// read as an input (render X.yaml -o X.yaml).
#include <string>

namespace sdfrt::detail {

struct OutputTarget {
  std::string path;       // the file to write: the symlink's target, or the path itself
  bool in_place = false;  // a device or FIFO: opened and written directly, never renamed
};

// Throws IoError for a directory, a socket, a protected input or a symlink
// loop.
OutputTarget resolve_output(const std::string& path);

// Records a file as an input that no output may replace (by device and inode).
void protect_input_file(const std::string& path);

// Removes "<name>.tmp-<pid>-XXXXXX" files beside `path` left by sdfc
// processes that no longer run (a SIGKILL between creating and renaming).
void remove_stale_temp_files(const std::string& path);

// "<path>.tmp-<pid>-XXXXXX", the mkstemp pattern of our own temp files.
std::string temp_pattern(const std::string& path);

}  // namespace sdfrt::detail
