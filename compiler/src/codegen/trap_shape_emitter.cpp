#include "trap_shape_emitter.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <vector>

#include "kernel_text.hpp"
#include "sdfc/codegen/stdlib_manifest.hpp"

namespace sdfc::codegen::detail {

namespace {

using Shape = ir::TrapShape::Kind;

// Registrations in `used` start with a character no stdlib name has.
constexpr char kMeasure[] = "#measure ";
constexpr char kShaped[] = "#shaped ";

// The default measure as the stdlib writes it, and the point it measures.
struct DefaultMeasure {
  const char* text;
  const char* point;
};
constexpr DefaultMeasure kDefaults[] = {{"fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z)))", "z"},
                                        {"fmin(fabs(a), fmin(fabs(v.x), fabs(v.y)))", "v3(a, v.x, v.y)"}};

std::string measure_name(size_t material) { return fmt::format("orbit_trap_m{}", material); }

const char* shape_name(Shape s) {
  switch (s) {
    case Shape::Point: return "point";
    case Shape::Plane: return "plane";
    case Shape::Line: return "line";
    case Shape::Sphere: return "sphere";
    case Shape::Cross: break;
  }
  return "cross";
}

std::string measure_function(const ir::MaterialDef& md, size_t i, const Literals& lit) {
  const ir::TrapShape& t = md.trap_shape;
  const std::string c = lit.vec3(t.point), d = lit.vec3(t.direction);
  CodeWriter w;
  w.line(fmt::format("// material {} '{}': the orbit trap's shape, {}", i, kernel_text(md.name), shape_name(t.kind)));
  w.line(fmt::format("inline real {}(vec3 z)", measure_name(i)));
  w.open("{");
  w.line(fmt::format("vec3 q = v3_sub(z, {});", c));
  switch (t.kind) {
    case Shape::Point: w.line("return v3_length(q);  // distance to the point"); break;
    case Shape::Plane: w.line(fmt::format("return fabs(v3_dot(q, {}));  // distance to the plane", d)); break;
    case Shape::Line:
      w.line(fmt::format("real along = v3_dot(q, {});", d));
      w.line("return sqrt(fmax(v3_dot(q, q) - along * along, K(0.0f)));  // distance to the line");
      break;
    case Shape::Sphere:
      w.line(fmt::format("return fabs(v3_length(q) - {});  // distance to the sphere's shell", lit.real(t.radius)));
      break;
    case Shape::Cross: throw std::logic_error("the default trap shape has no measure function");
  }
  w.close("}");
  return w.take();
}

// The stdlib function's text with another name and material i's measure.
std::string shaped_copy(const std::string& fn, size_t i) {
  const StdlibFunction* f = StdlibManifest::instance().find(fn);
  if (!f) throw std::logic_error("stdlib has no function '" + fn + "'");
  std::string out = fmt::format("// {} with material {}'s trap shape\n", fn, i);
  size_t renamed = 0, measured = 0;
  size_t at = 0;
  while (at < f->text.size()) {
    size_t end = f->text.find('\n', at);
    std::string line = f->text.substr(at, end == std::string::npos ? std::string::npos : end - at);
    at = end == std::string::npos ? f->text.size() : end + 1;
    if (line.rfind("//!", 0) == 0) continue;  // the manifest header belongs to the original
    const std::string call = " " + fn + "(";
    if (size_t k = line.find(call); k != std::string::npos) {
      line.replace(k, call.size(), fmt::format(" {}_m{}(", fn, i));
      ++renamed;
    }
    for (const DefaultMeasure& d : kDefaults)
      if (size_t k = line.find(d.text); k != std::string::npos) {
        line.replace(k, std::string(d.text).size(), fmt::format("{}({})", measure_name(i), d.point));
        ++measured;
      }
    out += line + "\n";
  }
  if (renamed != 1 || measured != 1)
    throw std::logic_error(fmt::format("stdlib function '{}' does not have one default trap measure to replace", fn));
  return out;
}

}  // namespace

bool shaped_trap(const ir::RenderPlan& plan, size_t material) {
  return material < plan.materials.size() && plan.materials[material].trap_shape.kind != Shape::Cross;
}

std::string trap_measure_call(size_t material, const std::string& z, std::set<std::string>& used) {
  used.insert(kMeasure + std::to_string(material));
  return fmt::format("{}({})", measure_name(material), z);
}

std::string shaped_trap_fn(const std::string& fn, size_t material, std::set<std::string>& used) {
  used.insert(kMeasure + std::to_string(material));
  used.insert(fmt::format("{}{} {}", kShaped, material, fn));
  return fmt::format("{}_m{}", fn, material);
}

std::string emit_trap_shapes(const ir::RenderPlan& plan, const Literals& lit, std::set<std::string>& used) {
  std::string measures, copies;
  std::vector<std::string> deps;
  for (auto it = used.begin(); it != used.end();) {
    const std::string& s = *it;
    if (s.rfind(kMeasure, 0) == 0) {
      size_t i = std::stoul(s.substr(sizeof kMeasure - 1));
      measures += "\n" + measure_function(plan.materials.at(i), i, lit);
    } else if (s.rfind(kShaped, 0) == 0) {
      std::string rest = s.substr(sizeof kShaped - 1);
      size_t space = rest.find(' ');
      std::string fn = rest.substr(space + 1);
      copies += "\n" + shaped_copy(fn, std::stoul(rest.substr(0, space)));
      for (const std::string& d : StdlibManifest::instance().find(fn)->deps) deps.push_back(d);
    } else {
      ++it;
      continue;
    }
    it = used.erase(it);
  }
  used.insert(deps.begin(), deps.end());  // the copies call what their originals call
  return measures.empty() ? "" : "\n// ---- orbit-trap shapes ----" + measures + copies;
}

}  // namespace sdfc::codegen::detail
