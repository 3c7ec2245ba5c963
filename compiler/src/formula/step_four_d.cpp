// The running Jacobian of a 4-D step: its 4x4 map applied to each column
// of dz/dp together with that column's entry of the w row (dw/dp).
#include <fmt/format.h>

#include "../codegen/code_writer.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {

void emit_rows4(EmitState& s, const std::array<std::string, 16>& m) {
  // one row: the sum of the non-zero entries times the column's components
  auto row = [&](int i) {
    static const char* const d[4] = {"dx", "dy", "dz", "dw"};
    std::string out;
    for (int j = 0; j < 4; ++j)
      if (!m[size_t(4 * i + j)].empty()) out += fmt::format("{}({}) * {}", out.empty() ? "" : " + ", m[size_t(4 * i + j)], d[j]);
    return out.empty() ? std::string("(real)(0.0f)") : out;
  };
  s.w.open("{  // the Jacobian of the 4-D step, column by column");
  const char* cols[3][2] = {{"ja", "jw.x"}, {"jb", "jw.y"}, {"jc", "jw.z"}};
  for (auto& c : cols)
    s.w.line(fmt::format("{{ const real dx = {0}.x, dy = {0}.y, dz = {0}.z, dw = {1}; {0} = v3({2}, {3}, {4}); {1} = {5}; }}",
                         c[0], c[1], row(0), row(1), row(2), row(3)));
  s.w.close();
}

void apply_rows4(RefState& s, const std::array<double, 16>& m) {
  double* w[3] = {&s.jw[0], &s.jw[1], &s.jw[2]};
  for (int k = 0; k < 3; ++k) {
    const double d[4] = {s.j[size_t(k)][0], s.j[size_t(k)][1], s.j[size_t(k)][2], *w[k]};
    double out[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) out[i] += m[size_t(4 * i + j)] * d[j];
    s.j[size_t(k)] = {out[0], out[1], out[2]};
    *w[k] = out[3];
  }
}

}  // namespace sdfc::formula
