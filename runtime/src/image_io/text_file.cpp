#include <sdfrt/text_file.hpp>

#include "image_io/atomic_file.hpp"

namespace sdfrt {

WriteReport write_text_file(const std::string& path, std::string_view text) {
  AtomicFile file(path);
  file.write(text.data(), text.size());
  file.commit();
  return WriteReport{path, 0, file.bytes_written()};
}

}  // namespace sdfrt
