// The merge's checks: parts that tile the image pass; a missing, doubled,
// overlapping or mismatched part is refused with a message naming it.
#include <gtest/gtest.h>

#include "merge_plan.hpp"

namespace sdfc::cli {
namespace {

PartInfo part(const std::string& name, int x0, int y0, int x1, int y1, int k = -1, int n = 0) {
  PartInfo p;
  p.path = name;
  auto& h = p.header;
  h.image_width = 10, h.image_height = 8;
  h.x0 = x0, h.y0 = y0, h.x1 = x1, h.y1 = y1;
  h.part = k, h.parts = n;
  h.fingerprint = "f";
  h.sections = {{"beauty", 3}, {"depth", 1}};
  return p;
}

std::string error_of(const std::vector<PartInfo>& parts) {
  try {
    check_parts(parts);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(MergePlan, StripsAndRectanglesThatTileThePicture) {
  EXPECT_EQ(error_of({part("a", 0, 0, 10, 3, 0, 2), part("b", 0, 3, 10, 8, 1, 2)}), "");
  EXPECT_EQ(error_of({part("b", 0, 3, 10, 8, 1, 2), part("a", 0, 0, 10, 3, 0, 2)}), "");  // any order
  EXPECT_EQ(error_of({part("l", 0, 0, 4, 8), part("tr", 4, 0, 10, 5), part("br", 4, 5, 10, 8)}), "");
}

TEST(MergePlan, NamesTheMissingPart) {
  std::string e = error_of({part("a", 0, 0, 10, 2, 0, 4), part("b", 0, 2, 10, 4, 1, 4), part("d", 0, 6, 10, 8, 3, 4)});
  EXPECT_NE(e.find("part 2 of 4 is missing"), std::string::npos) << e;
  e = error_of({part("l", 0, 0, 4, 8), part("tr", 4, 0, 10, 5)});
  EXPECT_NE(e.find("pixels 4,5 to 10,8 are in no part"), std::string::npos) << e;
}

TEST(MergePlan, RefusesOverlapsAndDoubles) {
  std::string e = error_of({part("l", 0, 0, 5, 8), part("r", 4, 0, 10, 8)});
  EXPECT_NE(e.find("'r'"), std::string::npos) << e;
  EXPECT_NE(e.find("overlaps"), std::string::npos) << e;
  e = error_of({part("a", 0, 0, 10, 4, 0, 2), part("a2", 0, 0, 10, 4, 0, 2), part("b", 0, 4, 10, 8, 1, 2)});
  EXPECT_NE(e.find("part 0 of 2 is given twice"), std::string::npos) << e;
}

TEST(MergePlan, RefusesMismatchedParts) {
  auto a = part("a", 0, 0, 10, 4), b = part("b", 0, 4, 10, 8);
  b.header.fingerprint = "g";
  EXPECT_NE(error_of({a, b}).find("another scene or other settings"), std::string::npos);
  b = part("b", 0, 4, 10, 8);
  b.header.bit_depth = 16;
  EXPECT_NE(error_of({a, b}).find("16-bit"), std::string::npos);
  b = part("b", 0, 4, 10, 8);
  b.header.sections.pop_back();
  EXPECT_NE(error_of({a, b}).find("carries beauty, but"), std::string::npos) << error_of({a, b});
  b = part("b", 0, 4, 10, 8);
  b.header.image_height = 9;
  EXPECT_NE(error_of({a, b}).find("10x9"), std::string::npos);
  EXPECT_NE(error_of({}).find("no parts"), std::string::npos);
}

}  // namespace
}  // namespace sdfc::cli
