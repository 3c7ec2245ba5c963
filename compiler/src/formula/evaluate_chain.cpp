// The chain's orbit in double, step for step as emit_chain writes it.
#include <algorithm>
#include <cmath>

#include "sdfc/formula/evaluate.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {

namespace {
double length(const V3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
}  // namespace

OrbitResult evaluate(const Chain& c, const std::array<double, 3>& p,
                     const std::function<double(const std::array<double, 3>&)>& measure) {
  const Plan pl = plan(c);
  RefState s;
  s.z = p;
  s.c = c.julia ? c.c : p;
  s.mandel = !c.julia;
  s.jacobian = pl.jacobian;
  s.four_d = four_d(c);
  s.w = c.w_start;
  s.cw = c.julia ? c.cw : 0;
  // a 4-D chain's r is |(z, w)|
  auto radius = [&] { return s.four_d ? std::sqrt(length(s.z) * length(s.z) + s.w * s.w) : length(s.z); };
  double trap = 1e10, n = 0;
  double r = radius();
  for (int i = 0; i < c.iterations && r < c.bailout; ++i) {
    for (size_t k = i == 0 ? 0 : size_t(c.repeat_from); k < c.steps.size(); ++k) {
      const Step& st = c.steps[k];
      const int at = st.period > 0 ? i % st.period : i;
      if (at >= st.from && at < st.until) st.def->eval(st, s);
    }
    n += 1;
    trap = std::min(trap, measure ? measure(s.z) : std::min({std::fabs(s.z[0]), std::fabs(s.z[1]), std::fabs(s.z[2])}));
    r = radius();
  }
  double norm = std::fabs(s.dr);
  if (pl.jacobian) {
    norm = 0;
    for (const V3& col : s.j) norm += col[0] * col[0] + col[1] * col[1] + col[2] * col[2];
    norm += s.jw[0] * s.jw[0] + s.jw[1] * s.jw[1] + s.jw[2] * s.jw[2];
    norm = std::sqrt(norm);
  }
  norm = std::max(norm, 1e-30);
  double d = pl.log ? 0.5 * std::log(std::max(r, 1e-20)) * r / norm : r / norm;
  if (pl.kleinian) {
    double rxy = std::sqrt(s.z[0] * s.z[0] + s.z[1] * s.z[1]);
    d = std::max(rxy - c.kleinian_size, std::fabs(rxy * s.z[2]) / std::max(r, 1e-20)) / norm;
  }
  if (pl.jos_kleinian) {
    const double y = c.jos_height > 0 ? std::min(s.z[1], c.jos_height - s.z[1]) : s.z[1];
    d = std::min(y, c.jos_cap) / std::max(norm, c.jos_min_dr);
  }
  double r0 = length(p);
  const double ball = c.set_radius > 0 ? c.set_radius : c.bailout;
  if (pl.jos_kleinian) d = std::max(d, r0 - c.bailout);
  if (r0 > 2 * ball) d = r0 - ball;
  return {d, trap, n, r};
}

}  // namespace sdfc::formula
