// The importer's entry: a parsed .fract file to sdfc YAML (see import.hpp).
#include "sdfc/fract/import.hpp"

#include <fmt/format.h>

#include "import_parts.hpp"

namespace sdfc::fract {

Imported import_scene(const File& file) {
  if (file.version > 0 && file.version < 2.0)
    fail(file.version_loc, "files of Mandelbulber 1.x cannot be imported", "open it in Mandelbulber 2 and save it again");
  Params main(file.main, false);
  ImportContext w;
  w.mirror_y = main.boolean("legacy_coordinate_system");
  Node geometry = import_geometry(file, main, w);
  geometry.modifiers.push_back({"material", "surface", "mat1_*"});
  std::string o = fmt::format("# Imported from a Mandelbulber {} settings file by `sdfc import`.\n"
                              "# Each value names the Mandelbulber key it came from.\n",
                              file.version > 0 ? num(file.version) : std::string("2"));
  o += import_view(file, main, import_camera_path(file, main, w), w);
  o += import_look(file, main, w);
  o += "scene:\n";
  write_node(o, geometry, 2, false);
  return {o, w.lines};
}

Imported import_file(const std::string& path) { return import_scene(read_file(path)); }

}  // namespace sdfc::fract
