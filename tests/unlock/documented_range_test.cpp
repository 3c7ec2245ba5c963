// A value unlocked without a range spans the range its kind's node reference
// documents (ParamDoc::range), and every documented number of every
// described kind's example unlocks that way: the docs and the readers agree.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "sdfc/kinds/param_range.hpp"
#include "sdfc/kinds/registry.hpp"
#include "sdfc/source/yaml_loader.hpp"
#include "sdfc/support/diagnostics.hpp"
#include "unlock_support.hpp"

namespace sdfc::test {
namespace {

using kinds::parse_doc_range;
using kinds::slider_range;

TEST(DocumentedRange, RangeTextsAreRead) {
  auto r = parse_doc_range("> 0, up to 100");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->lo, 0);
  EXPECT_TRUE(r->lo_open);
  EXPECT_EQ(r->hi, 100);
  EXPECT_FALSE(r->hi_open);
  auto box = parse_doc_range("-8 to 8, |scale| > 1");
  ASSERT_TRUE(box);
  EXPECT_EQ(box->lo, -8);
  EXPECT_EQ(box->hi, 8);
  EXPECT_EQ(box->abs_above, 1);
  auto each = parse_doc_range("each -10 to 10, not zero");
  ASSERT_TRUE(each);
  EXPECT_EQ(each->lo, -10);
  EXPECT_EQ(each->hi, 10);
  EXPECT_FALSE(parse_doc_range("less than fixed_radius"));
  EXPECT_FALSE(parse_doc_range(""));
}

TEST(DocumentedRange, SlidersStayInsideTheRange) {
  // x +- max(|x|, 1), an eighth short of an open end.
  auto [lo, hi] = slider_range(*parse_doc_range("> 0"), 1.5);
  EXPECT_DOUBLE_EQ(lo, 1.5 / 8);
  EXPECT_DOUBLE_EQ(hi, 3);
  std::tie(lo, hi) = slider_range(*parse_doc_range("> 0, up to 100"), 80);
  EXPECT_DOUBLE_EQ(hi, 100);
  // A Mandelbox scale keeps to its side of [-1, 1].
  std::tie(lo, hi) = slider_range(*parse_doc_range("-8 to 8, |scale| > 1"), -1.5);
  EXPECT_DOUBLE_EQ(lo, -3);
  EXPECT_LT(hi, -1);
  EXPECT_GT(hi, -1.5);
  std::tie(lo, hi) = slider_range(*parse_doc_range("-8 to 8, |scale| > 1"), 7);
  EXPECT_GT(lo, 1);
  EXPECT_DOUBLE_EQ(hi, 8);
}

TEST(DocumentedRange, UnlockWithoutARangeTakesTheDocumentedOne) {
  Unlocked u = compile_unlocked("scene:\n  mandelbox: {scale: 2, iterations: 10}\n", {"scene.mandelbox.scale"});
  ASSERT_EQ(u.slots.size(), 1u);
  EXPECT_TRUE(u.slots[0]->ranged);
  EXPECT_GT(u.slots[0]->lo, 1);  // the reader's |scale| > 1 holds over the whole slider
  EXPECT_DOUBLE_EQ(u.slots[0]->hi, 4);
  // A light has no node reference: the reader's own range.
  Unlocked light = compile_unlocked("scene: {sphere: {radius: 1}}\nlights: [{point: {position: [2, 2, 2], intensity: 3}}]\n",
                                    {"lights[0].point.intensity"});
  EXPECT_FALSE(light.slots[0]->ranged);
  EXPECT_EQ(light.slots[0]->hi, 6);  // x + max(|x|, 1)
}

// Each described kind's example, every number in its body that the node
// reference gives a range: unlocked with no range, the scene builds over
// the documented slider, or (when a clause the text states in words, such
// as "less than half the smallest side", refuses it) the value's own check
// says why at the value, and the panel's narrower range then works.
TEST(DocumentedRange, EveryDocumentedNumberOfEveryExampleUnlocks) {
  int documented = 0, narrowed = 0;
  for (const kinds::Description* d : kinds::all()) {
    const std::string yaml = "scene: " + std::string(d->example) + "\n";
    SourceValue doc = load_yaml_text(yaml, "unlock.yaml");
    const SourceValue* body = find_value(doc, "scene." + std::string(d->yaml));
    if (!body || !body->is_map()) continue;
    for (const auto& [key, v] : body->entries) {
      const kinds::ParamDoc* pd = kinds::documented_param({"scene", std::string(d->yaml), key.scalar});
      if (!pd || !parse_doc_range(pd->range)) continue;
      std::vector<std::string> paths;
      if (v.is_scalar()) paths.push_back(key.scalar);
      for (size_t i = 0; v.is_seq() && i < v.items.size(); ++i) paths.push_back(key.scalar + "." + std::to_string(i));
      for (const std::string& p : paths) {
        const std::string path = "scene." + std::string(d->yaml) + "." + p;
        const SourceValue* x = find_value(doc, path);
        if (!x || !x->is_scalar()) continue;
        SCOPED_TRACE(path);
        const double value = std::strtod(x->scalar.c_str(), nullptr);
        try {
          Unlocked u = compile_unlocked(yaml, {path});
          EXPECT_TRUE(u.slots[0]->ranged);
          EXPECT_LE(u.slots[0]->lo, value);
          EXPECT_GE(u.slots[0]->hi, value);
          ++documented;
        } catch (const SceneError& e) {
          const std::string what = e.what();
          if (what.find("cannot be unlocked") != std::string::npos) continue;  // it shapes the code
          EXPECT_NE(what.find("unlock.yaml:1:"), std::string::npos) << what;
          std::cout << path << ": documented range refused: " << what.substr(0, what.find('\n')) << "\n";
          const double lo = std::min(value * 0.75, value * 1.25), hi = std::max(value * 0.75, value * 1.25);
          try {
            compile_unlocked(yaml, {path + "=" + std::to_string(lo) + ":" + std::to_string(hi)});
            ++narrowed;
          } catch (const SceneError& n) {  // only a value that cannot move at run time at all (a Juliabulb's power)
            EXPECT_NE(std::string(n.what()).find("cannot be animated"), std::string::npos) << n.what();
          }
        }
      }
    }
  }
  std::cout << documented << " documented numbers unlock over their documented range, " << narrowed
            << " need the narrower one\n";
  EXPECT_GT(documented, 20);
  EXPECT_LT(narrowed, documented);
}

}  // namespace
}  // namespace sdfc::test
