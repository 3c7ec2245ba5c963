// Saving from the panel: only the characters of the changed values change,
// everything else (comments, order, spacing, quotes) stays byte for byte, and
// a file changed on disk since it was loaded is not replaced.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include "run_sdfc.hpp"
#include "sdfc/source/write_back.hpp"
#include "sdfc/source/yaml_loader.hpp"
#include "sdfc/support/diagnostics.hpp"
#include "test_files.hpp"

namespace sdfc {
namespace {

const std::string kScene =
    "# A sphere and a box, commented.\n"
    "camera: {position: [0, -6, 2], target: [0, 0, 0]}   # looking at the origin\n"
    "lights:\n"
    "  - point: {position: [2, -3, 3], intensity: 6}\n"
    "scene:\n"
    "  union:\n"
    "    - sphere:\n"
    "        radius:   0.80   # odd spacing survives\n"
    "      translate: [-1, 0, 0]\n"
    "    - box: {size: [1, 1, 1], radius: '0.05'}\n";

std::string rewrite(const std::string& text, const std::vector<ValueEdit>& edits) {
  return rewrite_values(text, load_yaml_text(text, "s.yaml"), edits);
}

// `text` with `from` (once, at or after `after`) replaced by `to`.
std::string replaced(std::string text, const std::string& after, const std::string& from, const std::string& to) {
  size_t at = text.find(from, text.find(after));
  text.replace(at, from.size(), to);
  return text;
}

TEST(WriteBack, NothingChangedIsByteIdentical) {
  EXPECT_EQ(rewrite(kScene, {}), kScene);
  EXPECT_EQ(rewrite(kScene, {{"scene.union[0].sphere.radius", "0.80"}}), kScene);
}

TEST(WriteBack, OnlyTheEditedCharactersChange) {
  std::string out = rewrite(kScene, {{"scene.union[0].sphere.radius", "0.75"},
                                     {"scene.union[0].translate[0]", "-1.25"},
                                     {"lights.0.point.intensity", "12"}});
  std::string expected = replaced(kScene, "radius:", "0.80", "0.75");
  expected = replaced(expected, "translate:", "-1", "-1.25");
  expected = replaced(expected, "intensity:", "6", "12");
  EXPECT_EQ(out, expected);
  SourceValue back = load_yaml_text(out, "s.yaml");
  EXPECT_EQ(back.find("scene")->find("union")->items[0].find("sphere")->find("radius")->scalar, "0.75");
}

TEST(WriteBack, QuotedValuesKeepTheirQuotes) {
  std::string out = rewrite(kScene, {{"scene.union[1].box.radius", "0.1"}});
  EXPECT_EQ(out, replaced(kScene, "box:", "'0.05'", "'0.1'"));
}

TEST(WriteBack, UndoRestoresTheFile) {
  std::string edited = rewrite(kScene, {{"scene.union[0].sphere.radius", "1.5"}});
  ASSERT_NE(edited, kScene);
  EXPECT_EQ(rewrite(edited, {{"scene.union[0].sphere.radius", "0.80"}}), kScene);
}

TEST(WriteBack, RefusesWhatItCannotWriteExactly) {
  EXPECT_THROW(rewrite(kScene, {{"scene.union[0].sphere", "1"}}), SceneError);      // a map
  EXPECT_THROW(rewrite(kScene, {{"scene.union[5].sphere.radius", "1"}}), SceneError);  // no such item
  EXPECT_THROW(rewrite(kScene, {{"lights.0.point.intensity", "1 # x"}}), SceneError);  // not one word
  EXPECT_THROW(rewrite(kScene, {{"lights.0.point.intensity", "{a: 1}"}}), SceneError);
  const std::string folded = "scene:\n  sphere:\n    radius: \"1\\\n      .5\"\n";
  EXPECT_THROW(rewrite(folded, {{"scene.sphere.radius", "2"}}), SceneError);  // escaped across lines
}

TEST(WriteBack, NumbersAreTheShortestTextThatReadsBack) {
  EXPECT_EQ(yaml_number(0.75), "0.75");
  EXPECT_EQ(yaml_number(2), "2");
  EXPECT_EQ(yaml_number(40), "40");  // a slider left at 40 is saved as people write it
  EXPECT_EQ(yaml_number(1500), "1500");
  EXPECT_EQ(yaml_number(-1e-5), "-1e-05");
  EXPECT_EQ(yaml_number(0.1 + 0.2), "0.30000000000000004");
  for (double x : {1.0 / 3, 123456.789, -0.0625}) EXPECT_EQ(std::stod(yaml_number(x)), x);
}

TEST(WriteBack, SaveReplacesOnlyAnUnchangedFileAndKeepsItsMode) {
  test::ScratchDir dir;
  std::string path = dir.write("s.yaml", kScene);
  ::chmod(path.c_str(), 0640);
  std::string edited = rewrite(kScene, {{"lights.0.point.intensity", "7"}});
  EXPECT_TRUE(save_if_unchanged(path, kScene, edited));
  EXPECT_EQ(test::read_text_file(path), edited);
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u);
  // Someone else saved meanwhile: the file is left as they wrote it.
  EXPECT_FALSE(save_if_unchanged(path, kScene, kScene));
  EXPECT_EQ(test::read_text_file(path), edited);
}

}  // namespace
}  // namespace sdfc
