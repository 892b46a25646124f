// Progress of long work on stderr: one line rewritten in place ("\r"), at
// most four times a second, wiped when the work ends. By default it shows
// when stderr is a terminal, once the work has taken a second; `--progress`
// shows it from the start whatever stderr is, `--no-progress` never.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "args.hpp"

namespace contour::cli {

enum class ProgressMode : std::uint8_t { Off, Terminal, Forced };

// --progress (Forced) / --no-progress (Off), both: a UsageError; neither:
// Terminal when stderr is one, else Off.
ProgressMode progress_wanted(const Args& a);

class Progress {
 public:
  // `what` starts the line ("line 6 5 [engine iss]"); `unit` names the count.
  Progress(ProgressMode mode, std::string what, std::string unit);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // `done` of `total` units (total 0: unknown). Cheap: looks at the clock
  // once every 4096 calls.
  void update(std::uint64_t done, std::uint64_t total) {
    if (enabled_ && (++calls_ & 4095) == 0) show(done, total);
  }
  // The totals passed to update() are estimates (shown as "~N").
  void totals_are_estimates() { estimate_ = true; }
  // Wipes the line (also done by the destructor).
  void finish();

 private:
  void show(std::uint64_t done, std::uint64_t total);

  bool enabled_;
  bool estimate_ = false;
  std::chrono::steady_clock::duration delay_;  // nothing shown before
  std::string what_, unit_;
  std::uint64_t calls_ = 0;
  std::size_t shown_ = 0;  // length of the line on screen
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace contour::cli
