#include "sdfc/ir/printer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace sdfc::ir {

namespace {

// Shortest text that reads back as the same double (%.17g trimmed).
std::string num(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  for (int prec = 6; prec <= 17; ++prec) {
    std::string s = fmt::format("{:.{}g}", v, prec);
    if (std::stod(s) == v) return s;
  }
  return fmt::format("{:.17g}", v);
}

std::string vec(const Vec3d& v) { return "[" + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + "]"; }

std::string box(const Box3& b) {
  if (!b.finite()) return "unbounded";
  return "[" + num(b.lo[0]) + " " + num(b.lo[1]) + " " + num(b.lo[2]) + " .. " + num(b.hi[0]) + " " + num(b.hi[1]) +
         " " + num(b.hi[2]) + "]";
}

}  // namespace

size_t count_nodes(const Module& m) { return m.graph->postorder(m.root).size(); }

std::string print(const Module& m, const PrintOptions& opt) {
  std::string out;
  std::unordered_map<NodeId, size_t> number;
  const Graph& g = *m.graph;
  for (NodeId id : g.postorder(m.root)) {
    size_t n = number.size();
    number[id] = n;
    const Node& node = g.node(id);
    const KindInfo& ki = info(node.kind);
    std::string line = fmt::format("%{} = {}", n, ki.name);
    // An object set prints its header (offset, counts), not its data.
    const size_t shown = std::min(node.params.size(), ki.params.size());
    for (size_t i = 0; i < shown; ++i) {
      if (const auto& e = node.animation(i)) line += fmt::format(" {}=\"{}\"", ki.params[i], expr::to_string(e));
      else line += fmt::format(" {}={}", ki.params[i], num(node.params[i]));
    }
    for (NodeId c : node.children) line += fmt::format(" %{}", number.at(c));
    if (opt.props && node.props.known)
      line += fmt::format("    ; {} L={} cost={} bounds={}", to_string(node.props.cls), num(node.props.lipschitz),
                          num(node.props.cost), box(node.props.bounds));
    out += line + "\n";
  }
  out += m.root == kNoNode ? "root = none\n" : fmt::format("root = %{}\n", number.at(m.root));
  if (opt.plan) out += print_plan(m.plan);
  return out;
}

std::string print_plan(const RenderPlan& p) {
  std::string out;
  const auto& c = p.camera;
  out += fmt::format("camera position={} target={} up={} fov={}\n", vec(c.position), vec(c.target), vec(c.up),
                     num(c.fov_degrees));
  const auto& r = p.march;
  out += fmt::format("render {}x{} precision={} max_steps={} hit_epsilon={} max_distance={} step_factor={} gamma={} normals={}\n",
                     r.width, r.height, r.precision == Precision::Float ? "float" : "double", r.max_steps,
                     num(r.hit_epsilon), num(r.max_distance), num(r.step_factor), num(r.gamma),
                     r.normals == NormalMethod::Tetrahedral ? "tetrahedral" : r.normals == NormalMethod::Central ? "central" : "dual");
  if (r.normal_step != 0.5 || r.refine != MarchSettings::Refine::None)
    out += fmt::format("render normal_step={} refine={}\n", num(r.normal_step),
                       r.refine == MarchSettings::Refine::Bisection ? "bisection" : "none");
  out += fmt::format("background top={} bottom={}\n", vec(p.background.top), vec(p.background.bottom));
  for (size_t i = 0; i < p.lights.size(); ++i) {
    const Light& l = p.lights[i];
    switch (l.kind) {
      case LightKind::Directional:
        out += fmt::format("light {} directional direction={}", i, vec(l.direction));
        break;
      case LightKind::Point: out += fmt::format("light {} point position={}", i, vec(l.position)); break;
      case LightKind::Ambient: out += fmt::format("light {} ambient", i); break;
    }
    out += fmt::format(" color={} intensity={}\n", vec(l.color),
                       l.intensity_anim ? "\"" + expr::to_string(l.intensity_anim) + "\"" : num(l.intensity));
  }
  for (size_t i = 0; i < p.materials.size(); ++i) {
    const MaterialDef& md = p.materials[i];
    out += fmt::format("material {} '{}' color={} specular={} shininess={}\n", i, md.name, vec(md.color),
                       num(md.specular), num(md.shininess));
  }
  return out;
}

}  // namespace sdfc::ir
