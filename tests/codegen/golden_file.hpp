#pragma once
// Text compared with a file under tests/golden/. After an intended change,
// regenerate the files with
//   SDFC_UPDATE_GOLDEN=1 ctest -R Golden
// and review the diff like any other change.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
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

}  // namespace sdfc::test
