// The geometry of an imported scene: which formula slots are in use, each
// one's node through the formula table, and how they combine — one formula,
// Mandelbulber's boolean mode (each slot its own object, combined left to
// right with AND / OR / SUB, placed by formula_position_N and
// formula_scale_N) or a hybrid (one orbit through several formulas).
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "formula_table.hpp"
#include "formula_writers.hpp"
#include "import_parts.hpp"

namespace sdfc::fract {
namespace {

struct Slot {
  int n;    // 1 ... 9
  int id;
  SourceLoc loc;
};

// Mandelbulber's formula slots in use: formula_N != 0 and fractal_enable_N
// (which only boolean mode reads); an absent formula_1 is its default, 2.
std::vector<Slot> used_slots(const Params& main, bool boolean_mode) {
  std::vector<Slot> out;
  for (int n = 1; n <= kFractalSlots; ++n) {
    std::string key = fmt::format("formula_{}", n);
    int id = main.integer(key);
    if (id == 0) continue;
    if (boolean_mode && !main.boolean(fmt::format("fractal_enable_{}", n))) continue;
    out.push_back({n, id, main.loc(key)});
  }
  return out;
}

// Shape-changing settings sdfc has no node for yet: an error, never a
// silently different shape.
void refuse_unmapped_shape_keys(const Params& main) {
  auto refuse = [&](const std::string& key, const std::string& what) {
    fail(main.loc(key), fmt::format("{} is not supported yet ({} = {})", what, key, printable(main.section().entries.at(key).value, 80)));
  };
  auto vec_set = [&](const char* key) { return main.given(key) && main.vec3(key) != Vec3{0, 0, 0}; };
  if (vec_set("fractal_rotation") && main.boolean("boolean_operators"))
    refuse("fractal_rotation", "rotating the fractal in boolean mode");
  if (vec_set("fractal_rotation") && main.boolean("limits_enabled"))
    refuse("fractal_rotation", "rotating the fractal with limits_enabled");
  if (vec_set("repeat")) refuse("repeat", "repeating the fractal");
  if (main.given("interior_mode") && main.boolean("interior_mode")) refuse("interior_mode", "the interior mode");
  if (main.given("iteration_threshold_mode") && main.boolean("iteration_threshold_mode"))
    refuse("iteration_threshold_mode", "the iteration threshold mode");
  // Mandelbulber's folds of every iteration, before any formula.
  for (const char* key : {"box_folding", "spherical_folding"})
    if (main.given(key) && main.boolean(key)) refuse(key, "the general box and spherical folding");
  for (const auto& [key, e] : main.section().entries)
    if (key.rfind("primitive_", 0) == 0 && key.size() > 8 && key.compare(key.size() - 8, 8, "_enabled") == 0 &&
        (e.value == "true" || e.value == "1"))
      fail(e.loc, fmt::format("Mandelbulber primitives are not supported yet ({})", key));
}

// Calls use(formula, input) with the slot's FormulaInput.
template <class Use>
auto with_input(const Slot& s, const File& file, const Params& main, ImportContext& w, bool hybrid, Use use) {
  const Formula* f = find_formula(s.id);
  std::string name = f ? f->name : formula_name(s.id);
  if (!f || !f->write || (hybrid && !f->chain))
    fail(s.loc, formula_label(s.id) + " is not supported yet" + (hybrid ? " (in a hybrid)" : ""),
         "sdfc imports the Mandelbulb (2), Mandelbulb - Power 2 (3), the Mandelbox (8), the Menger sponge (7), the "
         "Kaleidoscopic IFS (10), Xenodreambuie (11), box_fold_bulb_pow2 (16), Menger - Mod 1 (61), eiffie_msltoe (70), "
         "Menger - Cross KIFS (98), pseudoKleinian2 (103), Menger - Smooth (113), Abox - Mod 11 (119), Amazing Surf - "
         "Mod 2 (132) and the quaternion in julia mode (5); in a hybrid 2, 3, 7, 8, 10, 16, 119 and 132");
  if (w.mirror_y && !f->mirror_symmetric)
    fail(main.loc("legacy_coordinate_system"), formula_label(s.id) + " in the legacy coordinate system is not supported yet");
  Params fractal(file.fractal[size_t(s.n - 1)], true);
  bool use_default = main.boolean("use_default_bailout");
  FormulaInput in{fractal,
                  main,
                  s.n,
                  s.id,
                  name,
                  s.loc,
                  main.boolean("julia_mode"),
                  w.world(main.vec3("julia_c")),
                  main.integer("N"),
                  use_default ? f->default_bailout : main.number("bailout"),
                  &w.lines,
                  w.mirror_y,
                  file.version};
  return use(*f, in);
}

Node formula_node(const Slot& s, const File& file, const Params& main, ImportContext& w) {
  return with_input(s, file, main, w, false, [](const Formula& f, const FormulaInput& in) { return f.write(in); });
}

Node hybrid_node(const std::vector<Slot>& slots, const File& file, const Params& main, ImportContext& w) {
  for (const Slot& s : slots)  // name the first formula that has no mapping, before the sequence
    with_input(s, file, main, w, true, [](const Formula&, const FormulaInput&) { return 0; });
  Vec3 julia{};
  Node n = hybrid_chain(main, slots[0].loc, [&](int slot) {
    auto s = std::find_if(slots.begin(), slots.end(), [&](const Slot& x) { return x.n == slot; });
    if (s == slots.end()) fail(slots[0].loc, "this hybrid sequence has iterations without a formula (formula_start/stop_iteration_N)");
    return with_input(*s, file, main, w, true, [&](const Formula& f, const FormulaInput& in) {
      if (in.julia) julia = julia_constant(in);
      return HybridPart{f.chain(in), in.bailout};
    });
  });
  if (main.boolean("julia_mode")) n.fields.push_back({"julia", vec(julia), "julia_mode true, julia_c x fractal_constant_factor"});
  return n;
}

// limits_enabled keeps the fractal inside the box limit_min ... limit_max:
// the intersection with that box.
Node with_limits(Node n, const Params& main, const ImportContext& w) {
  if (!main.boolean("limits_enabled")) return n;
  Vec3 lo = main.vec3("limit_min"), hi = main.vec3("limit_max");
  Vec3 size{}, centre{};
  for (size_t k = 0; k < 3; ++k) {
    if (!(hi[k] > lo[k])) fail(main.loc("limit_max"), "limit_max must be above limit_min on every axis");
    size[k] = hi[k] - lo[k];
    centre[k] = 0.5 * (hi[k] + lo[k]);
  }
  Node box{"box", "limits_enabled", {{"size", vec(size), "limit_max - limit_min"}}, {}, {}};
  if (w.world(centre) != Vec3{0, 0, 0}) box.modifiers.push_back({"translate", vec(w.world(centre)), "the limits' centre"});
  return Node{"intersection", "limits_enabled: the fractal inside limit_min ... limit_max", {}, {}, {n, box}};
}

// fractal_rotation: Mandelbulber iterates M·p, M = Rz(r.z)·Ry(r.y)·Rx(r.x)
// (CRotationMatrix::SetRotation2), so the shape turns by M⁻¹ = Mᵀ: that
// as one axis and angle (in the scene's coordinates, mirrored when legacy).
Node with_rotation(Node n, const Params& main, const ImportContext& w) {
  Vec3 r = main.vec3("fractal_rotation");
  if (r == Vec3{0, 0, 0}) return n;
  using M3 = std::array<std::array<double, 3>, 3>;
  auto mul = [](const M3& a, const M3& b) {
    M3 c{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
    return c;
  };
  auto turn = [](int axis, double degrees) {  // right-handed, as CRotationMatrix::RotateX/Y/Z
    double a = degrees * M_PI / 180, cs = std::cos(a), sn = std::sin(a);
    int u = (axis + 1) % 3, v = (axis + 2) % 3;
    M3 m{};
    m[axis][axis] = 1;
    m[u][u] = cs, m[u][v] = -sn, m[v][u] = sn, m[v][v] = cs;
    return m;
  };
  M3 m = mul(mul(turn(2, r[2]), turn(1, r[1])), turn(0, r[0])), t{};
  double sy = w.mirror_y ? -1 : 1;  // S·Mᵀ·S with S = diag(1, -1, 1)
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t[i][j] = m[j][i] * (i == 1 ? sy : 1) * (j == 1 ? sy : 1);
  double angle = std::acos(std::clamp((t[0][0] + t[1][1] + t[2][2] - 1) / 2, -1.0, 1.0));
  Vec3 axis{t[2][1] - t[1][2], t[0][2] - t[2][0], t[1][0] - t[0][1]};
  if (std::sin(angle) < 1e-9) {  // a half turn: the axis from the diagonal (t = 2aaᵀ − I)
    size_t k = t[0][0] >= t[1][1] && t[0][0] >= t[2][2] ? 0 : t[1][1] >= t[2][2] ? 1 : 2;
    for (size_t i = 0; i < 3; ++i) axis[i] = (t[i][k] + (i == k)) / 2;
  }
  double len = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  if (!(len > 0) || angle < 1e-12) return n;
  auto tidy = [](double v) { return std::round(v * 1e12) / 1e12; };  // 120, not 119.99999999999999
  for (double& a : axis) a = tidy(a / len);
  n.modifiers.push_back({"rotate", fmt::format("{{axis: {}, degrees: {}}}", vec(axis), num(tidy(angle * 180 / M_PI))),
                         "fractal_rotation: Mandelbulber turns the point by it, so the shape turns back"});
  return n;
}

}  // namespace

Node import_geometry(const File& file, const Params& main, ImportContext& w) {
  refuse_unmapped_shape_keys(main);
  bool boolean_mode = main.boolean("boolean_operators");
  bool hybrid = main.boolean("hybrid_fractal_enable");
  std::vector<Slot> slots = used_slots(main, boolean_mode);
  if (slots.empty()) fail(main.section().loc, "no formula is in use (every formula_N is 0 or disabled)");
  if (!boolean_mode && !hybrid) {  // Mandelbulber then iterates formula_1 alone
    if (slots[0].n != 1) fail(main.loc("formula_1"), "formula_1 is 0 (none) and neither hybrid nor boolean mode is on");
    slots.resize(1);
  }
  if (!boolean_mode && hybrid && slots.size() > 1) return with_limits(with_rotation(hybrid_node(slots, file, main, w), main, w), main, w);
  if (!boolean_mode) return with_limits(with_rotation(formula_node(slots[0], file, main, w), main, w), main, w);

  Node root;
  for (const Slot& s : slots) {
    Node n = formula_node(s, file, main, w);
    std::string rot = fmt::format("formula_rotation_{}", s.n);
    if (main.vec3(rot) != Vec3{0, 0, 0}) fail(main.loc(rot), "formula_rotation_N in boolean mode is not supported yet");
    Vec3 pos = w.world(main.vec3(fmt::format("formula_position_{}", s.n)));
    double scale = main.number(fmt::format("formula_scale_{}", s.n));
    if (!(scale > 0)) fail(main.loc(fmt::format("formula_scale_{}", s.n)), "formula_scale_N must be positive");
    if (scale != 1) n.modifiers.push_back({"scale", num(scale), fmt::format("formula_scale_{}", s.n)});
    if (pos != Vec3{0, 0, 0}) n.modifiers.push_back({"translate", vec(pos), fmt::format("formula_position_{}", s.n)});
    if (root.kind.empty()) {
      root = n;
      continue;
    }
    int op = main.integer(fmt::format("boolean_operator_{}", s.n));
    const char* kind = op == 0 ? "intersection" : op == 1 ? "union" : op == 2 ? "difference" : nullptr;
    if (!kind) fail(main.loc(fmt::format("boolean_operator_{}", s.n)), "expected a boolean operator 0 (AND), 1 (OR) or 2 (SUB)");
    Node combined{kind, fmt::format("boolean_operator_{} {}", s.n, op), {}, {}, {root, n}};
    root = combined;
  }
  return with_limits(root, main, w);
}

}  // namespace sdfc::fract
