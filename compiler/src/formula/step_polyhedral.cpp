// polyhedral_fold: Mandelbulber's generalized box fold. The box fold
// reflects z into a cube; this one folds into a chosen polyhedron whose
// faces lie at distance 1 from the origin: beyond a face z is
// reflected in it, beyond an edge it is turned half-way round the edge
// line, beyond a corner it is reflected through the corner. Each is an
// isometry (|dz| kept, the scalar derivative unchanged); the Jacobian's
// columns take the linear part: I - 2nn^T, 2uu^T - I or -I. (Mandelbulber's
// `solid` moves the faces but not the point its edge search starts from, so
// away from 1 the edge and corner folds stop being isometries: it is left
// at 1.)
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "../codegen/code_writer.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {
namespace {

// The polyhedra's face normals, in Mandelbulber's order (its ties pick the
// first face in the list).
std::vector<V3> normals(int type) {
  const double s = 1 / std::sqrt(3.0);
  const std::vector<V3> tet = {{s, s, -s}, {s, -s, s}, {-s, s, s}, {-s, -s, -s}};
  const std::vector<V3> cube = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<V3> oct = tet;
  oct.insert(oct.end(), {{s, s, s}, {-s, -s, s}, {-s, s, -s}, {s, -s, -s}});
  const double g = (1 + std::sqrt(5.0)) / 2, b = 1 / std::sqrt(g * g + 1);
  const double f = std::sqrt(g * g + 1 / (g * g)), c = g / f, d = 1 / g / f;
  std::vector<V3> out;
  auto prism = [&](int n) {
    out = {{0, 0, 1}, {0, 0, -1}};
    for (int k = 0; k < n; ++k) out.push_back({std::cos(2 * M_PI / n * k), std::sin(2 * M_PI / n * k), 0});
  };
  switch (type) {
    case 0: out = tet; break;
    case 1: out = cube; break;
    case 2: out = oct; break;
    case 3:
      out = {{0, b, g * b}, {0, b, -g * b}, {0, -b, g * b}, {0, -b, -g * b}, {b, g * b, 0},  {b, -g * b, 0},
             {-b, g * b, 0}, {-b, -g * b, 0}, {g * b, 0, b}, {-g * b, 0, b}, {g * b, 0, -b}, {-g * b, 0, -b}};
      break;
    case 4:
      out = oct;
      out.insert(out.end(), cube.begin(), cube.end());
      break;
    case 5:
      out = oct;
      out.insert(out.end(), {{0, d, c}, {0, d, -c}, {0, -d, c}, {0, -d, -c}, {c, 0, d}, {c, 0, -d}, {-c, 0, d}, {-c, 0, -d},
                             {d, c, 0}, {d, -c, 0}, {-d, c, 0}, {-d, -c, 0}});
      break;
    case 6: prism(6); break;
    default: prism(5); break;
  }
  return out;
}

double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 mad(const V3& y, const V3& l, double a) { return {y[0] + a * l[0], y[1] + a * l[1], y[2] + a * l[2]}; }

// The nearest face plane (dot(x, n) = solid) that the segment y + a l,
// 0 < a < 1, crosses, skipping faces `skip1` and `skip2`: its index or -1,
// and the parameter where it crosses in *a.
int cut(const std::vector<V3>& nv, double solid, const V3& y, const V3& l, int skip1, int skip2, double* a) {
  int side = -1;
  *a = 1;
  for (int i = 0; i < int(nv.size()); ++i) {
    if (i == skip1 || i == skip2) continue;
    double b = solid - dot(y, nv[size_t(i)]), c = dot(l, nv[size_t(i)]);
    if (c > 0 && *a * c > b) side = i, *a = b / c;
  }
  return side;
}

void fold_eval(const Step& st, RefState& s) {
  const std::vector<V3> nv = normals(int(st.a[0]));
  const double solid = 1;
  const V3 z = s.z;
  double a;
  const int m = cut(nv, solid, {0, 0, 0}, z, -1, -1, &a);
  if (m < 0) return;  // inside the polyhedron
  const V3& nm = nv[size_t(m)];
  const V3 xm = mad(z, nm, -(dot(z, nm) - solid));
  V3 x = xm, u{};
  int kind = 1;  // 1: face, 2: edge, 3: corner
  const V3 l2{xm[0] - nm[0], xm[1] - nm[1], xm[2] - nm[2]};
  const int r = cut(nv, solid, nm, l2, m, -1, &a);
  if (r >= 0) {
    const V3 xmr = mad(nm, l2, a), &nr = nv[size_t(r)];
    V3 lr{nm[1] * nr[2] - nm[2] * nr[1], nm[2] * nr[0] - nm[0] * nr[2], nm[0] * nr[1] - nm[1] * nr[0]};
    const double ll = std::max(dot(lr, lr), 1e-300);
    const V3 xr = mad(xmr, lr, (dot(z, lr) - dot(xmr, lr)) / ll);
    const double n = std::sqrt(ll);
    u = {lr[0] / n, lr[1] / n, lr[2] / n};
    x = xr, kind = 2;
    const V3 l3{xr[0] - xmr[0], xr[1] - xmr[1], xr[2] - xmr[2]};
    if (cut(nv, solid, xmr, l3, m, r, &a) >= 0) x = mad(xmr, l3, a), kind = 3;
  }
  const V3 d{x[0] - z[0], x[1] - z[1], x[2] - z[2]};
  if (dot(d, d) <= 0) return;
  s.z = mad(z, d, 2);
  for (V3& col : s.j) {
    if (kind == 1) col = mad(col, nm, -2 * dot(col, nm));
    else if (kind == 2) col = mad({-col[0], -col[1], -col[2]}, u, 2 * dot(col, u));
    else col = {-col[0], -col[1], -col[2]};
  }
}

void fold_emit(const Step& st, EmitState& s) {
  const std::vector<V3> nv = normals(int(st.a[0]));
  const std::string arr = s.tmp("pfn");
  std::string init;
  for (const V3& n : nv)
    for (double x : n) init += (init.empty() ? "" : ", ") + s.lit.real(x);
  s.w.open("{");
  s.w.line(fmt::format("const scalar {}[{}] = {{{}}};  // polyhedral_fold: the face normals", arr, 3 * nv.size(), init));
  if (s.jacobian) {
    s.used.insert("fold_polyhedral_j");
    s.w.line(fmt::format("fold_polyhedral_j(&z, &ja, &jb, &jc, {}, {});", arr, nv.size()));
  } else {
    s.used.insert("fold_polyhedral");
    s.w.line(fmt::format("z = fold_polyhedral(z, {}, {});", arr, nv.size()));
  }
  s.w.close();
}

}  // namespace

extern const StepDef kPolyhedralFold{
    "polyhedral_fold",
    {{"type", 1, {0}, false, 0, 7,
      {"tetrahedron", "cube", "octahedron", "dodecahedron", "octahedron_cube", "icosahedron", "hexagonal_prism",
       "pentagonal_prism"}}},
    always_conformal, false, fold_emit, fold_eval,
    "folds z into a polyhedron (face, edge or corner reflection), Mandelbulber's generalized box fold", false,
    keeps_dr};

}  // namespace sdfc::formula
