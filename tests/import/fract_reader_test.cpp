// The .fract reader: sections, locale decimals, hex colours, gradients,
// renamed keys of older versions, Mandelbulber's defaults, and broken files
// reported at their line and column.
#include <gtest/gtest.h>

#include "sdfc/fract/fract_file.hpp"
#include "sdfc/fract/fract_params.hpp"

namespace sdfc::fract {
namespace {

std::string file(const std::string& version, const std::string& main, const std::string& fractal1 = "") {
  return "# Mandelbulber settings file\n# version " + version + "\n# only modified parameters\n[main_parameters]\n" +
         main + "[fractal_1]\n" + fractal1 + "[fractal_2]\n";
}

// The first diagnostic of a file that must fail, as "line:col message".
std::string error_of(const std::string& text) {
  try {
    parse_text(text, "t.fract");
  } catch (const SceneError& e) {
    const Diagnostic& d = e.diagnostics().at(0);
    return std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + " " + d.message;
  }
  return "no error";
}

TEST(FractReader, SectionsVersionAndValues) {
  File f = parse_text(file("2.20", "camera 1 -2.5 3;\nN 12;\n", "mandelbox_scale -1,5;\n"), "t.fract");
  EXPECT_DOUBLE_EQ(f.version, 2.20);
  EXPECT_TRUE(f.only_modified);
  EXPECT_TRUE(f.fractal[0].present);
  EXPECT_TRUE(f.fractal[1].present);
  EXPECT_FALSE(f.fractal[2].present);
  Params main(f.main, false), f1(f.fractal[0], true);
  EXPECT_EQ(main.vec3("camera"), (Vec3{1, -2.5, 3}));
  EXPECT_EQ(main.integer("N"), 12);
  EXPECT_DOUBLE_EQ(f1.number("mandelbox_scale"), -1.5);  // a comma decimal, as a Polish locale saves it
  EXPECT_EQ(main.loc("N").line, 6);
  EXPECT_EQ(main.loc("N").column, 3);
}

TEST(FractReader, LocaleDecimalsInVectorsAndTables) {
  File f = parse_text(file("2.20", "camera 0,25 -1,5e-3 2;\n") + "[keyframes]\nframe;main_camera_x\n0;0,5\n1;1,25\n",
                      "t.fract");
  EXPECT_EQ(Params(f.main, false).vec3("camera"), (Vec3{0.25, -0.0015, 2}));
  ASSERT_EQ(f.keyframes.rows.size(), 2u);
  double v = 0;
  ASSERT_TRUE(parse_number(f.keyframes.rows[1][1], v));
  EXPECT_DOUBLE_EQ(v, 1.25);
  EXPECT_FALSE(parse_number("1,2,3", v));
  EXPECT_FALSE(parse_number("nan", v));
}

TEST(FractReader, SixteenBitHexColoursAndGradients) {
  File f = parse_text(file("2.20", "glow_color_1 ffff 8000 0;\nmat1_surface_color_gradient 0 ff0000 5000 00ff00 9000 0000ff;\n"),
                      "t.fract");
  Params main(f.main, false);
  Vec3 c = main.colour("glow_color_1");
  EXPECT_DOUBLE_EQ(c[0], 1.0);
  EXPECT_NEAR(c[1], 0x8000 / 65535.0, 1e-12);
  EXPECT_DOUBLE_EQ(c[2], 0.0);
  std::vector<GradientStop> g = main.gradient("mat1_surface_color_gradient");
  ASSERT_EQ(g.size(), 3u);
  EXPECT_DOUBLE_EQ(g[1].at, 0.5);
  EXPECT_EQ(g[1].color, (Vec3{0, 1, 0}));
  EXPECT_EQ(g[2].color, (Vec3{0, 0, 1}));
}

TEST(FractReader, DefaultsFillWhatOnlyModifiedFilesLeaveOut) {
  File f = parse_text(file("2.20", ""), "t.fract");
  Params main(f.main, false), f1(f.fractal[0], true);
  EXPECT_EQ(main.integer("formula_1"), 2);  // Mandelbulber's Mandelbulb
  EXPECT_EQ(main.integer("formula_5"), 0);  // a numbered family's default
  EXPECT_EQ(main.integer("N"), 250);
  EXPECT_EQ(main.vec3("camera"), (Vec3{3, -6, 2}));
  EXPECT_EQ(main.vec3("aux_light_position_3"), (Vec3{-3, 3, -1}));  // differs per index
  EXPECT_DOUBLE_EQ(f1.number("mandelbox_folding_min_radius"), 0.5);
  EXPECT_DOUBLE_EQ(f1.number("power"), 9);
  EXPECT_FALSE(main.given("N"));
  EXPECT_THROW(main.number("a_key_the_importer_never_reads"), std::logic_error);
}

TEST(FractReader, RenamedKeysOfOlderAndNewerVersions) {
  // Before 2.19 the surface colours were a palette of evenly spaced colours.
  File old = parse_text(file("2.05", "surface_color_palette 717171 503f1e 554b46 ;\nreflect 0,5;\nspecular 2;\n"), "t.fract");
  Params o(old.main, false);
  ASSERT_TRUE(o.given("mat1_surface_color_gradient"));
  std::vector<GradientStop> g = o.gradient("mat1_surface_color_gradient");
  ASSERT_EQ(g.size(), 3u);
  EXPECT_NEAR(g[1].at, 0.3333, 1e-9);
  EXPECT_TRUE(o.given("mat1_specular"));
  // 2.25 renamed the lights; they are read under 2.20's names.
  File newer = parse_text(file("2.25", "light1_alpha 30;\nlight1_cast_shadows false;\nlight3_position 1 2 3;\n"), "t.fract");
  Params n(newer.main, false);
  EXPECT_DOUBLE_EQ(n.number("main_light_alpha"), 30);
  EXPECT_FALSE(n.boolean("shadows_enabled"));
  EXPECT_EQ(n.vec3("aux_light_position_2"), (Vec3{1, 2, 3}));
  EXPECT_EQ(current_key_name("main_light_alpha", 2.20), "main_light_alpha");
}

TEST(FractReader, BrokenFilesAtTheirLineAndColumn) {
  EXPECT_EQ(error_of("camera 1 2 3;\n"), "1:1 not a Mandelbulber settings file: the first line must be '# Mandelbulber settings file'");
  EXPECT_EQ(error_of(file("2.20", "camera 1 2 3\n")).substr(0, 4), "5:13");  // no ';'
  EXPECT_NE(error_of(file("2.20", "N 3;\nN 4;\n")).find("6:1 'N' is given twice"), std::string::npos);
  EXPECT_NE(error_of(file("2.20", "") + "[fractal_10]\n").find("7:2 unknown section [fractal_10]"), std::string::npos);
  EXPECT_NE(error_of("# Mandelbulber settings file\n# version abc\n[main_parameters]\n").find("2:1 expected a version"),
            std::string::npos);
  EXPECT_NE(error_of(file("2.20", "") + "[frames]\nframe;main_camera_x\n0;1;2\n").find("9:1 this row of [frames] has 3"),
            std::string::npos);
  EXPECT_NE(error_of("Mandelbulber 1.21;\nformula 2;\n").find("Mandelbulber 1.x"), std::string::npos);
  // A value that does not parse fails where it is read, at its place.
  File f = parse_text(file("2.20", "N twelve;\ncamera 1 2;\nglow_color_1 fffff 0 0;\n"), "t.fract");
  Params main(f.main, false);
  try {
    main.integer("N");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.diagnostics()[0].loc.line, 5);
    EXPECT_EQ(e.diagnostics()[0].loc.column, 3);
    EXPECT_NE(e.diagnostics()[0].message.find("'N' expects a number, got 'twelve'"), std::string::npos);
  }
  EXPECT_THROW(main.vec3("camera"), SceneError);
  EXPECT_THROW(main.colour("glow_color_1"), SceneError);  // five hex digits: not a 16-bit channel
}

}  // namespace
}  // namespace sdfc::fract
