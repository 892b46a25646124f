// The `contour` CLI as a user sees it: paper examples, formats, errors.
#include <gtest/gtest.h>

#include <cctype>
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
                      BadInput{"nosuchcommand", "unknown command 'nosuchcommand'"}),
    [](const ::testing::TestParamInfo<BadInput>& info) {
      // "line 16777216 0" -> "line_16777216_0"; the index keeps names unique.
      std::string name;
      for (const char* c = info.param.args; *c; ++c) name += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '_';
      return name + "_" + std::to_string(info.index);
    });

TEST(Cli, HelpListsCommandsAndEngines) {
  expect_success_printing("--help", {"line", "arc"});
  expect_success_printing("arc --help", {"--engine E", "model"});
}

}  // namespace
}  // namespace contour::test
