// sdfc compare REFERENCE.png TEST.png: error metrics of a render against a
// reference render of the same view (AOVs are found beside each image).
#include <iostream>
#include <sdfrt/image_metrics.hpp>

#include "cli_support.hpp"
#include "commands.hpp"

namespace sdfc::cli {

Action add_compare(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "compare", "Compare a render with a reference render of the same view: hit-mask disagreement, depth and "
                 "normal error (from <stem>.depth.pfm, <stem>.normal.pfm and <stem>.hit.pfm beside each PNG), differing pixels, PSNR and SSIM");
  auto ref = std::make_shared<std::string>(), test = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  cmd->add_option("reference", *ref, "The reference render (PNG)")->required();
  cmd->add_option("test", *test, "The render to measure (PNG)")->required();
  auto threshold = std::make_shared<double>(sdfrt::kDefaultPixelThreshold * 255.0);
  cmd->add_flag("--json", *json, "Print JSON instead of a table");
  cmd->add_option("--pixel-threshold", *threshold,
                  "A pixel differs when some channel differs by more than this many levels of 255 (default 4)")
      ->check(CLI::Range(0.0, 255.0))
      ->check(finite_number());
  return [ref, test, json, threshold] {
    sdfrt::ComparisonMetrics m = sdfrt::compare_renders(sdfrt::load_render_outputs(*ref),
                                                        sdfrt::load_render_outputs(*test), *threshold / 255.0);
    std::cout << (*json ? sdfrt::format_json(m) : sdfrt::format_table(m));
    return kOk;
  };
}

}  // namespace sdfc::cli
