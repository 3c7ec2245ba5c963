#include <sdfrt/output_file.hpp>

#include "image_io/atomic_file.hpp"

namespace sdfrt {

void write_output_file(const std::string& path, std::string_view bytes) {
  AtomicFile out(path);
  out.write(bytes.data(), bytes.size());
  out.commit();
}

void protect_input(const std::string& path) { AtomicFile::protect_input(path); }

}  // namespace sdfrt
