// Functional coverage of the contract (docs/algorithm.md) in the
// co-simulation: which parts of it the engines actually exercised. Each
// bin is computed from what an engine did — its own output pulses, replayed
// in the move's frame against the rules of docs/algorithm.md (quadrant
// table Q, D, the tie and end-point rules), and its host-side events
// (EngineRun::events) — never from the case list. Only runs that passed
// (PASS or FLAGGED) count: a pulse the scoreboard refused proves nothing.
// Plain C++, no SystemC; it shares no code with the model it observes.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "cases.hpp"
#include "scoreboard.hpp"

namespace contour::cosim {

struct CoverageBin {
  std::string group;  // "arc direction", "arc rules", "line", "sequence", "host"
  std::string name;   // one line: what was exercised
  std::map<std::string, std::uint64_t> hits;  // per engine
  std::uint64_t total() const {
    std::uint64_t n = 0;
    for (const auto& [e, h] : hits) n += h;
    return n;
  }
};

class Coverage {
 public:
  Coverage();
  // Adds what `run` did on `c` (its row says whether it passed).
  void add(const Case& c, const Expected& exp, const EngineRun& run, const Row& row);
  const std::vector<CoverageBin>& bins() const { return bins_; }
  std::size_t hit() const;  // bins with at least one hit
  double percent() const;

 private:
  void count(std::size_t bin, const std::string& engine, std::uint64_t n = 1) { bins_[bin].hits[engine] += n; }
  void walk_arc(const Move& m, const std::vector<Pulse>& ps, bool complete, const std::string& engine);
  void walk_line(const Move& m, const std::vector<Pulse>& ps, const std::string& engine);
  std::vector<CoverageBin> bins_;
};

// Bin indices, in the order of Coverage::bins().
namespace bin {
// arc direction: 16 bins, index = kArcDir + q * 4 + cw * 2 + outward
inline constexpr std::size_t kArcDir = 0;
inline constexpr std::size_t kArcTie = 16, kArcEndOut = 17, kArcEndIn = 18;
inline constexpr std::size_t kArcK = 19;  // + k, 0..4
inline constexpr std::size_t kArcCrossOntoEnd = 24;
inline constexpr std::size_t kLineTie = 25, kLineEnd = 26;
inline constexpr std::size_t kLineSigns = 27;  // + (xe < 0) + 2 * (ye < 0)
inline constexpr std::size_t kBackToBack = 31, kOverrun = 32, kQueueFull = 33, kPushRefused = 34, kAbort = 35;
inline constexpr std::size_t kCount = 36;
}  // namespace bin

}  // namespace contour::cosim
