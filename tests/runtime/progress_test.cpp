#include <sdfrt/progress.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace sdfrt {
namespace {

// Captures what a ProgressBar prints through a real FILE*.
class Capture {
 public:
  Capture() : file_(std::tmpfile()) {}
  ~Capture() { std::fclose(file_); }
  std::FILE* file() { return file_; }
  std::string text() {
    std::fflush(file_);
    std::rewind(file_);
    std::string out;
    for (int c; (c = std::fgetc(file_)) != EOF;) out += static_cast<char>(c);
    return out;
  }

 private:
  std::FILE* file_;
};

TEST(ProgressBar, LinesModePrintsAtMostOneLinePerTenth) {
  Capture capture;
  {
    ProgressBar bar("tiles", ProgressBar::Style::Lines, capture.file());
    bar.update(0, 48);
    for (int i = 1; i <= 48; ++i) bar.update(i, 48);
  }
  const std::string text = capture.text();
  const auto lines = std::count(text.begin(), text.end(), '\n');
  EXPECT_GE(lines, 9);
  EXPECT_LE(lines, 10);
  EXPECT_EQ(text.find('\r'), std::string::npos);
  EXPECT_NE(text.find("48/48 tiles"), std::string::npos) << text;
  EXPECT_NE(text.find("elapsed  ETA"), std::string::npos) << text;
}

TEST(ProgressBar, AutoOnAFileIsLinesMode) {
  Capture capture;
  {
    ProgressBar bar("tiles", ProgressBar::Style::Auto, capture.file());
    bar.update(1, 2);
    bar.update(2, 2);
  }
  EXPECT_EQ(capture.text().find('\r'), std::string::npos);
}

TEST(ProgressBar, InteractiveRedrawsOneLineAndEndsWithNewline) {
  Capture capture;
  {
    ProgressBar bar("tiles", ProgressBar::Style::Interactive, capture.file());
    auto callback = bar.callback();
    callback(0, 48);
    callback(12, 48);
    callback(48, 48);
  }
  const std::string text = capture.text();
  EXPECT_EQ(text.rfind("\r[", 0), 0u) << text;
  EXPECT_NE(text.find("] 48/48 tiles"), std::string::npos) << text;
  EXPECT_NE(text.find("[" + std::string(30, '#') + "]"), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1);
  EXPECT_EQ(text.back(), '\n');
}

TEST(ProgressBar, UnfinishedInteractiveBarStillEndsTheLine) {
  Capture capture;
  {
    ProgressBar bar("tiles", ProgressBar::Style::Interactive, capture.file());
    bar.update(3, 10);  // e.g. cancelled here
  }
  const std::string text = capture.text();
  EXPECT_NE(text.find("[#########.....................] 3/10 tiles"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
}

}  // namespace
}  // namespace sdfrt
