#pragma once
// One function per subcommand; main.cpp wires them into CLI11.
#include <CLI/CLI.hpp>

namespace sdfc::cli {

// Exit codes, documented in `sdfc --help` and docs/cli.md.
enum Exit : int { kOk = 0, kSceneError = 1, kUsageError = 2, kDeviceError = 3, kOutputError = 4 };

// Each registers its subcommand and returns the action to run when chosen.
using Action = std::function<int()>;
Action add_check(CLI::App& app);
Action add_compile(CLI::App& app);
Action add_render(CLI::App& app);
Action add_devices(CLI::App& app);
Action add_view(CLI::App& app);
Action add_audit(CLI::App& app);
Action add_compare(CLI::App& app);
Action add_merge(CLI::App& app);  // cmd_merge.cpp: a still's region files into its image
Action add_farm(CLI::App& app);   // cmd_farm.cpp: Slurm job scripts
Action add_mesh(CLI::App& app);
Action add_kinds(CLI::App& app);  // cmd_kinds.cpp: the node kinds (hidden; for the docs)
Action add_import(CLI::App& app);  // cmd_import.cpp: Mandelbulber .fract to YAML

}  // namespace sdfc::cli
