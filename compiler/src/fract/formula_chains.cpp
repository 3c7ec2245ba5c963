// Mandelbulber's folding formulas as formula-chain steps: the Mandelbox with
// its main rotation and constant factor, the Menger sponge at any scale and
// the Kaleidoscopic IFS (kaleidoscopic_ifs.cl) with its direction vectors,
// rotations and edges. Shared: Mandelbulber's rotation matrices as rotate
// steps, and c added times fractal_constant_factor.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <utility>

#include "formula_writers.hpp"

namespace sdfc::fract {
namespace {

std::string vstep(const char* name, const char* key, const Vec3& v) { return fmt::format("{{{}: {{{}: {}}}}}", name, key, vec(v)); }

// A plane fold (reflect where z·n > d) in the scene's coordinates.
std::string plane_fold(const FormulaInput& in, const Vec3& n, double d) {
  Vec3 w = in.mirror_y ? Vec3{n[0], -n[1], n[2]} : n;
  return fmt::format("{{plane_fold: {{normal: {}, offset: {}}}}}", vec(w), num(d));
}

Vec3 world(const FormulaInput& in, const Vec3& v) { return in.mirror_y ? Vec3{v[0], -v[1], v[2]} : v; }

}  // namespace

// Turns about x, y, z by the given angles, in the order z sees them.
// Mirrored in y, the turns about x and z reverse.
std::string turn_steps(const std::array<std::pair<int, double>, 3>& turns, bool mirror) {
  std::string s;
  const char* axes[3] = {"[1, 0, 0]", "[0, 1, 0]", "[0, 0, 1]"};
  for (const auto& [axis, degrees] : turns) {
    double a = degrees * (mirror && axis != 1 ? -1 : 1);
    if (a != 0) s += fmt::format("{{rotate: {{axis: {}, angle: {}}}}}, ", axes[axis], num(a));
  }
  return s;
}

// CRotationMatrix::SetRotation2 (Mandelbox main rotation, transf_rotation):
// Rz(r.z)·Ry(r.y)·Rx(r.x), so z turns about x first.
std::string rotation2_steps(const Vec3& r, bool mirror) { return turn_steps({{{0, r[0]}, {1, r[1]}, {2, r[2]}}}, mirror); }

// CRotationMatrix::SetRotation3 (the IFS rotations): Rz(r.x)·Ry(r.y)·Rx(r.z).
std::string rotation3_steps(const Vec3& r, bool mirror) { return turn_steps({{{0, r[2]}, {1, r[1]}, {2, r[0]}}}, mirror); }

// compute_fractal.cl adds c·fractal_constant_factor (julia_c times it in
// julia mode, which the formula's julia constant carries); `adds` says
// whether this formula adds c at all.
std::string add_c_step(const FormulaInput& in, bool adds) {
  if (!adds) return "";
  Vec3 k = in.main.vec3("fractal_constant_factor");
  if (in.julia || k == Vec3{1, 1, 1}) return "add_c";
  return fmt::format("{{expr: {{x: \"x + {}*cx\", y: \"y + {}*cy\", z: \"z + {}*cz\"}}}}", num(k[0]), num(k[1]), num(k[2]));
}

// dont_add_c_constant_N: Mandelbulber's "add c" switch for the formulas that
// add none by default (Menger, IFS), its "don't add c" for the others.
bool adds_c(const FormulaInput& in, bool by_default) {
  bool flag = in.main.boolean(fmt::format("dont_add_c_constant_{}", in.slot));
  return by_default ? !flag : flag;
}

ChainPart mandelbox_chain(const FormulaInput& in) {
  const Params& f = in.fractal;
  double scale = f.number("mandelbox_scale"), limit = f.number("mandelbox_folding_limit");
  double value = f.number("mandelbox_folding_value");
  double min_r = f.number("mandelbox_folding_min_radius"), fixed_r = f.number("mandelbox_folding_fixed_radius");
  if (f.boolean("mandelbox_rotations_enabled")) unsupported_setting(in, "mandelbox_rotations_enabled", "true");
  if (f.vec3("mandelbox_offset") != Vec3{0, 0, 0}) unsupported_setting(in, "mandelbox_offset", vec(f.vec3("mandelbox_offset")));
  if (std::fabs(value - 2 * limit) > 1e-12 * std::max(1.0, std::fabs(limit)))
    unsupported_setting(in, "mandelbox_folding_value", num(value) + " (only 2 x mandelbox_folding_limit maps)");
  if (!(std::fabs(scale) > 1e-3 && std::fabs(scale) <= 8)) unsupported_setting(in, "mandelbox_scale", num(scale));
  if (!(min_r > 0 && min_r < fixed_r && fixed_r <= 100))
    unsupported_setting(in, "mandelbox_folding_min_radius", num(min_r) + " with fixed radius " + num(fixed_r));
  if (!(limit > 0)) unsupported_setting(in, "mandelbox_folding_limit", num(limit));
  std::string s = fmt::format("{{box_fold: {{limit: {}}}}}, {{sphere_fold: {{min_radius: {}, fixed_radius: {}}}}}, ", num(limit),
                              num(min_r), num(fixed_r));
  if (f.boolean("mandelbox_main_rotation_enabled")) s += rotation2_steps(f.vec3("mandelbox_rotation_main"), in.mirror_y);
  s += fmt::format("{{scale: {}}}", num(scale));
  std::string c = add_c_step(in, adds_c(in, true));
  return {c.empty() ? s : s + ", " + c, "mandelbox.cl: box fold, sphere fold, main rotation, scale, + c", 200};
}

// menger_sponge.cl: sort |z|, z·s − (2, 2, 0), z.z −= 2 above 1: menger_fold
// with scale s about the corner 2 / (s − 1).
ChainPart menger_chain(const FormulaInput& in) {
  double s = in.fractal.number("transf_scale_3");
  if (!(s > 1.001 && s <= 10)) unsupported_setting(in, "transf_scale_3", num(s));
  double o = 2 / (s - 1);
  std::string steps = fmt::format("{{menger_fold: {{scale: {}, offset: {}}}}}", num(s), vec(Vec3{o, o, o}));
  // Its abs forgets the mirror (legacy_coordinate_system): flip y back, or
  // the c added after it (here or by the next formula) is on the wrong side.
  if (in.mirror_y) steps += ", {scale_xyz: {scale: [1, -1, 1]}}";
  std::string c = add_c_step(in, adds_c(in, false));
  return {c.empty() ? steps : steps + ", " + c, "menger_sponge.cl with transf_scale_3", 40};
}

ChainPart ifs_chain(const FormulaInput& in) {
  const Params& f = in.fractal;
  std::string s;
  // Mirrored in y, Mandelbulber's y = |y| is y = -|y| (a fold of y > 0):
  // an abs there would leave the mirrored vectors below on the wrong side.
  bool abs_y = f.boolean("IFS_abs_y"), fold_y = abs_y && in.mirror_y;
  Vec3 axes{double(f.boolean("IFS_abs_x")), double(abs_y && !fold_y), double(f.boolean("IFS_abs_z"))};
  if (axes != Vec3{0, 0, 0}) s += vstep("abs", "axes", axes) + ", ";
  if (fold_y) s += "{plane_fold: {normal: [0, 1, 0], offset: 0}}, ";
  // Each enabled vector: its rotation, then the reflection where z·d < distance.
  for (int i = 0; i < 9; ++i) {
    if (!f.boolean(fmt::format("IFS_enabled_{}", i))) continue;
    std::string ik = fmt::format("IFS_intensity_{}", i);
    if (f.number(ik) != 1) unsupported_setting(in, ik, num(f.number(ik)) + " (only 1, a reflection, maps)");
    Vec3 d = f.vec3(fmt::format("IFS_direction_{}", i));
    double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(l > 1e-12)) unsupported_setting(in, fmt::format("IFS_direction_{}", i), "0 0 0");
    s += rotation3_steps(f.vec3(fmt::format("IFS_rotations_{}", i)), in.mirror_y);
    s += plane_fold(in, {-d[0] / l, -d[1] / l, -d[2] / l}, -f.number(fmt::format("IFS_distance_{}", i))) + ", ";
  }
  Vec3 offset = f.vec3("IFS_offset");
  // Files of 2.06 and before have no IFS_rotation_enabled: Mandelbulber
  // turns it on in fractals 1 ... 4 when it loads them.
  bool rotate = f.boolean("IFS_rotation_enabled") || (in.version > 0 && in.version <= 2.06 && in.slot <= 4);
  if (rotate && f.vec3("IFS_rotation") != Vec3{0, 0, 0}) {
    bool shift = offset != Vec3{0, 0, 0};
    if (shift) s += vstep("translate", "offset", world(in, {-offset[0], -offset[1], -offset[2]})) + ", ";
    s += rotation3_steps(f.vec3("IFS_rotation"), in.mirror_y);
    if (shift) s += vstep("translate", "offset", world(in, offset)) + ", ";
  }
  Vec3 edge = f.vec3("IFS_edge");  // z = e − |e − z|: the side beyond e reflected back
  for (int k = 0; k < 3; ++k)
    if (edge[size_t(k)] > 0) s += plane_fold(in, {double(k == 0), double(k == 1), double(k == 2)}, edge[size_t(k)]) + ", ";
  double scale = f.number("IFS_scale");
  if (!(scale > 1.001 && scale <= 10)) unsupported_setting(in, "IFS_scale", num(scale));
  std::string c = add_c_step(in, adds_c(in, false));
  if (f.boolean("IFS_menger_sponge_mode")) {
    // z·s − (ox, oy, 0)·(s − 1), then z.z −= H = oz·(s − 1) where z.z > H/2.
    // The next iteration's abs makes that shift the reflection 2·(H/2) − z.z,
    // a plane fold; without abs_z (or with c added between) it is not.
    double h = offset[2] * (scale - 1);
    if (h != 0 && (!f.boolean("IFS_abs_z") || !c.empty()))
      unsupported_setting(in, "IFS_menger_sponge_mode", "true (maps with IFS_abs_z and no c added)");
    s += fmt::format("{{scale: {{scale: {}, offset: {}}}}}", num(scale), vec(world(in, {offset[0], offset[1], 0})));
    if (h != 0) s += ", " + plane_fold(in, {0, 0, 1}, 0.5 * h);
  } else {
    s += fmt::format("{{scale: {{scale: {}, offset: {}}}}}", num(scale), vec(world(in, offset)));
  }
  return {c.empty() ? s : s + ", " + c, "kaleidoscopic_ifs.cl: abs, vectors, rotation, edge, scale about the offset", 60};
}

// One formula alone as a `formula:` node.
Node chain_formula(const FormulaInput& in, const ChainPart& part) {
  if (!(in.bailout > 1e-3 && in.bailout <= 1e6)) unsupported_setting(in, "bailout", num(in.bailout));
  Node n{"formula", fmt::format("formula_{} {} ({})", in.slot, in.id, in.name), {}, {}, {}};
  n.fields = {iterations_field(in, part.cap),
              {"bailout", num(in.bailout), "bailout"},
              {"iterate", "[" + part.steps + "]", part.how}};
  if (in.julia) n.fields.push_back({"julia", vec(julia_constant(in)), "julia_mode true, julia_c x fractal_constant_factor"});
  return n;
}

Vec3 julia_constant(const FormulaInput& in) {
  Vec3 k = in.main.vec3("fractal_constant_factor"), c{};
  for (size_t i = 0; i < 3; ++i) {
    c[i] = in.julia_c[i] * k[i];
    if (std::fabs(c[i]) > 10) unsupported_setting(in, "julia_c", vec(in.julia_c));
  }
  return c;
}

Node ifs(const FormulaInput& in) { return chain_formula(in, ifs_chain(in)); }

}  // namespace sdfc::fract
