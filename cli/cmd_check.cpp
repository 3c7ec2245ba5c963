// sdfc check SCENE: parse, validate and summarise on one screen.
#include <fmt/format.h>

#include <string>
#include <vector>
#include "sdfc/ir/de_info.hpp"

#include <iostream>

#include "cli_support.hpp"
#include "sdfc/scene_caps.hpp"
#include "commands.hpp"
#include "sdfc/codegen/camera_view.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/formula/chain.hpp"
#include "sdfc/ir/printer.hpp"
#include "sdfc/kinds/params.hpp"
#include "sdfc/kinds/registry.hpp"

namespace sdfc::cli {

namespace {

std::string box_text(const ir::Box3& b) {
  if (!b.finite()) return "unbounded";
  return fmt::format("[{:.3g}, {:.3g}, {:.3g}] .. [{:.3g}, {:.3g}, {:.3g}]", b.lo[0], b.lo[1], b.lo[2], b.hi[0],
                     b.hi[1], b.hi[2]);
}

// camera.fit: the box it frames and where that puts the camera.
void print_fit(const ir::RenderPlan& plan) {
  const ir::Camera& c = plan.camera;
  if (!c.fit) return;
  if (!c.has_fit_box) {
    fmt::print("  camera fit: the scene has no bounded part to frame; the camera stays where it is\n");
    return;
  }
  const ir::Camera f = codegen::fitted(c, plan.march.width, plan.march.height);
  fmt::print("  camera fit: frames {} at {}x{}: position [{:.4g}, {:.4g}, {:.4g}], target [{:.4g}, {:.4g}, {:.4g}]\n",
             box_text({c.fit_lo, c.fit_hi}), plan.march.width, plan.march.height, f.position[0], f.position[1],
             f.position[2], f.target[0], f.target[1], f.target[2]);
}

int run_check(const SceneArgs& args) {
  SourceValue doc = load_scene_source(args.path, args.sets);
  size_t lowered_nodes = 0;
  ir::Module m = build_module(doc, args.path, [&](std::string_view pass, const ir::Module& mod) {
    if (pass == "lower") lowered_nodes = ir::count_nodes(mod);
  });
  warn_if_camera_inside(m, args.path);
  const ir::Graph& g = *m.graph;
  const ir::Props& root = g.node(m.root).props;
  fmt::print("{}: ok\n", args.path);
  fmt::print("geometry: {} IR nodes ({} as written), class {}, L = {}, cost ~{:.0f}\n", ir::count_nodes(m),
             lowered_nodes, ir::to_string(root.cls), root.lipschitz, root.cost);
  fmt::print("  bounds {}\n", box_text(root.bounds));
  print_fit(m.plan);
  fmt::print("  work per sample ~{:.3g} (limit {:.3g}, see docs/security.md)\n", estimated_cost_per_sample(m),
             scene_caps().max_cost_per_sample);
  // Every node with its class and Lipschitz constant, and where the kernel
  // divides by L (the correction is local to that subtree).
  int corrected = 0, steep = 0;
  for (ir::NodeId id : g.postorder(m.root)) {
    const ir::Node& n = g.node(id);
    if (n.kind == ir::Kind::Material) continue;
    std::string at = n.loc.line > 0 ? fmt::format("line {}", n.loc.line) : "";
    std::string note;
    if (n.props.lipschitz > 1 + 1e-9) {
      ++steep;
      corrected += n.props.corrected;
      note = n.props.corrected ? "  corrected: distance / L here" : "  NOT corrected (render.lipschitz_correction: false)";
    }
    std::string de = ir::de_summary(n);  // fractals: the estimator and what it promises
    if (!de.empty()) note += "  " + de;
    if (n.kind == ir::Kind::StepFactor) note += fmt::format("  factor {:.3g}", kinds::step_factor(n));
    fmt::print("  {:<20} {:<9} L = {:<6.4g} {}{}\n", ir::info(n.kind).name, ir::to_string(n.props.cls), n.props.lipschitz,
               at, note);
    if (const kinds::Description* d = kinds::find(n.kind); d && d->explain) fmt::print("{}", d->explain(n));
    if (auto k = formula::builtin_chain_at(n.loc)) {
      const formula::Chain& c = formula::chain(*k);
      fmt::print("preset {} renders with the built-in {}'s own code (the same fractal; a setting only a chain has,\n"
                 "such as de, makes it the chain). The chain it stands for:\n{}",
                 c.preset, ir::info(n.kind).name, formula::describe(c));
    }
  }
  if (steep > 0)
    fmt::print("  Lipschitz correction: {} of {} nodes with L > 1 divided locally\n", corrected, steep);
  const auto& p = m.plan;
  std::string lights;
  for (const auto& l : p.lights)
    lights += std::string(lights.empty() ? "" : ", ") +
              (l.kind == ir::LightKind::Directional ? "directional" : l.kind == ir::LightKind::Point ? "point" : "ambient");
  fmt::print("lights: {} ({})\n", p.lights.size(), lights);
  std::string mats;
  for (const auto& md : p.materials) mats += std::string(mats.empty() ? "" : ", ") + md.name;
  fmt::print("materials: {} ({})\n", p.materials.size(), mats);
  std::vector<std::string> fx;
  const auto& e = p.effects;
  if (e.ambient_occlusion.enabled)
    fx.push_back(e.ambient_occlusion.method == ir::AmbientOcclusion::Method::StepCount ? "ambient occlusion (step count)"
                                                                                       : "ambient occlusion (normal samples)");
  int shadowed = 0;
  for (const auto& l : p.lights) shadowed += l.shadows != ir::Light::Shadows::None;
  if (shadowed) fx.push_back(fmt::format("shadows ({} light(s))", shadowed));
  if (e.glow.enabled) fx.push_back("glow");
  if (e.fog.enabled) fx.push_back(e.fog.height_falloff > 0 ? "height fog" : "fog");
  if (e.reflections.depth > 0) fx.push_back(fmt::format("reflections (depth {})", e.reflections.depth));
  if (p.camera.aperture > 0) fx.push_back("depth of field");
  if (p.march.samples > 1) fx.push_back(fmt::format("{} samples per pixel", p.march.samples));
  if (p.march.dither) fx.push_back("dither");
  if (p.march.tone_mapping != ir::MarchSettings::ToneMapping::Clamp) fx.push_back("tone mapping");
  if (!p.camera.path.empty()) fx.push_back(fmt::format("camera path ({} keys)", p.camera.path.size()));
  std::string list;
  for (const auto& f : fx) list += (list.empty() ? "" : ", ") + f;
  fmt::print("effects: {}\n", list.empty() ? "none" : list);
  const auto& r = p.march;
  fmt::print("render: {}x{}, {} precision, up to {} steps, hit epsilon {} px, step factor {}\n", r.width, r.height,
             r.precision == ir::Precision::Float ? "float" : "double", r.max_steps, r.hit_epsilon, r.step_factor);
  return kOk;
}

}  // namespace

Action add_check(CLI::App& app) {
  auto* cmd = app.add_subcommand("check", "Parse and validate a scene; print a summary or the errors");
  auto args = std::make_shared<SceneArgs>();
  args->add_to(*cmd);
  return [args] { return run_check(*args); };
}

}  // namespace sdfc::cli
