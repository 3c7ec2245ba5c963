#include "sdfc/compile.hpp"

#include <fmt/format.h>

#include <chrono>
#include <iostream>
#include <vector>

#include "sdfc/fract/import.hpp"
#include "sdfc/frontend/lower_scene.hpp"
#include "sdfc/scene_caps.hpp"
#include "sdfc/source/overrides.hpp"
#include "sdfc/source/unlock.hpp"
#include "sdfc/source/yaml_loader.hpp"

namespace sdfc {

namespace {
// The kernel holds one statement per node on every path from the root (a
// shared subtree is written out at each use), and PoCL's build time grows
// faster than that count: 1 000 translated spheres (2 002 statements) build in
// 16 s, 10 000 in 365 s (2 busy cores). Refuse before emitting.
constexpr double kMaxKernelNodes = 4096;
// Each light writes its shading (and shadow loop) into the kernel: 3 000
// point lights with soft shadows took 117 s to build. One counts as this many nodes.
constexpr double kNodesPerLight = 16;

void check_kernel_size(const ir::Module& m) {
  if (m.root == ir::kNoNode) return;
  const ir::Graph& g = *m.graph;
  std::vector<double> paths(g.size(), 0);  // double: alias-built trees can exceed any integer
  for (ir::NodeId id : g.postorder(m.root)) {
    double n = 1;
    for (ir::NodeId c : g.node(id).children) n += paths[c];
    paths[id] = n;
  }
  paths[m.root] += kNodesPerLight * double(m.plan.lights.size());
  if (paths[m.root] > kMaxKernelNodes)
    fail(g.node(m.root).loc,
         fmt::format("the scene makes a kernel of {:.0f} node evaluations, more than the limit of {:.0f}: the OpenCL "
                     "build time grows faster than the kernel (10 000 spheres take minutes to build)",
                     paths[m.root], kMaxKernelNodes),
         "use fewer, larger shapes or fewer lights (each light counts as 16 nodes), or split the scene");
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

SourceValue load_scene_source(const std::string& path, const std::vector<std::string>& overrides) {
  // A Mandelbulber settings file is imported first (sdfc import shows the
  // scene it makes, with the line numbers its errors then refer to).
  SourceValue doc;
  if (fract::is_fract_path(path)) {
    fract::Imported im = fract::import_file(path);
    for (const std::string& w : im.warnings) std::cerr << printable(path) << ": warning: " << printable(w) << "\n";
    doc = load_yaml_text(im.yaml, path + " (imported)");
  } else {
    doc = load_yaml_file(path);
  }
  apply_overrides(doc, overrides);
  return doc;
}

ir::Module build_module(const SourceValue& doc, const std::string& source_name, const passes::PassObserver& after,
                        CompileTimings* t) {
  auto t0 = std::chrono::steady_clock::now();
  ir::Module m = lower_scene(doc, source_name);
  if (t) t->lower_ms = ms_since(t0);
  const UnlockSlots slots = marked_slots(doc);
  check_unlocked(doc, slots);
  if (after) after("lower", m);
  auto t1 = std::chrono::steady_clock::now();
  m = passes::run_pipeline(std::move(m), after, t ? &t->per_pass : nullptr);
  if (t) t->passes_ms = ms_since(t1);
  m.unlocked = static_cast<int>(slots.size());
  check_kernel_size(m);
  check_scene_cost(m);
  return m;
}

}  // namespace sdfc
