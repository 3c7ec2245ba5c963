// sdfc compile SCENE --emit ast|ir|cl [--dump-after PASS|all] [--unlock PATH[=LO:HI]] [-o FILE]
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <iostream>

#include <sdfrt/device.hpp>
#include <sdfrt/program.hpp>

#include "cli_support.hpp"
#include "commands.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/ir/printer.hpp"
#include "sdfc/source/unlock.hpp"

namespace sdfc::cli {

namespace {

struct CompileArgs {
  SceneArgs scene;
  std::string emit = "cl";
  std::vector<std::string> dump_after;
  std::vector<std::string> unlock;
  std::string output = "-";
  int simd_width = 0;
  int packet_rows = 0;
  bool stats = false;
  bool build = false;
  std::string device;
};

double ms(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

int run_compile(const CompileArgs& a) {
  std::vector<std::string_view> names{"lower"};
  for (const auto& p : passes::pipeline()) names.push_back(p.name);
  for (const auto& d : a.dump_after) {
    bool known = d == "all";
    for (auto n : names) known = known || n == d;
    if (!known) {
      std::string all;
      for (auto n : names) all += " " + std::string(n);
      std::string hint = did_you_mean(d, names);
      std::cerr << fmt::format("sdfc compile: unknown pass '{}' for --dump-after{}; passes:{} (or all)\n", d,
                               hint.empty() ? "" : " (" + hint + ")", all);
      return kUsageError;
    }
  }
  auto t0 = std::chrono::steady_clock::now();
  SourceValue doc = load_scene_source(a.scene.path, a.scene.sets);
  std::vector<UnlockRequest> unlocks;
  for (const auto& u : a.unlock) unlocks.push_back(parse_unlock(u));
  const UnlockSlots slots = mark_unlocked(doc, unlocks);
  double parse_ms = ms(t0);
  std::string out;
  if (a.emit == "ast") {
    write_text_output(a.output, print_source(doc));
    return kOk;
  }
  auto wants = [&](std::string_view pass) {
    for (const auto& d : a.dump_after)
      if (d == "all" || d == pass) return true;
    return false;
  };
  CompileTimings tm;
  ir::Module m = build_module(
      doc, a.scene.path,
      [&](std::string_view pass, const ir::Module& mod) {
        if (wants(pass)) out += fmt::format("// ---- IR after {} ({} nodes) ----\n{}", pass, ir::count_nodes(mod), ir::print(mod));
      },
      &tm);
  auto t1 = std::chrono::steady_clock::now();
  codegen::EmittedKernel k;
  if (a.emit == "cl" || a.stats) k = codegen::emit_opencl(m, {.simd_width = a.simd_width > 0 ? a.simd_width : default_simd_width(true), .packet_rows = a.packet_rows});
  double emit_ms = ms(t1);
  if (a.emit == "ir" && a.dump_after.empty()) out += ir::print(m);
  if (a.emit == "cl") out += k.source;
  for (const auto& s : slots)  // where each unlocked value sits, and the range its bounds assume
    std::cerr << fmt::format("unlocked[{}] = {} ({}), range {} to {}\n", s->index, s->path, s->value, s->lo, s->hi);
  write_text_output(a.output, out);
  if (a.stats) {
    std::string t = fmt::format("{:<26}{:>10.3f} ms\n", "parse", parse_ms);
    t += fmt::format("{:<26}{:>10.3f} ms\n", "lower", tm.lower_ms);
    for (const auto& p : tm.per_pass) t += fmt::format("  {:<24}{:>10.3f} ms\n", p.pass, p.ms);
    t += fmt::format("{:<26}{:>10.3f} ms\n", "emit", emit_ms);
    t += fmt::format("{:<26}{:>10.3f} ms\n", "front end + passes + emit", parse_ms + tm.lower_ms + tm.passes_ms + emit_ms);
    if (a.build) {
      sdfrt::Device device = sdfrt::open_device(a.device.empty() ? std::nullopt : std::optional<std::string>(a.device));
      sdfrt::BuildStats bs;
      sdfrt::build_program(device, k.source, "", &bs);
      t += fmt::format("{:<26}{:>10.3f} ms{}\n", "opencl build", bs.build_ms, bs.cache_hit ? " (from the binary cache)" : "");
    }
    t += fmt::format("kernel: {} bytes, {} lines, SIMD width {}, {} IR nodes, {} stdlib functions\n", k.source.size(),
                     std::count(k.source.begin(), k.source.end(), '\n'), k.simd_width, ir::count_nodes(m),
                     k.stdlib_functions.size());
    std::cerr << t;
  }
  return kOk;
}

}  // namespace

Action add_compile(CLI::App& app) {
  auto* cmd = app.add_subcommand("compile", "Show any stage: the AST, the IR (after any pass) or the OpenCL kernel");
  auto a = std::make_shared<CompileArgs>();
  a->scene.add_to(*cmd);
  cmd->add_option("--emit", a->emit, "What to print: ast, ir or cl (the exact kernel 'render' builds)")
      ->check(CLI::IsMember({"ast", "ir", "cl"}));
  cmd->add_option("--dump-after", a->dump_after, "Print the IR after this pass (repeatable; 'all' for every pass)");
  cmd->add_option("--unlock", a->unlock,
                  "Read this value from the frame block instead of baking it (as the viewer's panel does); "
                  "PATH walks keys and list indices (lights[0].intensity), =LO:HI the range it may take (repeatable)");
  cmd->add_option("-o,--output", a->output, "Write to FILE instead of stdout");
  cmd->add_option("--simd-width", a->simd_width, "Pixels per work-item: 1 (GPU form) or 2/4/8/16/32/64 (CPU packets); "
                                                 "default: the width render picks for a CPU device")
      ->check(CLI::IsMember({1, 2, 4, 8, 16, 32, 64}));
  cmd->add_option("--packet-rows", a->packet_rows, "Pixel rows per packet, dividing --simd-width (default: 4 at widths 16 and 32, 8 at 64)")
      ->check(CLI::IsMember({1, 2, 4, 8, 16, 32, 64}));
  cmd->add_flag("--stats", a->stats, "Print the time of each stage and the kernel's size on stderr");
  cmd->add_flag("--build", a->build, "With --stats: also build the kernel on the device and time it "
                                     "(SDFC_KERNEL_CACHE=0 for a cold build)");
  cmd->add_option("--device", a->device, "Device for --build (see 'sdfc devices')");
  return [a] { return run_compile(*a); };
}

}  // namespace sdfc::cli
