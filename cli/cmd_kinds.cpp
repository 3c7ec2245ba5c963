// sdfc kinds: the node kinds from the kind table, as a list or as the node
// reference of docs/scene-format.md (scripts/kind-docs splices it in).
#include <iostream>

#include "commands.hpp"
#include "kind_reference.hpp"

namespace sdfc::cli {

Action add_kinds(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "kinds", "List the node kinds (name, category, bounded or not, example), or print their reference in Markdown");
  cmd->group("");  // for the docs' scripts; not listed in sdfc --help
  auto markdown = std::make_shared<bool>(false);
  cmd->add_flag("--markdown", *markdown, "Print the node reference of docs/scene-format.md instead of the list");
  return [markdown] {
    std::cout << (*markdown ? kind_reference_markdown() : kind_list());
    return kOk;
  };
}

}  // namespace sdfc::cli
