// Material shares across smooth blends: a blended point shows each
// material in proportion to how much its child shapes the blended distance.
#include "materials.hpp"

#include <algorithm>
#include <cmath>

namespace sdfc::reference::detail {

namespace {

std::vector<std::pair<int, double>> shares_of(const Sample& s) {
  if (s.shares.empty()) return {{s.material, 1.0}};
  return s.shares;
}

void add(std::vector<std::pair<int, double>>& out, int id, double w) {
  if (w == 0) return;
  for (auto& [i, v] : out)
    if (i == id) {
      v += w;
      return;
    }
  out.emplace_back(id, w);
}

}  // namespace

double share_of_b(const std::function<double(double, double)>& blend, double a, double b) {
  double e = 1e-6 * std::max({1.0, std::fabs(a), std::fabs(b)});
  double w = (blend(a, b + e) - blend(a, b - e)) / (2 * e);
  // The difference quotient carries rounding noise of ~1e-12 where the
  // blend is flat in b (or follows b): that is 0 (or 1), one child alone.
  if (w < 1e-9) return 0;
  if (w > 1 - 1e-9) return 1;
  return w;
}

Sample mix_samples(const Sample& a, const Sample& b, double wb, double distance, int material) {
  Sample out{distance, material};
  for (const auto& [id, w] : shares_of(a)) add(out.shares, id, w * (1 - wb));
  for (const auto& [id, w] : shares_of(b)) add(out.shares, id, w * wb);
  if (out.shares.size() == 1 && out.shares[0].first == material) out.shares.clear();  // `material` says it
  return out;
}

void claim(Sample& s, int material) {
  if (s.material == 0) s.material = material;
  std::vector<std::pair<int, double>> merged;
  for (const auto& [id, w] : s.shares) add(merged, id == 0 ? material : id, w);
  s.shares = std::move(merged);
}

}  // namespace sdfc::reference::detail
