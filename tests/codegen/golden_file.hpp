#pragma once
// Text compared with a file under tests/golden/. After an intended change,
// regenerate the files with
//   SDFC_UPDATE_GOLDEN=1 ctest -R Golden
// and review the diff like any other change.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>

#include "test_files.hpp"

namespace sdfc::test {

// "line N: golden ... actual ..." for the first line that differs, "" if none.
inline std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream sa(a), sb(b);
  std::string la, lb;
  for (int line = 1;; ++line) {
    bool ea = !std::getline(sa, la), eb = !std::getline(sb, lb);
    if (ea && eb) return "";
    if (ea || eb || la != lb)
      return "line " + std::to_string(line) + ":\n  golden: " + (ea ? "<end>" : la) + "\n  actual: " + (eb ? "<end>" : lb);
  }
}

// Expects `text` to equal tests/golden/NAME (or writes it there under SDFC_UPDATE_GOLDEN=1).
inline void expect_golden(const std::string& text, const std::string& name) {
  std::filesystem::path path = std::filesystem::path(SDFC_SOURCE_DIR) / "tests/golden" / name;
  if (const char* u = std::getenv("SDFC_UPDATE_GOLDEN"); u && std::string(u) == "1") {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path) << text;
    GTEST_SKIP() << "updated " << path;
  }
  std::string golden = std::filesystem::exists(path) ? read_text_file(path) : "";
  ASSERT_FALSE(golden.empty()) << "missing " << path << " (run with SDFC_UPDATE_GOLDEN=1)";
  EXPECT_TRUE(text == golden) << name << " differs at " << first_difference(golden, text);
}

// The kernel's sections (each starts with a "// ---- title" line; the
// lines before the first belong to none) whose title starts with one of
// `titles`, or (keep = false) all the others.
inline std::string kernel_sections(const std::string& kernel, std::initializer_list<const char*> titles, bool keep) {
  std::istringstream in(kernel);
  std::string line, out;
  bool named = false;
  while (std::getline(in, line)) {
    if (line.rfind("// ---- ", 0) == 0) {
      named = false;
      for (const char* t : titles) named = named || line.rfind(t, 0) == 0;
    }
    if (named == keep) out += line + "\n";
  }
  return out;
}

// The titles of the sections that hold the scene's own functions.
inline std::initializer_list<const char*> scene_section_titles() {
  static const std::initializer_list<const char*> titles = {
      "// ---- scene", "// ---- orbit trap of the nearest fractal", "// ---- iteration count of the nearest fractal",
      "// ---- the scene's exact gradient"};
  return titles;
}

}  // namespace sdfc::test
