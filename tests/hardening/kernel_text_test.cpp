// Text from a scene (material names, file names, --set values) reaches the
// kernel only through kernel_text(): hostile names build and render exactly
// like plain ones, and the kernel holds only printable ASCII.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "kernel_text.hpp"
#include "run_sdfc.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/source/yaml_loader.hpp"
#include "sdfc_test_support.hpp"

namespace sdfc::test {
namespace {

// YAML double-quoted spellings of names that broke out of a `//` comment
// or would: newline, lone CR, block-comment end, line-continuing backslash,
// a trigraph backslash, NUL, non-ASCII and terminal escapes.
const std::vector<std::string> kHostileYaml = {
    R"(a\nmat_record x; int y = 1/0;)", R"(b\r#define sd_sphere(p, r) 0)", R"(c*/ x /*)", R"(d\\)",
    R"(e??/)",                          R"(f\0g)",                         R"(h\u00e9\u4e2d)", R"(i\e]0;T\a\e[2J)",
};

// One sphere per material, sphere i wearing uses[i] (names by default).
std::string scene_with_names(const std::vector<std::string>& names, std::vector<std::string> uses = {}) {
  if (uses.empty()) uses = names;
  std::string mats = "materials:\n", kids;
  for (size_t i = 0; i < names.size(); ++i) {
    mats += fmt::format("  \"{}\": {{color: [{}, 0.5, {}]}}\n", names[i], 0.1 * i, 1 - 0.1 * i);
    kids += fmt::format("    - {{sphere: {{radius: 0.4}}, translate: [{}, 0, 0], material: \"{}\"}}\n",
                        i * 1.0 - 3.5, uses[i]);
  }
  return "camera: {position: [0, -9, 2], target: [0, 0, 0], fov: 50}\n"
         "render: {width: 48, height: 16}\n"
         "lights:\n  - directional: {direction: [-0.4, 0.6, -0.7], shadows: soft}\n" +
         mats + "scene:\n  union:\n" + kids;
}

std::vector<std::string> plain_names(size_t n) {
  std::vector<std::string> v;
  for (size_t i = 0; i < n; ++i) v.push_back("m" + std::to_string(i));
  return v;
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Renders `scene` (a path) to a PNG in `dir`; returns its bytes.
std::string render(const ScratchDir& dir, const std::string& scene, const std::string& extra = "") {
  std::string out = dir.file("out.png");
  RunResult r = run_sdfc("render " + shell_quote(scene) + " -q -o " + shell_quote(out) + " " + extra);
  EXPECT_EQ(r.code, 0) << r.err;
  return r.code == 0 ? read_text(out) : std::string();
}

// Does `payload` occur in `src` other than after a `//` on its line?
bool outside_comments(const std::string& src, const std::string& payload) {
  for (size_t at = src.find(payload); at != std::string::npos; at = src.find(payload, at + 1)) {
    size_t line = src.rfind('\n', at);
    line = line == std::string::npos ? 0 : line + 1;
    if (src.substr(line, at - line).find("//") == std::string::npos) return true;
  }
  return false;
}

TEST(KernelText, EncodesEverythingButPlainPunctuation) {
  std::string all;
  for (int c = 0; c < 256; ++c) all += static_cast<char>(c);
  std::string s = codegen::kernel_text(all, 1000);
  for (char c : s) {
    EXPECT_GE(c, 0x20);
    EXPECT_LE(c, 0x7e);
    EXPECT_NE(c, '\\');
  }
  EXPECT_EQ(s.find("*/"), std::string::npos);
  EXPECT_EQ(s.find("?\?"), std::string::npos);
  EXPECT_EQ(codegen::kernel_text("bone_2 (floor)"), "bone_2 (floor)");
  EXPECT_EQ(codegen::kernel_text("a\nb"), "a%0Ab");
  EXPECT_EQ(codegen::kernel_text(std::string(500, 'x'), 10), "xxxxxxxxxx...");
}

TEST(KernelText, KernelsOfHostileNamesArePlainAscii) {
  for (const auto& name : kHostileYaml) {
    SCOPED_TRACE(name);
    ir::Module m = compile_text(scene_with_names({name, "plain"}), "x\n\r*/\\?\?/\x1b\xc3\xa9.yaml");
    std::string src = codegen::emit_opencl(m).source;
    EXPECT_TRUE(codegen::kernel_source_is_plain(src));
    EXPECT_FALSE(outside_comments(src, "1/0"));
    EXPECT_FALSE(outside_comments(src, "#define sd_sphere(p, r) 0"));
  }
}

// Expression text (animated values, displace) is parsed and written out
// again by sdfc: line breaks, tabs and spacing in it never reach the kernel.
TEST(KernelText, ExpressionsAreRewrittenNotCopied) {
  ir::Module m = compile_text(
      "scene: {sphere: {radius: \"0.4 +\\r\\n 0.1*sin(time)\\t\"}, displace: {expr: \"0.01*sin(\\n8*x)  \\r\"}}\n");
  std::string src = codegen::emit_opencl(m).source;
  EXPECT_TRUE(codegen::kernel_source_is_plain(src));
  EXPECT_NE(src.find("radius=\"(0.4 + (0.1 * sin(time)))\""), std::string::npos) << "the comment holds sdfc's own text";
  EXPECT_NE(src.find("// displace (0.01 * sin((8 * x)))"), std::string::npos);
  // A backslash or a comment in an expression is no expression.
  for (const char* bad : {"0.4 + 0.1*sin(time)\\\\", "0.4 // x"})
    EXPECT_THROW(compile_text(std::string("scene: {sphere: {radius: \"") + bad + "\"}}\n"), SceneError) << bad;
}

TEST(KernelText, HostileMaterialNamesRenderLikePlainOnes) {
  ScratchDir dir;
  std::string plain = render(dir, dir.write("plain.yaml", scene_with_names(plain_names(kHostileYaml.size()))));
  std::string hostile = render(dir, dir.write("hostile.yaml", scene_with_names(kHostileYaml)));
  ASSERT_FALSE(plain.empty());
  EXPECT_TRUE(hostile == plain) << "a hostile material name changed the image";
}

TEST(KernelText, HostileFileAndDirectoryNamesRenderLikePlainOnes) {
  ScratchDir dir;
  std::string text = scene_with_names(plain_names(3));
  std::string plain = render(dir, dir.write("plain.yaml", text));
  // Everything but NUL and '/' can be in a file name; the full path goes on
  // kernel line 1, the base name into every node comment.
  // A name holds no '/', so "*/" and "??/" come from directories ending in
  // "*" and "??"; the file name ends in a backslash.
  std::string evil = "d\nint y = *(int*)7;\r#define K(x) 0\n \x1b[2J \xc3\xa9 *";
  std::filesystem::create_directories(dir.file(evil) + "/?\?");
  std::string path = dir.file(evil) + "/?\?/" + evil + ".yaml\\";
  { std::ofstream(path) << text; }
  std::string hostile = render(dir, path);
  ASSERT_FALSE(plain.empty());
  EXPECT_TRUE(hostile == plain) << "a hostile file name changed the image";
}

TEST(KernelText, HostileSetValuesRenderLikeTheSameNameInTheFile) {
  ScratchDir dir;
  std::vector<std::string> names = {"m0", "m1", R"(x\n#define v3(a, b, c) 0 ??/)"};
  std::string direct = render(dir, dir.write("direct.yaml", scene_with_names(names)));
  std::string other = dir.write("other.yaml", scene_with_names(names, {"m0", "m1", "m0"}));
  std::string via_set =
      render(dir, other, "--set " + shell_quote("scene.union.2.material=\"" + names[2] + "\""));
  ASSERT_FALSE(direct.empty());
  EXPECT_TRUE(via_set == direct) << "a hostile --set value changed the image";
  EXPECT_FALSE(via_set == render(dir, other)) << "the override did nothing";
}

}  // namespace
}  // namespace sdfc::test
