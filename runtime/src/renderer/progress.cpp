#include <sdfrt/progress.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <unistd.h>

namespace sdfrt {
namespace {

constexpr int kBarWidth = 30;
// Redrawing more often than this only costs terminal bandwidth.
constexpr auto kMinRedraw = std::chrono::milliseconds(50);

}  // namespace

ProgressBar::ProgressBar(std::string unit, Style style, std::FILE* out)
    : unit_(std::move(unit)),
      interactive_(style == Style::Interactive ||
                   (style == Style::Auto && ::isatty(::fileno(out)) == 1)),
      out_(out),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() { finish(); }

std::string ProgressBar::format_status(int done, int total, double elapsed_s) const {
  std::string eta = "--";
  if (done > 0 && total >= done) {
    eta = fmt::format("{:.1f}s", elapsed_s / done * (total - done));
  }
  return fmt::format("{}/{} {}  {:.1f}s elapsed  ETA {}", done, total, unit_, elapsed_s, eta);
}

void ProgressBar::update(int done, int total) {
  if (finished_ || total <= 0) return;
  done = std::clamp(done, 0, total);
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();

  if (interactive_) {
    if (drew_ && done != total && now - last_draw_ < kMinRedraw) return;
    const int filled = static_cast<int>(static_cast<long long>(kBarWidth) * done / total);
    // Trailing spaces wipe leftovers of a longer previous line.
    fmt::print(out_, "\r[{}{}] {}   ", std::string(static_cast<std::size_t>(filled), '#'),
               std::string(static_cast<std::size_t>(kBarWidth - filled), '.'),
               format_status(done, total, elapsed));
    std::fflush(out_);
    drew_ = true;
    last_draw_ = now;
    if (done == total) finish();
    return;
  }

  // Logs and pipes: one line whenever another tenth is done (the last at 100%).
  const int decile = static_cast<int>(10LL * done / total);
  if (decile > last_decile_) {
    fmt::print(out_, "{}\n", format_status(done, total, elapsed));
    std::fflush(out_);
    last_decile_ = decile;
  }
  if (done == total) finished_ = true;
}

void ProgressBar::finish() {
  if (finished_) return;
  finished_ = true;
  if (interactive_ && drew_) {
    std::fputc('\n', out_);
    std::fflush(out_);
  }
}

}  // namespace sdfrt
