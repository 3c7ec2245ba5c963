#pragma once
// "Did you mean" for a mistyped subcommand or option, from the parser's own
// lists of what exists.
#include <CLI/CLI.hpp>

#include <string>

namespace sdfc::cli {

// A hint for the first word of argv that names no subcommand of `app` (or no
// option of the subcommand it follows), e.g. "did you mean 'render'?"; ""
// when nothing is mistyped or nothing is close.
std::string suggest_for_arguments(const CLI::App& app, int argc, char** argv);

}  // namespace sdfc::cli
