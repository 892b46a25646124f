#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace contour::cli {

ProgressMode progress_wanted(const Args& a) {
  if (a.flag("progress") && a.flag("no-progress")) throw UsageError("give at most one of --progress and --no-progress");
  if (a.flag("progress")) return ProgressMode::Forced;
  if (a.flag("no-progress")) return ProgressMode::Off;
  return ::isatty(2) ? ProgressMode::Terminal : ProgressMode::Off;
}

Progress::Progress(ProgressMode mode, std::string what, std::string unit)
    : enabled_(mode != ProgressMode::Off),
      delay_(mode == ProgressMode::Forced ? std::chrono::steady_clock::duration{} : std::chrono::seconds(1)),
      what_(std::move(what)), unit_(std::move(unit)), start_(std::chrono::steady_clock::now()),
      last_(start_ - std::chrono::seconds(1)) {}

Progress::~Progress() { finish(); }

void Progress::show(std::uint64_t done, std::uint64_t total) {
  using namespace std::chrono;
  const auto now = steady_clock::now();
  if (now - start_ < delay_ || now - last_ < milliseconds(250)) return;
  last_ = now;
  char line[256];
  const double s = duration<double>(now - start_).count();
  int n;
  if (total)
    n = std::snprintf(line, sizeof line, "%s: %llu of %s%llu %s (%.1f%%), %.0f s", what_.c_str(),
                      static_cast<unsigned long long>(done), estimate_ ? "~" : "",
                      static_cast<unsigned long long>(total), unit_.c_str(),
                      100.0 * static_cast<double>(done) / static_cast<double>(total), s);
  else
    n = std::snprintf(line, sizeof line, "%s: %llu %s, %.0f s", what_.c_str(), static_cast<unsigned long long>(done),
                      unit_.c_str(), s);
  const std::size_t len = n < 0 ? 0 : std::min<std::size_t>(static_cast<std::size_t>(n), sizeof line - 1);
  std::fprintf(stderr, "\r%s%*s", line, static_cast<int>(shown_ > len ? shown_ - len : 0), "");
  std::fflush(stderr);
  shown_ = std::max(shown_, len);
}

void Progress::finish() {
  if (!shown_) return;
  std::fprintf(stderr, "\r%*s\r", static_cast<int>(shown_), "");
  std::fflush(stderr);
  shown_ = 0;
}

}  // namespace contour::cli
