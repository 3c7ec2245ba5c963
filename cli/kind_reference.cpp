#include "kind_reference.hpp"

#include <fmt/format.h>

#include "sdfc/frontend/lower_scene.hpp"
#include "sdfc/kinds/registry.hpp"
#include "sdfc/passes/passes.hpp"
#include "sdfc/source/yaml_loader.hpp"

namespace sdfc::cli {
namespace {

std::string_view category_title(ir::Category c) {
  switch (c) {
    case ir::Category::Primitive: return "Primitives";
    case ir::Category::Fractal: return "Fractals";
    case ir::Category::Transform: return "Transforms and domain operations";
    case ir::Category::Combinator: return "Combinators";
    case ir::Category::Material: return "Materials";
  }
  return "Other nodes";
}

std::string_view category_word(ir::Category c) {
  switch (c) {
    case ir::Category::Primitive: return "primitive";
    case ir::Category::Fractal: return "fractal";
    case ir::Category::Transform: return "transform";
    case ir::Category::Combinator: return "combinator";
    case ir::Category::Material: return "material";
  }
  return "node";
}

// A table cell: `|` would end it.
std::string cell(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

// What the example shows: the props of its outermost node of this kind
// (none when the passes folded it away, as a transform into its child),
// and whether the whole example is bounded.
struct ExampleFacts {
  bool found = false;
  ir::Props props;
  bool bounded = false;
};
ExampleFacts example_facts(const kinds::Description& d) {
  std::string text = fmt::format("scene: {}\n", d.example);
  ir::Module m = passes::run_pipeline(lower_scene(load_yaml_text(text, "example.yaml"), "example.yaml"));
  ExampleFacts f;
  for (ir::NodeId id : m.graph->postorder(m.root))
    if (m.graph->node(id).kind == d.kind) f.found = true, f.props = m.graph->node(id).props;
  f.bounded = m.graph->node(m.root).props.bounds.finite();
  return f;
}

std::string distance_class(const kinds::Description& d) {
  ExampleFacts f = example_facts(d);
  if (!f.found) return "";
  std::string cls(ir::to_string(f.props.cls));
  if (f.props.lipschitz > 1) cls += fmt::format(" (L = {:.3g} in the example)", f.props.lipschitz);
  return cls;
}

void write_kind(std::string& out, const kinds::Description& d) {
  // Two kinds can share a key (a mandelbulb with julia: is its own kind):
  // the picture is named after the kind, as `sdfc check` prints it.
  const std::string_view name = ir::info(d.kind).name;
  if (name == d.yaml) out += fmt::format("#### `{}`\n", d.yaml);
  else out += fmt::format("#### `{}` (`{}`)\n", d.yaml, name);
  out += fmt::format("![{} {}](images/kinds/{}.png)\n\n", d.yaml, category_word(ir::info(d.kind).category), name);
  if (!d.written_as.empty()) out += fmt::format("Written as {}. ", d.written_as);
  out += std::string(d.summary);
  if (std::string cls = distance_class(d); !cls.empty()) out += fmt::format(" Distance: {}.", cls);
  out += "\n\n";
  if (!d.docs.empty()) {
    out += "| parameter | type | default | range | meaning |\n|---|---|---|---|---|\n";
    for (const kinds::ParamDoc& p : d.docs)
      out += fmt::format("| `{}` | {} | {} | {} | {} |\n", p.name, cell(p.type),
                         p.fallback.empty()      ? "required"
                         : p.fallback[0] == '(' ? std::string(p.fallback.substr(1, p.fallback.size() - 2))
                                                 : fmt::format("`{}`", p.fallback), cell(p.range),
                         cell(p.what));
    out += "\n";
  }
  out += fmt::format("```yaml\nscene: {}\n```\n\n", d.example);
}

// The kinds of the reference: every kind a scene writes as a node of its
// own, then every operation with an example (the ones the compiler makes
// itself, such as a bounding box test, have none).
std::vector<const kinds::Description*> documented() {
  std::vector<const kinds::Description*> out = kinds::all();
  for (const kinds::Description* d : kinds::operations())
    if (!d->example.empty()) out.push_back(d);
  return out;
}

}  // namespace

std::string kind_reference_markdown() {
  std::string out =
      "## Node reference\n"
      "Every node kind with its parameters, their defaults and the values they\n"
      "accept, its distance class and an example with its picture (the example\n"
      "alone, framed by `camera.fit`). A parameter left out takes its default.\n"
      "A primitive's numbers and vec3s may be expressions of `time` (see\n"
      "[Animation](#animation)) unless their row says they are fixed.\n"
      "Transforms, domain operations and combinators work on the nodes they\n"
      "are written on or hold; their pictures show their examples.\n\n";
  const auto all = documented();
  for (int c = 0; c <= int(ir::Category::Material); ++c) {
    bool heading = false;
    for (const kinds::Description* d : all) {
      if (int(ir::info(d->kind).category) != c) continue;
      if (!heading) out += fmt::format("### {}\n", category_title(ir::Category(c)));
      heading = true;
      write_kind(out, *d);
    }
  }
  while (out.size() > 1 && out[out.size() - 1] == '\n' && out[out.size() - 2] == '\n') out.pop_back();
  return out;
}

std::string kind_list() {
  std::string out;
  for (const kinds::Description* d : documented())
    out += fmt::format("{}\t{}\t{}\t{}\n", ir::info(d->kind).name, category_word(ir::info(d->kind).category),
                       example_facts(*d).bounded ? "bounded" : "unbounded", d->example);
  return out;
}

}  // namespace sdfc::cli
