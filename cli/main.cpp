// sdfc: compile signed-distance scenes to one OpenCL kernel and render them.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <csignal>
#include <iostream>
#include <new>
#include <sdfrt/errors.hpp>

#include "commands.hpp"
#include "suggest.hpp"
#include "sdfc/support/diagnostics.hpp"

int main(int argc, char** argv) {
  using namespace sdfc::cli;
  // Past `ulimit -f`, a write should fail with EFBIG (reported, temp file
  // removed) rather than the process being killed half-way.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"sdfc: compiles signed-distance and fractal scenes (YAML) to one OpenCL kernel and renders them",
               "sdfc"};
  app.footer(
      "Exit codes: 0 success, 1 scene error, 2 usage error, 3 device/OpenCL error, 4 output not written,\n"
      "130 stopped by Ctrl-C.\n"
      "Environment: SDFC_DEVICE picks the device (see 'sdfc devices'); SDFC_CACHE_DIR and\n"
      "SDFC_KERNEL_CACHE=0 control the kernel binary cache.");
  app.set_version_flag("--version", std::string("sdfc ") + SDFC_VERSION);
  app.require_subcommand(1);
  std::vector<std::pair<CLI::App*, Action>> commands;
  auto reg = [&](Action (*add)(CLI::App&)) {
    size_t before = app.get_subcommands({}).size();
    Action a = add(app);
    commands.push_back({app.get_subcommands({}).at(before), std::move(a)});
  };
  reg(add_check);
  reg(add_compile);
  reg(add_render);
  reg(add_devices);
  reg(add_view);
  reg(add_audit);
  reg(add_compare);
  reg(add_merge);
  reg(add_farm);
  reg(add_mesh);
  reg(add_kinds);
  reg(add_import);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --version
    app.exit(e);
    if (std::string hint = suggest_for_arguments(app, argc, argv); !hint.empty()) std::cerr << "sdfc: " << hint << "\n";
    return kUsageError;
  }
  try {
    for (auto& [cmd, action] : commands)
      if (cmd->parsed()) return action();
  } catch (const sdfc::SceneError& e) {
    std::cerr << e.what() << "\n";
    return kSceneError;
  } catch (const sdfrt::DeviceError& e) {
    std::cerr << "sdfc: device error: " << sdfc::printable(e.what(), 100000) << "\n";
    return kDeviceError;
  } catch (const sdfrt::IoError& e) {
    std::cerr << "sdfc: " << sdfc::printable(e.what()) << "\n";
    return kOutputError;
  } catch (const sdfrt::Cancelled&) {
    std::cerr << "sdfc: cancelled\n";
    return 130;
  } catch (const std::bad_alloc&) {
    std::cerr << "sdfc: out of memory\n";
    return kDeviceError;
  } catch (const std::invalid_argument& e) {
    std::cerr << "sdfc: " << sdfc::printable(e.what()) << "\n";
    return kUsageError;
  } catch (const std::exception& e) {
    std::cerr << "sdfc: internal error: " << sdfc::printable(e.what()) << "\n";
    return 70;
  }
  return kUsageError;
}
