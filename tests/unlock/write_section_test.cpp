// A whole top-level section (the viewer's bookmarks) written into a scene
// file: added at the end when absent, its own lines replaced when present,
// every other byte kept.
#include <gtest/gtest.h>

#include "sdfc/source/write_section.hpp"
#include "sdfc/source/yaml_loader.hpp"
#include "sdfc/support/diagnostics.hpp"

namespace sdfc {
namespace {

const std::string kScene =
    "# a sphere (this comment must survive)\n"
    "camera: {position: [0, -4, 0], target: [0, 0, 0]}   # the start\n"
    "\n"
    "scene:\n"
    "  sphere: {radius: 1}\n";

std::string write(const std::string& text, const std::string& block) {
  return replace_section(text, load_yaml_text(text, "s.yaml"), "bookmarks", block);
}

TEST(WriteSection, AnAbsentSectionIsAddedAtTheEnd) {
  const std::string block = "bookmarks:\n  - {key: 1, position: [0, -3, 0], target: [0, 0, 0]}\n";
  EXPECT_EQ(write(kScene, block), kScene + block);
  // A file without a final line break gets one before the section.
  std::string bare = kScene.substr(0, kScene.size() - 1);
  EXPECT_EQ(write(bare, block), kScene + block);
}

TEST(WriteSection, APresentSectionIsReplacedAndWhatFollowsIsKept) {
  const std::string before = "# head\nbookmarks:\n  - {key: 1, position: [0, -3, 0], target: [0, 0, 0]}\n";
  const std::string after = "\n# the scene\nscene:\n  sphere: {radius: 1}\n";
  const std::string block = "bookmarks:\n  - {key: 1, position: [1, -3, 0], target: [0, 0, 0]}\n"
                            "  - {key: 2, position: [0, 3, 0], target: [0, 0, 0]}\n";
  // The blank line and the comment before `scene:` belong to the scene.
  EXPECT_EQ(write(before + after, block), "# head\n" + block + after);
  // The last section of the file, then rewritten again: the same text.
  const std::string last = kScene + block;
  EXPECT_EQ(write(last, block), last);
  const std::string one = "bookmarks:\n  - {key: 4, position: [0, -3, 1], target: [0, 0, 0]}\n";
  EXPECT_EQ(write(last, one), kScene + one);
  // The result reads back as the same scene plus the new section.
  SourceValue v = load_yaml_text(write(before + after, block), "s.yaml");
  ASSERT_NE(v.find("bookmarks"), nullptr);
  EXPECT_EQ(v.find("bookmarks")->items.size(), 2u);
  ASSERT_NE(v.find("scene"), nullptr);
}

TEST(WriteSection, AFlowMapFileIsRefused) {
  const std::string flow = "{scene: {sphere: {radius: 1}}}\n";
  EXPECT_THROW(write(flow, "bookmarks:\n  - {key: 1, position: [0, -3, 0], target: [0, 0, 0]}\n"), SceneError);
}

}  // namespace
}  // namespace sdfc
