// sdfc import FILE.fract [-o scene.yaml]: a Mandelbulber settings file as an
// sdfc scene, each value commented with the Mandelbulber key it came from.
#include <fmt/format.h>

#include <iostream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "sdfc/fract/import.hpp"
#include "sdfrt/output_file.hpp"

namespace sdfc::cli {
namespace {

struct ImportArgs {
  std::string path;
  std::string output = "-";
};

int run_import(const ImportArgs& a) {
  fract::Imported im = fract::import_file(a.path);
  for (const std::string& w : im.warnings) std::cerr << printable(a.path) << ": warning: " << printable(w) << "\n";
  write_text_output(a.output, im.yaml);
  return kOk;
}

}  // namespace

Action add_import(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "import", "Turn a Mandelbulber settings file (.fract) into an sdfc scene (render, view and check also take "
                ".fract files directly)");
  auto a = std::make_shared<ImportArgs>();
  cmd->add_option("file", a->path, "The .fract file")->required()->each([](const std::string& p) { sdfrt::protect_input(p); });
  cmd->add_option("-o,--output", a->output, "Write the scene to FILE (through a temporary file and a rename) "
                                            "instead of stdout");
  return [a] { return run_import(*a); };
}

}  // namespace sdfc::cli
