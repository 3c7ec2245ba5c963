// libFuzzer target for the front end: YAML text -> SourceValue -> IR ->
// passes -> IR printer, and expression strings -> parse/fold/evaluate/print.
// A SceneError is the expected outcome for bad input; anything else that
// escapes (another exception, a sanitizer report, a crash) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "sdfc/compile.hpp"
#include "sdfc/expr/expr.hpp"
#include "sdfc/ir/printer.hpp"
#include "sdfc/source/overrides.hpp"
#include "sdfc/source/yaml_loader.hpp"

namespace {

void fuzz_scene(const std::string& text) {
  sdfc::SourceValue doc = sdfc::load_yaml_text(text, "fuzz.yaml");
  sdfc::ir::Module m = sdfc::build_module(doc, "fuzz.yaml");
  (void)sdfc::ir::print(m);
}

void fuzz_expression(std::string_view text) {
  auto file = std::make_shared<const std::string>("fuzz.yaml");
  sdfc::SourceLoc at(file, 1, 1);
  auto e = sdfc::expr::parse(text, at, {"time", "x", "y", "z"});
  auto f = sdfc::expr::fold(e);
  (void)sdfc::expr::to_string(f);
  (void)sdfc::expr::evaluate(f, {{"time", 0.5}, {"x", 0.1}, {"y", -0.2}, {"z", 0.3}});
  (void)sdfc::expr::evaluate_interval(f, {{"time", {0, 1}}, {"x", {-1, 1}}, {"y", {-1, 1}}, {"z", {-1, 1}}});
  (void)sdfc::expr::to_string(sdfc::expr::derivative(f, "x"));
}

}  // namespace

// Inputs starting with "#expr\n" exercise the expression parser alone (the
// seed corpus holds some); everything else is a scene file.
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view in(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kExpr = "#expr\n";
  try {
    if (in.substr(0, kExpr.size()) == kExpr)
      fuzz_expression(in.substr(kExpr.size()));
    else
      fuzz_scene(std::string(in));
  } catch (const sdfc::SceneError&) {
    // Bad input reported properly: the expected path.
  }
  return 0;
}
