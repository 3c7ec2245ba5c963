#pragma once
// sdfc audit: measure where a scene's distance field breaks the promises
// sphere tracing relies on, node by node, with the CPU reference evaluator
// (which the conformance suite ties to every OpenCL evaluator).
//  - slope: max |d(p) - d(q)| / |p - q| along sampled lines (seed 001 part
//    VII's test; a consistent distance bound has slope <= 1);
//  - overshoot: rays on which marching by the distance passes the first
//    surface a conservative march (small steps, watching the sign) finds;
//  - non-finite values;
//  - the step factor that removes the overshoot, verified by re-marching.
#include <cstdint>
#include <string>
#include <vector>

#include "sdfc/ir/module.hpp"

namespace sdfc::analysis {

struct AuditOptions {
  int lines = 96;              // lines per node for the slope test
  int samples_per_line = 64;
  int rays = 128;              // rays per node for the overshoot test
  int max_steps = 512;         // of the distance march
  uint64_t seed = 1;
};

struct NodeAudit {
  ir::NodeId node;
  std::string kind;
  int line = 0;                // YAML line, 0 if none
  ir::DistanceClass cls;
  double promised_lipschitz;   // what infer_properties promises
  double measured_slope;       // max over the sampled lines
  int rays = 0, overshoots = 0;  // rays marched, rays that passed a surface
  long nonfinite = 0;          // NaN/Inf distances seen
  double recommended_step_factor = 1.0;  // 1 when no overshoot was seen
  bool warning = false;        // overshoot, non-finite values, or an exact field steeper than 1
  std::string note;            // why, in words
  double overshoot_rate() const { return rays ? double(overshoots) / rays : 0; }
};

struct AuditReport {
  std::vector<NodeAudit> nodes;  // children before parents; the root last
  bool any_warning() const;
};

AuditReport audit(const ir::Module& m, const AuditOptions& opt = {});

std::string format_table(const AuditReport& r);
std::string format_json(const AuditReport& r);

}  // namespace sdfc::analysis
