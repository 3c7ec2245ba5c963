#include "suggest.hpp"

#include <string_view>
#include <vector>

#include "sdfc/support/diagnostics.hpp"

namespace sdfc::cli {

namespace {

// The long option names of a command ("--width"), its help flag included.
std::vector<std::string> long_options(const CLI::App& cmd) {
  std::vector<std::string> names;
  for (const CLI::Option* o : cmd.get_options())
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
  return names;
}

std::string closest(std::string_view word, const std::vector<std::string>& names) {
  std::vector<std::string_view> views(names.begin(), names.end());
  return did_you_mean(word, views);
}

}  // namespace

std::string suggest_for_arguments(const CLI::App& app, int argc, char** argv) {
  if (argc < 2) return "";
  std::string first = argv[1];
  if (first.empty() || first[0] == '-') {  // an option before the subcommand: the top level's
    std::string name = first.substr(0, first.find('='));
    return first.rfind("--", 0) == 0 ? closest(name, long_options(app)) : "";
  }
  std::vector<std::string> commands;
  const CLI::App* sub = nullptr;
  for (const CLI::App* s : app.get_subcommands([](const CLI::App*) { return true; })) {
    commands.push_back(s->get_name());
    if (s->get_name() == first) sub = s;
  }
  if (!sub) {
    std::string hint = closest(first, commands);
    return "'" + first + "' is not a command" + (hint.empty() ? "" : "; " + hint);
  }
  std::vector<std::string> options = long_options(*sub);
  for (int i = 2; i < argc; ++i) {
    std::string word = argv[i];
    if (word.rfind("--", 0) != 0 || word == "--") continue;
    std::string name = word.substr(0, word.find('='));
    bool known = false;
    for (const std::string& o : options) known = known || o == name;
    if (!known) return closest(name, options);
  }
  return "";
}

}  // namespace sdfc::cli
