// sdfc audit SCENE: where does the distance field break sphere tracing?
#include <iostream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "sdfc/analysis/audit.hpp"
#include "sdfc/compile.hpp"

namespace sdfc::cli {

namespace {

struct AuditArgs {
  SceneArgs scene;
  analysis::AuditOptions opt;
  bool json = false;
  bool strict = false;
};

int run_audit(const AuditArgs& a) {
  ir::Module m = build_module(load_scene_source(a.scene.path, a.scene.sets), a.scene.path);
  analysis::AuditReport r = analysis::audit(m, a.opt);
  std::cout << (a.json ? analysis::format_json(r) : analysis::format_table(r));
  if (r.any_warning())
    std::cerr << "sdfc audit: some nodes break what their distance class promises (see WARNING rows); "
                 "a smaller step_factor on them or render.step_factor removes the overshoot\n";
  return a.strict && r.any_warning() ? kSceneError : kOk;
}

}  // namespace

Action add_audit(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "audit", "Sample the distance field per node: measured Lipschitz bound (slope test), overshoot rate against "
               "a conservative march, NaN/Inf counts and a recommended step factor");
  auto a = std::make_shared<AuditArgs>();
  a->scene.add_to(*cmd);
  cmd->add_option("--lines", a->opt.lines, "Lines per node for the slope test (default 96)")->check(CLI::Range(1, 100000));
  cmd->add_option("--rays", a->opt.rays, "Rays per node for the overshoot test (default 128)")->check(CLI::Range(1, 100000));
  cmd->add_option("--seed", a->opt.seed, "Random seed (default 1)");
  cmd->add_flag("--json", a->json, "Print JSON instead of a table");
  cmd->add_flag("--strict", a->strict, "Exit 1 when any node gets a warning");
  return [a] { return run_audit(*a); };
}

}  // namespace sdfc::cli
