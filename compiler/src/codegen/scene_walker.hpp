#pragma once
// The one scene walker: writes a scene function's body, one statement per
// IR node (each commented with the node and its YAML line). Points flow down
// (transforms make new point variables), values flow up. What a value holds
// besides the distance is what the function carries; the kinds with
// children write their own statements through kinds::Walker and never ask
// which function it is.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "../kinds/walker.hpp"
#include "code_writer.hpp"
#include "sdfc/ir/module.hpp"

namespace sdfc::codegen::detail {

enum class Carry {
  Distance,    // scene_dist: the distance alone
  Material,    // scene_dist_mat: the nearest material's id
  Trap,        // scene_trap: the nearest fractal's orbit trap (or smooth count, as its material asks)
  Iterations,  // scene_iterations: the nearest fractal's escape count (the AOV)
  Records,     // scene_material: material records mixed at smooth blends, and the nearest id
};

class SceneWalker final : public kinds::Walker {
 public:
  SceneWalker(const ir::Module& m, const Literals& lit, std::set<std::string>& used, CodeWriter& w, Carry carry);
  // A node's value at point p, divided by its Lipschitz constant where the
  // properties pass marked it for correction.
  kinds::Carried emit(ir::NodeId id, const std::string& p);

  // kinds::Walker
  kinds::Carried child(ir::NodeId id, const std::string& p) override { return emit(id, p); }
  kinds::Carried cells(const ir::Node& n, const std::vector<std::string>& points) override;
  void line(const std::string& s) override { w_.line(s); }
  void open(const std::string& s) override { w_.open(s); }
  void close(const std::string& s) override { w_.close(s); }
  std::string var(const char* prefix) override;
  std::string call(const std::string& fn) override;
  std::string describe(const ir::Node& n) const override;
  std::string where(const ir::Node& n) const override;
  const Literals& lit() const override { return lit_; }
  const ir::Graph& graph() const override { return g_; }
  bool tracks_material() const override { return carry_ != Carry::Distance; }
  bool tracks_trap() const override { return carry_ == Carry::Trap || carry_ == Carry::Iterations; }
  bool carries_records() const override { return carry_ == Carry::Records; }
  double enter_material(double id) override;
  double material() const override { return cur_mat_; }
  const ir::Module& module() const override { return m_; }

 private:
  kinds::Carried emit_node(ir::NodeId id, const std::string& p);
  kinds::Carried leaf(const ir::Node& n, const std::string& expr);
  kinds::Carried fractal(ir::NodeId id, const ir::Node& n, const std::string& p);
  std::string record(const ir::Node& n);
  void find_trap_sources(const ir::Module& m, ir::NodeId id, int material);

  const ir::Module& m_;
  const ir::Graph& g_;
  const ir::RenderPlan& plan_;
  const Literals& lit_;
  std::set<std::string>& used_;
  CodeWriter& w_;
  const Carry carry_;
  const bool orbit_traps_;
  const bool coloring_geometry_;
  const std::string file_;
  double cur_mat_ = 0;  // Records: the material of the nearest material node above
  std::string leaf_p_;
  std::set<ir::NodeId> iteration_;    // fractals whose material colours by the smooth iteration count
  std::map<ir::NodeId, size_t> shaped_;  // fractals whose material's trap has a shape, and that material
};

}  // namespace sdfc::codegen::detail
