#pragma once
// An object set: a large union of spheres and boxes (or of small smooth
// unions of them) held as data instead of code. The gather_object_sets pass
// makes one from a union whose such children are worth_a_set; the kernel
// walks a bounding-volume hierarchy over it (stdlib/object_set.cl)
// and reads the numbers from the scene data buffer that follows the frame
// block, so kernel source and build time stay the same for any count.
//
// The node's params: [offset in the scene data buffer, node count, item
// count, primitive count, then the floats the kernel reads]: the hierarchy's
// nodes (kNodeFloats each: box lo xyz, hi xyz, first, count; an inner node
// has count 0, its left child right after it and its right child at
// `first`; a leaf holds items [first, first + count)), the items
// (kItemFloats each: first primitive, primitive count, blend radius,
// material id) and the primitives (kPrimFloats each: type, centre xyz,
// sphere radius or box half extents xyz, box edge radius); then for the
// camera packets' gather a ball about each item (its shapes' balls grown by
// its blend's reach: the items' centres x, then y, z and radii, each
// kItemBallPad longer than the items) and the hierarchy as the gather reads
// it (kGatherFloats per node: every third level of the boxes', with the
// bounding balls of up to eight boxes below).
#include <cstddef>
#include <vector>

#include "sdfc/ir/graph.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::ir::object_set {

// Which unions become sets. A leaf of the hierarchy evaluates every
// primitive of its items, so children of four primitives or fewer (on
// average) pay from a dozen primitives, and larger groups only in numbers,
// where code's box test in front of each group loses to the walk. Smaller
// unions stay code: small scenes keep their fully specialised kernels.
inline constexpr size_t kSetMinChildren = 4, kSetMinPrims = 12, kSetMaxMeanPrims = 4;
inline constexpr size_t kLargeGroupSetMinChildren = 16, kLargeGroupSetMinPrims = 64;
// Whether `children` gatherable children holding `prims` primitives in all become a set.
inline bool worth_a_set(size_t children, size_t prims) {
  if (children >= kLargeGroupSetMinChildren && prims >= kLargeGroupSetMinPrims) return true;
  return children >= kSetMinChildren && prims >= kSetMinPrims && prims <= kSetMaxMeanPrims * children;
}
inline constexpr size_t kHeader = 4;
inline constexpr size_t kNodeFloats = 8, kItemFloats = 4, kPrimFloats = 8;
inline constexpr size_t kLeafItems = 4;  // items per leaf of the hierarchy
inline constexpr int kMaxDepth = 30;     // the kernel's stack holds 2 entries per level (OS_STACK in the stdlib)
// The gather's hierarchy: a node holds the balls about up to kGatherWidth
// boxes of the hierarchy kGatherLevels levels below its own box, so a packet
// tests them together; its stack (OS_GATHER_STACK in the stdlib) holds
// kGatherWidth - 1 entries per level and one more.
inline constexpr int kGatherLevels = 3, kGatherWidth = 1 << kGatherLevels;
inline constexpr size_t kGatherFloats = 5 * kGatherWidth;  // centres x, y, z, radii, then the boxes' indices
inline constexpr size_t kItemBallPad = kLeafItems;  // a leaf's balls are read kLeafItems at a time
inline constexpr int kGatherStack = (kGatherWidth - 1) * ((kMaxDepth + kGatherLevels - 1) / kGatherLevels) + 1;

enum PrimType { kSphere = 0, kBox = 1 };

struct Prim {
  int type = kSphere;
  Vec3d center{0, 0, 0};
  Vec3d size{0, 0, 0};  // sphere: radius in size[0]; box: half extents
  double edge = 0;      // box edge radius
};

// One child of the union: its primitives, smooth-united by `blend` (0 with
// one primitive), all of material `material` (0: none inside the set).
struct Item {
  std::vector<Prim> prims;
  double blend = 0;
  int material = 0;
};

// The node params (header and floats) for these items, with their hierarchy.
std::vector<double> pack(std::vector<Item> items, size_t offset);

// Flops of one evaluation where the walk does the most work: the hierarchy's
// depth plus the most items whose boxes overlap one place (counted on a
// coarse grid), so piling many objects on one spot cannot dodge the scene's
// cost cap.
double worst_cost(const std::vector<Item>& items);

// Reading a packed node back.
struct View {
  const std::vector<double>& q;
  size_t offset() const { return size_t(q[0]); }
  size_t nodes() const { return size_t(q[1]); }
  size_t items() const { return size_t(q[2]); }
  size_t prims() const { return size_t(q[3]); }
  size_t floats() const { return q.size() - kHeader; }
  const double* node(size_t i) const { return q.data() + kHeader + i * kNodeFloats; }
  const double* item(size_t i) const { return q.data() + kHeader + nodes() * kNodeFloats + i * kItemFloats; }
  const double* prim(size_t i) const { return item(items()) + i * kPrimFloats; }
  // Where the items' balls and the gather's hierarchy begin, counted from offset().
  size_t item_balls_at() const { return nodes() * kNodeFloats + items() * kItemFloats + prims() * kPrimFloats; }
  size_t gather_at() const { return item_balls_at() + 4 * (items() + kItemBallPad); }
};

}  // namespace sdfc::ir::object_set
