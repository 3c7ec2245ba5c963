// sdfc compare REFERENCE.png TEST.png: error metrics of a render against a
// reference render of the same view (AOVs are found beside each image).
#include <iostream>
#include <sdfrt/image_metrics.hpp>

#include "commands.hpp"

namespace sdfc::cli {

Action add_compare(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "compare", "Compare a render with a reference render of the same view: hit-mask disagreement, depth and "
                 "normal error (from <stem>.depth.pfm and <stem>.normal.pfm beside each PNG), PSNR and SSIM");
  auto ref = std::make_shared<std::string>(), test = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  cmd->add_option("reference", *ref, "The reference render (PNG)")->required();
  cmd->add_option("test", *test, "The render to measure (PNG)")->required();
  cmd->add_flag("--json", *json, "Print JSON instead of a table");
  return [ref, test, json] {
    sdfrt::ComparisonMetrics m =
        sdfrt::compare_renders(sdfrt::load_render_outputs(*ref), sdfrt::load_render_outputs(*test));
    std::cout << (*json ? sdfrt::format_json(m) : sdfrt::format_table(m));
    return kOk;
  };
}

}  // namespace sdfc::cli
