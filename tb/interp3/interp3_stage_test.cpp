// The chord stage on the Verilog core (interp3_stage.hpp) against the
// model's stage 2 (planner::two_stage_model): the same timed pulses, in
// the same order, for paper B's programs planned by the planner and for
// random chords; the same refusal for a chord beyond 24 bits.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "gcode/gcode.hpp"
#include "interp/types.hpp"
#include "interp3_stage.hpp"
#include "planner/planner.hpp"
#include "planner/two_stage.hpp"

namespace contour::rtl3 {
namespace {

using planner::StepChord;
using planner::TimedPulse;

// The core's stage on the planner's chords (the conversion the engine
// binding in sim/cli does).
std::vector<TimedPulse> core_stage(const std::vector<StepChord>& chords, double cycle_s) {
  std::vector<Chord> plain;
  for (const StepChord& c : chords) plain.push_back({c.dx, c.dy, c.dz});
  std::vector<TimedPulse> out;
  for (const TimedStep& s : run_chords(plain, cycle_s)) out.push_back({s.t, s.pulse});
  return out;
}

// Empty when equal; else the first difference with its neighbours.
std::string first_difference(const std::vector<TimedPulse>& model, const std::vector<TimedPulse>& rtl) {
  const std::size_t n = std::min(model.size(), rtl.size());
  std::size_t k = 0;
  while (k < n && model[k] == rtl[k]) ++k;
  if (k == n && model.size() == rtl.size()) return "";
  std::ostringstream o;
  o << "model " << model.size() << " pulses, rtl " << rtl.size() << "; first difference at pulse " << k << "\n";
  for (std::size_t i = k >= 3 ? k - 3 : 0; i < k + 3 && (i < model.size() || i < rtl.size()); ++i) {
    o << (i == k ? "> " : "  ") << i << "  model ";
    if (i < model.size()) o << model[i].t << " " << to_string(model[i].pulse);
    else o << "--";
    o << "   rtl ";
    if (i < rtl.size()) o << rtl[i].t << " " << to_string(rtl[i].pulse);
    else o << "--";
    o << "\n";
  }
  return o.str();
}

std::vector<StepChord> chords_of(const std::string& program, double steps_per_mm) {
  const auto blocks = gcode::parse(program);
  planner::Config c;
  const planner::Plan plan = planner::plan(blocks, c);
  return planner::chords_in_steps(planner::interpolate(plan), steps_per_mm);
}

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream b;
  b << in.rdbuf();
  return b.str();
}

TEST(Interp3Stage, PaperBProgramsGiveTheModelsPulses) {
  const std::string src = CONTOUR_SOURCE_DIR;
  for (const char* file : {"/docs/paper-b/fig2-3d-arc.ngc", "/docs/paper-b/circle.ngc"}) {
    const std::string text = read(src + file);
    ASSERT_FALSE(text.empty()) << file;
    const auto chords = chords_of(text, 1000);
    const auto model = planner::two_stage_model(chords, 1e-3);
    const auto rtl = core_stage(chords, 1e-3);
    ASSERT_GT(model.size(), 100000u) << file;  // 2.46 s at up to 100 mm/s, 1000 steps/mm
    EXPECT_EQ(first_difference(model, rtl), "") << file;
    std::printf("%s: %zu chords, %zu pulses, identical\n", file, chords.size(), rtl.size());
  }
}

TEST(Interp3Stage, RandomChordsGiveTheModelsPulses) {
  std::mt19937_64 rng(1982);
  std::vector<StepChord> chords;
  for (int i = 0; i < 2000; ++i) {
    auto v = [&] {
      const int k = static_cast<int>(rng() % 12);
      const auto m = static_cast<std::int64_t>(rng() % (std::uint64_t{1} << k));
      return (rng() & 1) ? -m : m;
    };
    chords.push_back({v(), v(), v()});
  }
  chords.push_back({0, 0, 0});
  chords.push_back({(1 << 20) + 3, -1, 7});
  const auto model = planner::two_stage_model(chords, 2e-3);
  const auto rtl = core_stage(chords, 2e-3);
  EXPECT_EQ(first_difference(model, rtl), "");
}

TEST(Interp3Stage, ChordBeyond24BitsIsRefusedLikeTheModel) {
  const std::vector<StepChord> chords = {{5, 5, 5}, {0, -(1 << 24), 0}};
  std::string model_msg, rtl_msg;
  try {
    planner::two_stage_model(chords, 1e-3);
  } catch (const InputError& e) {
    model_msg = e.what();
  }
  try {
    core_stage(chords, 1e-3);
  } catch (const InputError& e) {
    rtl_msg = e.what();
  }
  EXPECT_EQ(rtl_msg, "YE = -16777216 is out of range: |YE| must be <= 2^24 - 1 = 16777215");
  EXPECT_EQ(rtl_msg, model_msg);
}

}  // namespace
}  // namespace contour::rtl3
