// The `contour` CLI as a user sees it: paper examples, formats, errors.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run.hpp"

namespace contour::test {
namespace {

TEST(Cli, PaperFig2LineSixFive) {
  const ProcessResult o = contour("line 6 5 --format steps");
  EXPECT_EQ(o.status, 0);
  EXPECT_EQ(o.out, "+X +Y +X +Y +X +Y +X +Y +X +Y +X\n");
  EXPECT_EQ(o.err, "");
}

TEST(Cli, PaperFig5ArcCcw) {
  const ProcessResult o = contour("arc 6 0 0 6 --ccw --format steps");
  EXPECT_EQ(o.status, 0);
  EXPECT_EQ(o.out, "-X +Y +Y +Y +Y -X +Y -X +Y -X -X -X\n");
}

// `contour ARGS` exits 0 and prints every one of `parts`.
void expect_success_printing(const std::string& args, const std::vector<std::string>& parts) {
  const ProcessResult o = contour(args);
  EXPECT_EQ(o.status, 0) << args << ": " << o.err;
  for (const auto& part : parts) EXPECT_NE(o.out.find(part), std::string::npos) << part << " not in:\n" << o.out;
}

TEST(Cli, SummaryNamesPulsesEndAndDeviation) {
  expect_success_printing("arc 6 0 0 6 --ccw",
                          {"pulses:        12 (X 6, Y 6)", "end point:     (0, 6)", "max deviation: 1.0000"});
}

TEST(Cli, JsonCarriesPulsesAndFinalState) {
  expect_success_printing("line -3 2 --format json",
                          {"\"count\": 5", "\"pulses\": [\"-X\", \"+Y\", \"-X\", \"+Y\", \"-X\"]",
                           "\"x\": -3, \"y\": 2, \"d\": 0", "\"done\": true"});
}

TEST(Cli, SvgDrawsThePathAndTheIdealContour) {
  const std::string path = ::testing::TempDir() + "fig5.svg";
  const ProcessResult o = contour("arc 6 0 0 6 --ccw --format svg -o " + path);
  ASSERT_EQ(o.status, 0) << o.err;
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  EXPECT_EQ(s.str().rfind("<svg", 0), 0u);
  EXPECT_NE(s.str().find("pulse path"), std::string::npos);
  EXPECT_NE(s.str().find("ideal contour"), std::string::npos);
  // 13 path points: the start and one per pulse.
  const auto at = s.str().find("stroke=\"#d62728\"");
  ASSERT_NE(at, std::string::npos);
  const auto pts = s.str().find("points=\"", at);
  const auto end = s.str().find('"', pts + 8);
  int pairs = 0;
  for (auto i = pts; i < end; ++i) pairs += s.str()[i] == ',';
  EXPECT_EQ(pairs, 13);
}

struct BadInput {
  const char* args;
  const char* message;
};

class CliErrors : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliErrors, OneLineOnStderrAndExitTwo) {
  const ProcessResult o = contour(GetParam().args);
  EXPECT_EQ(o.status, 2) << GetParam().args;
  EXPECT_EQ(o.out, "");
  EXPECT_NE(o.err.find(GetParam().message), std::string::npos) << o.err;
  EXPECT_EQ(o.err.find('\n'), o.err.size() - 1) << "exactly one line: " << o.err;
}

INSTANTIATE_TEST_SUITE_P(
    Cli, CliErrors,
    ::testing::Values(BadInput{"line 16777216 0", "XE = 16777216 is out of range"},
                      BadInput{"line 1 -16777216", "YE = -16777216 is out of range"},
                      BadInput{"line six 5", "XE: 'six' is not an integer"},
                      BadInput{"line 1.5 5", "XE: '1.5' is not an integer"},
                      BadInput{"line 6", "missing argument YE"},
                      BadInput{"line 6 5 7", "unexpected argument '7'"},
                      BadInput{"line 6 5 --format xml", "unknown format 'xml'"},
                      BadInput{"line 6 5 --engine nope", "unknown engine 'nope'"},
                      BadInput{"line 6 5 --frobnicate", "unknown option '--frobnicate'"},
                      BadInput{"arc 0 0 0 0 --cw", "zero radius"},
                      BadInput{"arc 6 0 0 6", "exactly one of --cw and --ccw"},
                      BadInput{"arc 6 0 0 6 --cw --ccw", "exactly one of --cw and --ccw"},
                      BadInput{"arc 10 0 5 5 --ccw", "end point (5, 5) is not on the circle"},
                      BadInput{"arc 1 0 0 1 --ccw", "radius too small"},
                      BadInput{"arc 16777215 1 0 1 --ccw", "radius too large"},
                      BadInput{"arc 6 0 0 6 --ccw --format svg", "--format svg needs -o FILE"},
                      BadInput{"nosuchcommand", "unknown command 'nosuchcommand'"},
                      // One set of number rules (sim/cli/numbers.hpp): decimal, no spaces, no hex, no exponent.
                      BadInput{"line ' 5' 5", "XE: ' 5' is not an integer"},
                      BadInput{"line '5 ' 5", "XE: '5 ' is not an integer"},
                      BadInput{"line 0x10 5", "XE: '0x10' is not an integer"},
                      BadInput{"line 1e3 5", "XE: '1e3' is not an integer"},
                      BadInput{"line +5 5", "XE: '+5' is not an integer"},
                      BadInput{"line 5 5 -o", "option -o needs a value"},
                      BadInput{"line 5 5 --output", "option --output needs a value"},
                      BadInput{"line 5 5 --progress --no-progress", "at most one of --progress and --no-progress"},
                      BadInput{"arc 6 0 0 6 --ccw --format svg -o /nonexistent/x.svg",
                               "-o: cannot write '/nonexistent/x.svg'"},
                      BadInput{"line 6 5 -o /", "-o: cannot write '/'"},
                      BadInput{"sim85 /", "'/' is a directory, not a program file"},
                      BadInput{"sim85 /nonexistent/x.hex", "cannot open '/nonexistent/x.hex'"},
                      BadInput{"sim85 x.hex --max-tstates -1", "--max-tstates: '-1' must be 0 (no limit) or positive"},
                      BadInput{"cosim --suite paper --rate 1k,", "--rate '1k,': an empty item in the list"},
                      BadInput{"cosim --suite paper --rate ,1k", "--rate ',1k': an empty item in the list"},
                      BadInput{"cosim --suite paper --rate 0x10", "--rate '0x10' is not a rate"},
                      BadInput{"cosim --suite paper --rate 1e3", "--rate '1e3' is not a rate"},
                      BadInput{"cosim --suite paper --rate 4k --inject core:drop:-1",
                               "pulse number '-1' is not a positive integer"},
                      BadInput{"cosim --suite paper --rate 4k --step-len 0x10", "--step-len '0x10': expected clocks"},
                      BadInput{"cosim --suite paper --rate 4k --step-len 2.01us",
                               "--step-len '2.01us' is not a whole number of core clocks (20 ns)"},
                      BadInput{"cosim --suite paper --rate 4k --step-space 2ms", "--step-space '2ms': expected clocks"}),
    [](const ::testing::TestParamInfo<BadInput>& info) {
      // "line 16777216 0" -> "line_16777216_0"; the index keeps names unique.
      std::string name;
      for (const char* c = info.param.args; *c; ++c) name += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '_';
      return name + "_" + std::to_string(info.index);
    });

TEST(Cli, GcodeRealOptionsFollowTheNumberRules) {
  const ProcessResult o = contour("gcode " + std::string(CONTOUR_SOURCE_DIR) + "/docs/paper-b/fig2-3d-arc.ngc --accel 0x10");
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("--accel: '0x10' is not a number"), std::string::npos) << o.err;
}

TEST(Cli, HelpStatesTheNumberRules) {
  expect_success_printing("--help", {"Numbers are decimal", "No hex (0x10), no exponent (1e3)"});
  expect_success_printing("line --help", {"Numbers are decimal", "--progress"});
  expect_success_printing("sim85 --help", {"default 2000000000", "0: no limit"});
}

// The text of a file.
std::string read_text(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// Output timing in nanoseconds beside clocks: 2us and 1500ns are 100 and 75
// clocks of the core's 50 MHz, as the report's command line shows.
TEST(Cli, CosimStepTimingTakesDurations) {
  const std::string dir = ::testing::TempDir() + "cosim_ns";
  const ProcessResult o = contour("cosim --suite paper --rate 4k --engines model,core --step-len 2us --step-space 1500ns "
                                  "--no-progress --report " + dir);
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(read_text(dir + "/report.json").find("--step-len 100 --step-space 75 "), std::string::npos);
}

// A move of 8 000 000 pulses kept in memory takes hundreds of MB (48 bytes a
// step); streamed, a few MB whatever the length. 50 MB: the bound.
constexpr long kStreamRssLimitKb = 50 * 1024;

TEST(CliStreaming, LongLineInBoundedMemoryEveryFormat) {
  const std::string out = ::testing::TempDir() + "long.out", svg = ::testing::TempDir() + "long.svg";
  struct Case {
    std::string args, expect;  // `expect` ends the output
  };
  for (const Case& c : {Case{"--format steps -o " + out, "+X +Y +X +Y\n"},
                        Case{"--format json -o " + out,
                             "\"count\": 8000000, \"final\": {\"x\": 4000000, \"y\": 4000000, \"d\": 0, \"quadrant\": 0, "
                             "\"crossings\": 0, \"pulses\": 8000000, \"done\": true}, \"max_deviation\": 0.707107}\n"},
                        Case{"--format summary -o " + out, "pulses:        8000000 (X 4000000, Y 4000000)\n"
                                                           "  end point:     (4000000, 4000000)\n"
                                                           "  max deviation: 0.7071 pulses\n"},
                        Case{"--format svg -o " + svg, ""}}) {
    const ProcessResult o = contour("line 4000000 4000000 " + c.args);
    EXPECT_EQ(o.status, 0) << c.args << ": " << o.err;
    EXPECT_LT(o.max_rss_kb, kStreamRssLimitKb) << c.args;
    if (c.expect.empty()) continue;
    const std::string text = read_text(out);
    ASSERT_GE(text.size(), c.expect.size()) << c.args;
    EXPECT_EQ(text.substr(text.size() - c.expect.size()), c.expect) << c.args;
  }
  // The SVG's path is thinned to a few thousand points, end point kept.
  const std::string text = read_text(svg);
  EXPECT_LT(text.size(), 1u << 20);
  EXPECT_NE(text.find("4000000"), std::string::npos);
}

TEST(CliStreaming, ArcOnTheIssStreamsTheSameSteps) {
  const ProcessResult model = contour("arc 300 0 -300 0 --ccw --format steps");
  const ProcessResult iss = contour("arc 300 0 -300 0 --ccw --format steps --engine iss");
  EXPECT_EQ(iss.status, 0) << iss.err;
  EXPECT_EQ(iss.out, model.out);
  EXPECT_GT(model.out.size(), 1000u);
}

TEST(CliProgress, ForcedShowsPulsesOnStderrAndWipesTheLine) {
  const ProcessResult o = contour("line 20000 20000 --progress");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.err.find("line 20000 20000 [engine model]: "), std::string::npos) << o.err;
  EXPECT_NE(o.err.find(" of 40000 pulses ("), std::string::npos) << o.err;
  ASSERT_FALSE(o.err.empty());
  EXPECT_EQ(o.err.back(), '\r');
  EXPECT_EQ(o.err.find('\n'), std::string::npos);
}

// An arc's total is an estimate from the ideal arc: a full circle of radius
// R moves each axis 4R (geometry), exactly what the pulses add up to here.
TEST(CliProgress, ArcShowsAnEstimatedTotal) {
  const ProcessResult o = contour("arc 100000 0 100000 0 --ccw --progress");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.err.find(" of ~800000 pulses ("), std::string::npos) << o.err;
  EXPECT_NE(o.out.find("pulses:        800000 (X 400000, Y 400000)"), std::string::npos) << o.out;
}

TEST(CliProgress, OffWhenNotATerminalOrAskedOff) {
  EXPECT_EQ(contour("line 20000 20000").err, "");
  EXPECT_EQ(contour("line 20000 20000 --no-progress").err, "");
}

// Writes `bytes` to a file in the test's temporary folder; returns its path.
std::string write_binary(const std::string& name, const std::string& bytes) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(CliSim85, MaxTstatesZeroLiftsTheLimit) {
  const ProcessResult o = contour("sim85 " + write_binary("hlt.bin", "\x76") + " --max-tstates 0");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.out, "T-states: 5\n");
}

// MVI A,42h; OUT 10h; JMP 0004: the OUT is printed as it happens, before
// the run stops at its limit.
TEST(CliSim85, OutputIsWrittenAsTheProgramRuns) {
  const ProcessResult o = contour("sim85 " + write_binary("out_loop.bin", std::string("\x3E\x42\xD3\x10\xC3\x04\x00", 7)) +
                                  " --max-tstates 1000");
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.out, "OUT 10 42 T=7\n");
  EXPECT_NE(o.err.find("past the limit 1000"), std::string::npos) << o.err;
}

// OUT 10h; JMP 0100h as a CP/M program: 10 000 000 port writes in 2e8
// T-states, none printed and none kept (160 MB if each were logged).
TEST(CliSim85, CpmRunDoesNotGrowWithItsPortWrites) {
  const std::string bin = write_binary("cpm_out_loop.bin", std::string("\xD3\x10\xC3\x00\x01", 5));
  const ProcessResult o = contour("sim85 --cpm " + bin + " --max-tstates 200000000");
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.err.find("past the limit 200000000"), std::string::npos) << o.err;
  EXPECT_LT(o.max_rss_kb, kStreamRssLimitKb);
}

TEST(CliSim85, ForcedProgressCountsTStatesAgainstTheLimit) {
  const std::string bin = write_binary("jmp_progress.bin", std::string("\xC3\x00\x00", 3));
  const ProcessResult o = contour("sim85 " + bin + " --max-tstates 20000000 --progress");
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.err.find("sim85 " + bin + ": "), std::string::npos) << o.err;
  EXPECT_NE(o.err.find(" of 20000000 T-states ("), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("\rcontour sim85: "), std::string::npos) << "the progress line is wiped first: " << o.err;
}

// A program that never halts (JMP 0000) ends at the documented default
// limit (a few seconds on the ISS).
TEST(CliSim85, DefaultLimitEndsAProgramThatNeverHalts) {
  const ProcessResult o = contour("sim85 " + write_binary("jmp.bin", std::string("\xC3\x00\x00", 3)));
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.err.find("past the limit 2000000000"), std::string::npos) << o.err;
}

TEST(Cli, HelpListsCommandsAndEngines) {
  expect_success_printing("--help", {"line", "arc"});
  expect_success_printing("arc --help", {"--engine E", "model"});
}

// A waveform asked for that cannot be written is an error naming the file
// (it was silently ignored).
TEST(Cli, UnwritableWaveformIsAnError) {
  ::setenv("CONTOUR_FST", "/nonexistent-dir/x.fst", 1);
  const ProcessResult o = contour("line 6 5 --engine core");
  ::unsetenv("CONTOUR_FST");
  EXPECT_EQ(o.status, 2) << o.err;
  EXPECT_NE(o.err.find("cannot write the waveform file '/nonexistent-dir/x.fst'"), std::string::npos) << o.err;
  EXPECT_TRUE(o.out.empty()) << o.out;
}

}  // namespace

}  // namespace contour::test
