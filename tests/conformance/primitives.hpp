#pragma once
// The primitive table of the conformance suite. For each primitive: its YAML,
// its exact distance written here from the textbook (closest-point
// formulations, deliberately not the max/length forms the stdlib and the
// reference use), and a parametric sampler of its surface for the
// brute-force check of the oracle.
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "sdfc_test_support.hpp"

namespace sdfc::conformance {

using test::V3;

struct SurfaceSamples {
  std::vector<V3> points;
  double covering = 0;  // every surface point is within this distance of a sample
};

struct Primitive {
  std::string name;
  std::string yaml;  // the geometry node as a YAML flow map, e.g. "sphere: {radius: 0.8}"
  double extent;     // half-size of an origin-centred box that holds the shape (or the test region)
  std::function<double(const V3&)> exact;           // exact signed distance, local frame
  std::function<SurfaceSamples(double)> surface;    // samples with about this spacing, local frame
};
const std::vector<Primitive>& primitives();

// A primitive alone, or under a transform chain: the primitive node has
// scale + axis/angle rotate + translate + material m1, wrapped in a
// one-child union with Euler rotate + translate + scale + material m2, so
// the passes have transforms to fold and materials to order.
struct PrimitiveScene {
  const Primitive* prim = nullptr;
  bool transformed = false;

  std::string name() const { return prim->name + (transformed ? "_transformed" : "_plain"); }
  std::string yaml() const;
  // The chain, outermost first (world = chain[0](chain[1](local))).
  std::vector<test::Similarity> chain() const;
  double distance_scale() const;  // product of the scales
  V3 to_world(const V3& local) const;
  V3 to_local(const V3& world) const;
  double exact(const V3& world) const { return prim->exact(to_local(world)) * distance_scale(); }
  std::string material() const { return transformed ? "m1" : "default"; }  // the innermost one wins
  // An axis-aligned world box around the shape, `pad` times the local extent.
  void world_box(double pad, V3& lo, V3& hi) const;
  SurfaceSamples world_surface(double spacing) const;
};
inline void PrintTo(const PrimitiveScene& s, std::ostream* os) { *os << s.name(); }
std::vector<PrimitiveScene> primitive_scenes();

}  // namespace sdfc::conformance
