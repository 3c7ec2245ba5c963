#include "sdfc/compile.hpp"

#include <chrono>

#include "sdfc/frontend/lower_scene.hpp"
#include "sdfc/source/overrides.hpp"
#include "sdfc/source/yaml_loader.hpp"

namespace sdfc {

namespace {
double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

SourceValue load_scene_source(const std::string& path, const std::vector<std::string>& overrides) {
  SourceValue doc = load_yaml_file(path);
  apply_overrides(doc, overrides);
  return doc;
}

ir::Module build_module(const SourceValue& doc, const std::string& source_name, const passes::PassObserver& after,
                        CompileTimings* t) {
  auto t0 = std::chrono::steady_clock::now();
  ir::Module m = lower_scene(doc, source_name);
  if (t) t->lower_ms = ms_since(t0);
  if (after) after("lower", m);
  auto t1 = std::chrono::steady_clock::now();
  m = passes::run_pipeline(std::move(m), after, t ? &t->per_pass : nullptr);
  if (t) t->passes_ms = ms_since(t1);
  return m;
}

}  // namespace sdfc
