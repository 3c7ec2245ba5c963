#include "merge_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace sdfc::cli {
namespace {

std::string where(const PartInfo& p) {
  const auto& h = p.header;
  const std::string part = h.parts > 0 ? fmt::format("part {} of {}, ", h.part, h.parts) : "";
  return fmt::format("'{}' ({}pixels {},{} to {},{})", p.path, part, h.x0, h.y0, h.x1, h.y1);
}

std::string section_list(const sdfrt::RegionHeader& h) {
  std::string s;
  for (const auto& sec : h.sections) s += (s.empty() ? "" : ", ") + sec.name;
  return s;
}

void check_same_image(const PartInfo& first, const PartInfo& p) {
  const auto &a = first.header, &b = p.header;
  if (a.image_width != b.image_width || a.image_height != b.image_height)
    throw std::invalid_argument(fmt::format("{} is part of a {}x{} image, but {} of a {}x{} one", where(p), b.image_width,
                                            b.image_height, where(first), a.image_width, a.image_height));
  if (a.fingerprint != b.fingerprint)
    throw std::invalid_argument(fmt::format("{} was rendered from another scene or other settings than {}; render "
                                            "every part with the same scene, --set and render options",
                                            where(p), where(first)));
  if (a.bit_depth != b.bit_depth)
    throw std::invalid_argument(
        fmt::format("{} is {}-bit, {} is {}-bit", where(p), b.bit_depth, where(first), a.bit_depth));
  if (section_list(a) != section_list(b))
    throw std::invalid_argument(fmt::format("{} carries {}, but {} carries {}; render every part with the same --aov",
                                            where(p), section_list(b), where(first), section_list(a)));
  if (a.parts != b.parts)
    throw std::invalid_argument(fmt::format("{} and {} come from different splits", where(p), where(first)));
}

// Parts numbered by --parts: name a missing number before any pixel talk.
void check_numbers(const std::vector<PartInfo>& parts) {
  const int n = parts.front().header.parts;
  if (n == 0) return;
  std::set<int> seen;
  for (const auto& p : parts)
    if (!seen.insert(p.header.part).second)
      throw std::invalid_argument(fmt::format("part {} of {} is given twice (the second is {})", p.header.part, n,
                                              where(p)));
  for (int k = 0; k < n; ++k)
    if (!seen.count(k))
      throw std::invalid_argument(fmt::format(
          "part {} of {} is missing: none of the {} files given carries it (did its task fail? render it with "
          "'sdfc render ... --parts {} --shard {}/{}' and merge again)",
          k, n, parts.size(), n, k, n));
}

// Every row band between two region edges must be covered by x-intervals
// that tile [0, width) with neither gap nor overlap.
void check_coverage(const std::vector<PartInfo>& parts) {
  const int w = parts.front().header.image_width, h = parts.front().header.image_height;
  std::set<int> edges{0, h};
  for (const auto& p : parts) edges.insert(p.header.y0), edges.insert(p.header.y1);
  for (auto it = edges.begin(); std::next(it) != edges.end(); ++it) {
    const int y0 = *it, y1 = *std::next(it);
    std::vector<const PartInfo*> row;
    for (const auto& p : parts)
      if (p.header.y0 <= y0 && p.header.y1 >= y1) row.push_back(&p);
    std::sort(row.begin(), row.end(), [](auto* a, auto* b) { return a->header.x0 < b->header.x0; });
    int x = 0, gap_end = w;
    for (const PartInfo* p : row) {
      if (p->header.x0 < x)
        throw std::invalid_argument(fmt::format("{} overlaps another part in rows {}..{}", where(*p), y0, y1 - 1));
      if (p->header.x0 > x) {
        gap_end = p->header.x0;
        break;
      }
      x = p->header.x1;
    }
    if (x < w)
      throw std::invalid_argument(
          fmt::format("pixels {},{} to {},{} are in no part given: a part is missing", x, y0, gap_end, y1));
  }
}

}  // namespace

void check_parts(const std::vector<PartInfo>& parts) {
  if (parts.empty()) throw std::invalid_argument("no parts to merge");
  for (const auto& p : parts) check_same_image(parts.front(), p);
  check_numbers(parts);
  check_coverage(parts);
}

}  // namespace sdfc::cli
