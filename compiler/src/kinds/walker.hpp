#pragma once
// The scene walker as a kind with children sees it (codegen/scene_emitter.cpp
// implements it): it writes the node's statements, asks for its children's
// values at new points and gets back what the function being written
// carries. A kind's walk hook never asks which function that is.
#include <string>
#include <vector>

#include "../codegen/code_writer.hpp"
#include "sdfc/ir/module.hpp"
#include "sdfc/kinds/description.hpp"

namespace sdfc::kinds {

// A node's value in the walker: its distance variable and, where the function
// tracks them, its material (id or trap, "" when not tracked) and its
// blended material record ("" outside scene_material).
struct Carried {
  std::string d;
  std::string mat;
  std::string rec = "";
};

// The same value with another distance (operations on the distance keep the material).
inline Carried with_d(Carried v, std::string d) {
  v.d = std::move(d);
  return v;
}

class Walker {
 public:
  virtual ~Walker() = default;
  // Child `id` evaluated at point expression p (with its Lipschitz correction).
  virtual Carried child(ir::NodeId id, const std::string& p) = 0;
  // The nearest of n's only child over several points (one loop, its code once).
  virtual Carried cells(const ir::Node& n, const std::vector<std::string>& points) = 0;
  virtual void line(const std::string& s) = 0;
  virtual void open(const std::string& s) = 0;  // a line that opens a block, indenting what follows
  virtual void close(const std::string& s) = 0;
  virtual std::string var(const char* prefix) = 0;
  // The stdlib function fn, recorded as used.
  virtual std::string call(const std::string& fn) = 0;
  // The node as a kernel comment ("twist axis=2 rate=1.5  (scene.yaml:12)"), and its source line alone.
  virtual std::string describe(const ir::Node& n) const = 0;
  virtual std::string where(const ir::Node& n) const = 0;
  virtual const codegen::detail::Literals& lit() const = 0;
  // What the function being written carries besides the distance: a
  // material id (or, in scene_trap and scene_iterations, a fractal's trap or
  // count, which materials leave alone), and blended material records
  // (scene_material), whose material is the nearest material node's.
  virtual bool tracks_material() const = 0;
  virtual bool tracks_trap() const = 0;
  virtual bool carries_records() const = 0;
  // scene_material: the material of the leaves below; returns the one before.
  virtual double enter_material(double id) = 0;
  // scene_material: the material of the nearest material node above (0: none).
  virtual double material() const = 0;
  virtual const ir::Graph& graph() const = 0;
  virtual const ir::Module& module() const = 0;

  // A union's fold of its other children, set while it walks an object set
  // as its last child: items no nearer cannot change the union, so the
  // set's walk culls by it. Empty: no bound.
  std::string cull_bound;

  // In scene_dist: an upper bound of the scene's distance at p (empty:
  // none), seen by the root alone. A root union whose last child is an
  // object set culls that set's walk by it too (see bounded_normals).
  std::string above;

  // In the marching loops' distance: the mask of the lanes still marching
  // (the others' values are thrown away, so an object set's walk opens no
  // box for them). Elsewhere every lane counts: M_TRUE.
  std::string live_lanes = "M_TRUE";

  // In the camera rays' march: the packet's cone (os_cone), outside which an
  // object set's items cannot matter to those rays. Elsewhere none.
  std::string cone = "os_cone_none()";

  // Parameter i of n: a literal or its animated expression; param3: a vec3 from i.
  std::string param(const ir::Node& n, size_t i) const { return codegen::detail::param(n, i, lit()); }
  std::string param3(const ir::Node& n, size_t i) const { return codegen::detail::param3(n, i, lit()); }
  // A new point variable: vec3 NAME = expr;  // describe(n)
  std::string point(const ir::Node& n, const std::string& expr) {
    std::string p2 = var("p");
    line("vec3 " + p2 + " = " + expr + ";  // " + describe(n));
    return p2;
  }
};

}  // namespace sdfc::kinds

namespace sdfc::kinds {

// render.normals: dual: a node's distance and gradient variables.
struct Dual {
  std::string d, g;
};

// The gradient walker (codegen/gradient_emitter.cpp) as a kind with
// children sees it. Its parameters are the values at time 0.
class DualWalker {
 public:
  virtual ~DualWalker() = default;
  virtual Dual child(ir::NodeId id, const std::string& p) = 0;
  virtual void line(const std::string& s) = 0;
  virtual std::string var(const char* prefix) = 0;
  virtual std::string call(const std::string& fn) = 0;
  virtual const codegen::detail::Literals& lit() const = 0;
  std::string real(double v) const { return lit().real(v); }
};

}  // namespace sdfc::kinds
