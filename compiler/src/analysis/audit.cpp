#include "sdfc/analysis/audit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <unordered_map>

#include "sdfc/kinds/formula_node.hpp"
#include "sdfc/reference/evaluator.hpp"

namespace sdfc::analysis {

namespace {

using reference::Vec3;

Vec3 add(Vec3 a, Vec3 b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 sub(Vec3 a, Vec3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 mul(Vec3 a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double norm(Vec3 a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// Where to look at a node: its bounds (in the node's own input frame, where
// infer_properties puts them), grown by a quarter, unbounded sides clamped.
struct Region {
  Vec3 lo, hi;
  Vec3 centre() const { return mul(add(lo, hi), 0.5); }
  double diagonal() const { return norm(sub(hi, lo)); }
};

Region region_of(const ir::Props& p) {
  Region r;
  for (int i = 0; i < 3; ++i) {
    double lo = std::isfinite(p.bounds.lo[i]) ? p.bounds.lo[i] : -3.0;
    double hi = std::isfinite(p.bounds.hi[i]) ? p.bounds.hi[i] : 3.0;
    double pad = 0.25 * (hi - lo) + 0.1;
    r.lo[i] = lo - pad, r.hi[i] = hi + pad;
  }
  return r;
}

class Probe {
 public:
  Probe(const ir::Graph& g, ir::NodeId n) : g_(g), n_(n) {}
  double operator()(const Vec3& p) {
    double d = reference::evaluate(g_, n_, p).distance;
    if (!std::isfinite(d)) ++nonfinite;
    return d;
  }
  long nonfinite = 0;

 private:
  const ir::Graph& g_;
  ir::NodeId n_;
};

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0, 1);
  for (;;) {
    Vec3 v{n(rng), n(rng), n(rng)};
    double l = norm(v);
    if (l > 1e-9) return mul(v, 1 / l);
  }
}

Vec3 random_in(const Region& r, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  return {r.lo[0] + u(rng) * (r.hi[0] - r.lo[0]), r.lo[1] + u(rng) * (r.hi[1] - r.lo[1]),
          r.lo[2] + u(rng) * (r.hi[2] - r.lo[2])};
}

// Max slope of d along random lines, over pairs of neighbouring samples that
// are both outside the surface: that is where the march steps by d.
double measure_slope(Probe& f, const Region& r, const AuditOptions& opt, std::mt19937_64& rng) {
  double worst = 0, length = 0.5 * r.diagonal();
  for (int l = 0; l < opt.lines; ++l) {
    Vec3 a = random_in(r, rng), dir = random_unit(rng);
    double h = length / (opt.samples_per_line - 1);
    double prev = f(a);
    for (int i = 1; i < opt.samples_per_line; ++i) {
      double d = f(add(a, mul(dir, h * i)));
      if (std::isfinite(d) && std::isfinite(prev) && d >= 0 && prev >= 0) worst = std::max(worst, std::fabs(d - prev) / h);
      prev = d;
    }
  }
  return worst;
}

struct Ray {
  Vec3 origin, dir;
  double t_max;
};

// The first surface along the ray found by steps no longer than a twentieth
// of the distance and a small fraction of the region; -1 if none. A surface
// is where d < eps, as for the march: fractal estimators such as the
// Mandelbox's r/|dr| never change sign, so a sign test would find nothing.
double conservative_hit(Probe& f, const Ray& ray, double diag, double eps) {
  double t = 0, h_max = diag / 400, h_min = diag / 20000;
  while (t < ray.t_max) {
    double d = f(add(ray.origin, mul(ray.dir, t)));
    if (!std::isfinite(d)) return -1;
    if (d < eps) return t;
    t += std::clamp(0.05 * d, h_min, h_max);
  }
  return -1;
}

// Sphere tracing with a step factor: did it pass `surface` without a hit?
bool overshoots(Probe& f, const Ray& ray, double surface, double step_factor, double eps, double tolerance,
                int max_steps) {
  double t = 0;
  for (int i = 0; i < max_steps && t < ray.t_max; ++i) {
    double d = f(add(ray.origin, mul(ray.dir, t)));
    if (!std::isfinite(d)) return false;
    if (d < eps) return t > surface + tolerance;
    t += d * step_factor;
    if (t > surface + tolerance) return true;
  }
  return false;
}

bool worth_auditing(ir::Kind k) {
  // Rigid transforms, materials and bounding boxes pass the child's field on
  // unchanged in shape; auditing them repeats the child's numbers.
  return k != ir::Kind::Translate && k != ir::Kind::Rotate && k != ir::Kind::Scale && k != ir::Kind::Material &&
         k != ir::Kind::Bounded;
}

NodeAudit audit_node(const ir::Graph& g, ir::NodeId id, const AuditOptions& opt, std::mt19937_64& rng) {
  const ir::Node& n = g.node(id);
  NodeAudit a;
  a.node = id;
  a.kind = std::string(ir::info(n.kind).name);
  a.line = n.loc.line;
  a.cls = n.props.cls;
  a.promised_lipschitz = n.props.lipschitz;
  Probe f(g, id);
  Region r = region_of(n.props);
  a.measured_slope = measure_slope(f, r, opt, rng);

  double diag = r.diagonal(), eps = 1e-4 * diag, tolerance = 1e-3 * diag;
  std::vector<std::pair<Ray, double>> hits;  // rays with a surface, and where
  for (int i = 0; i < opt.rays; ++i) {
    Vec3 from = add(r.centre(), mul(random_unit(rng), 0.75 * diag));
    Vec3 to = random_in(r, rng);
    Vec3 dir = sub(to, from);
    Ray ray{from, mul(dir, 1 / norm(dir)), 1.5 * diag};
    double surface = conservative_hit(f, ray, diag, eps);
    if (surface >= 0) hits.push_back({ray, surface});
  }
  auto count = [&](double sf) {
    int c = 0;
    for (const auto& [ray, surface] : hits) c += overshoots(f, ray, surface, sf, eps, tolerance, opt.max_steps);
    return c;
  };
  a.rays = int(hits.size());
  a.overshoots = count(1.0);
  if (a.overshoots > 0) {
    // Start from 1/slope (with a margin) and shrink until the rays pass.
    double sf = std::min(1.0, 0.9 / std::max(a.measured_slope, 1e-9));
    while (sf > 0.02 && count(sf) > 0) sf *= 0.8;
    a.recommended_step_factor = sf;
  }
  a.nonfinite = f.nonfinite;

  // What the class promises. An exact field is 1-Lipschitz and continuous, so
  // its slope must not exceed 1. A bound (or a corrected Lipschitz field, or
  // a fractal estimate) promises never to exceed the distance, which is what
  // the overshoot test measures; such fields may jump (a box standing in far
  // away), so their slope is reported, not judged.
  if (a.nonfinite > 0) {
    a.warning = true;
    a.note = fmt::format("{} non-finite distances", a.nonfinite);
  } else if (a.overshoots > 0) {
    a.warning = true;
    a.note = fmt::format("{} of {} rays pass a surface; step factor {:.2f} removes it", a.overshoots, a.rays,
                         a.recommended_step_factor);
    // A formula chain: name the step its estimate takes on trust.
    if (n.kind == ir::Kind::Formula) {
      const std::string step = formula::plan(kinds::chain_of(n)).leans_on;
      if (!step.empty()) a.note += fmt::format(" (the estimate trusts the growth of the chain's {})", step);
    }
  } else if (a.cls == ir::DistanceClass::Exact && a.measured_slope > 1.02) {
    a.warning = true;
    a.note = fmt::format("an exact field with slope {:.3g} > 1", a.measured_slope);
  }
  return a;
}

// The same DAG with the bounding boxes the passes inserted taken out: they
// are an optimisation that keeps the field a lower bound (proven in the
// pass), and their switch from box to child is a jump the slope test would
// count as steepness.
ir::Module without_bounding_boxes(const ir::Module& m) {
  ir::Module out = m;
  out.graph = std::make_shared<ir::Graph>();
  out.graph->expressions = m.graph->expressions;  // displacement expressions, by index
  ir::Builder b(*out.graph);
  std::unordered_map<ir::NodeId, ir::NodeId> mapped;
  for (ir::NodeId id : m.graph->postorder(m.root)) {
    const ir::Node& n = m.graph->node(id);
    if (n.kind == ir::Kind::Bounded) {
      mapped[id] = mapped.at(n.children[0]);
      continue;
    }
    std::vector<ir::NodeId> kids;
    for (ir::NodeId c : n.children) kids.push_back(mapped.at(c));
    ir::NodeId nid = b.copy(n, std::move(kids));
    out.graph->mutable_node(nid).props = n.props;
    mapped[id] = nid;
  }
  out.root = mapped.at(m.root);
  return out;
}

}  // namespace

bool AuditReport::any_warning() const {
  for (const auto& n : nodes)
    if (n.warning) return true;
  return false;
}

AuditReport audit(const ir::Module& scene, const AuditOptions& opt) {
  const ir::Module m = without_bounding_boxes(scene);
  AuditReport r;
  std::mt19937_64 rng(opt.seed);
  for (ir::NodeId id : m.graph->postorder(m.root))
    if (id == m.root || worth_auditing(m.graph->node(id).kind)) r.nodes.push_back(audit_node(*m.graph, id, opt, rng));
  return r;
}

std::string format_table(const AuditReport& r) {
  std::string s = fmt::format("{:<22} {:>5} {:<9} {:>6} {:>7} {:>10} {:>8} {:>5}  {}\n", "node", "line", "class", "L",
                              "slope", "overshoot", "nonfinite", "step", "verdict");
  for (const auto& n : r.nodes)
    s += fmt::format("{:<22} {:>5} {:<9} {:>6.3g} {:>7.3f} {:>4}/{:<5} {:>8} {:>5.2f}  {}\n", n.kind,
                     n.line > 0 ? std::to_string(n.line) : "-", ir::to_string(n.cls), n.promised_lipschitz,
                     n.measured_slope, n.overshoots, n.rays, n.nonfinite, n.recommended_step_factor,
                     n.warning ? "WARNING: " + n.note : "ok");
  return s;
}

std::string format_json(const AuditReport& r) {
  std::string s = "{\"nodes\": [";
  for (size_t i = 0; i < r.nodes.size(); ++i) {
    const auto& n = r.nodes[i];
    s += fmt::format(
        "{}\n  {{\"kind\": \"{}\", \"line\": {}, \"class\": \"{}\", \"promised_lipschitz\": {}, \"measured_slope\": {}, "
        "\"rays\": {}, \"overshoots\": {}, \"overshoot_rate\": {}, \"nonfinite\": {}, \"recommended_step_factor\": {}, "
        "\"warning\": {}}}",
        i ? "," : "", n.kind, n.line, ir::to_string(n.cls), n.promised_lipschitz, n.measured_slope, n.rays,
        n.overshoots, n.overshoot_rate(), n.nonfinite, n.recommended_step_factor, n.warning ? "true" : "false");
  }
  return s + "\n]}\n";
}

}  // namespace sdfc::analysis
