// Tests of the co-simulation: the scoreboard's rules on hand-made streams,
// then whole SystemC runs (a reduced sweep, injected faults, the gated core
// clock against a free-running one). Each SystemC run happens in a forked
// child, because SystemC elaborates once per process; the child sends its
// rows back through a pipe.
//
// Expected pulses come from paper A, not from the model: Fig. 2 (line to
// (6, 5)) is +X +Y +X +Y +X +Y +X +Y +X +Y +X, Fig. 5 (arc (6, 0) to (0, 6)
// CCW) is -X +Y +Y +Y +Y -X +Y -X +Y -X -X -X.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cases.hpp"
#include "coverage.hpp"
#include "options.hpp"
#include "report.hpp"
#include "scoreboard.hpp"
#include "top.hpp"

// SystemC's main() calls sc_main; the tests are the program.
static const int kNoBanner = ::setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);

int sc_main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}

namespace contour::cosim {

// gtest prints a Verdict as its word.
void PrintTo(Verdict v, std::ostream* os) { *os << to_string(v); }

namespace {

const char* kFig2 = "+X +Y +X +Y +X +Y +X +Y +X +Y +X";
const char* kFig5 = "-X +Y +Y +Y +Y -X +Y -X +Y -X -X -X";

std::vector<Pulse> pulses(const std::string& text) {
  std::vector<Pulse> out;
  std::istringstream in(text);
  std::string t;
  while (in >> t) out.push_back(Pulse{t[1] == 'X' ? Axis::X : Axis::Y, static_cast<std::int8_t>(t[0] == '-' ? -1 : 1)});
  return out;
}

Case fig2() { return suite("paper").cases.at(0); }
Case fig5() { return suite("paper").cases.at(1); }

// An engine run that put out `ps`, one every 10 us, with `overruns` flagged.
EngineRun run_of(const std::string& engine, const std::vector<Pulse>& ps, std::int64_t overruns) {
  EngineRun r;
  r.engine = engine;
  for (std::size_t i = 0; i < ps.size(); ++i) r.out.push_back({10.0 * double(i + 1) + 1, ps[i], ""});
  r.overruns_known = true;
  r.overruns = overruns;
  return r;
}

std::vector<double> commands(std::size_t n) {
  std::vector<double> t;
  for (std::size_t i = 0; i < n; ++i) t.push_back(10.0 * double(i + 1));
  return t;
}

TEST(Scoreboard, TheSuitesPaperCasesAreThePapersFigures) {
  EXPECT_EQ(expect(fig2()).pulses, pulses(kFig2));
  EXPECT_EQ(expect(fig5()).pulses, pulses(kFig5));
}

TEST(Scoreboard, IdenticalStreamPasses) {
  const auto exp = expect(fig2());
  const Row r = judge(fig2(), exp, 4e3, commands(11), run_of("iss", pulses(kFig2), 0));
  EXPECT_EQ(r.verdict, Verdict::Pass) << r.note;
  EXPECT_EQ(r.lost, 0u);
  EXPECT_TRUE(r.latency_exact);
  EXPECT_NEAR(r.lat_min_us, 1.0, 1e-9);
}

TEST(Scoreboard, DroppedPulseIsTheFirstDivergence) {
  auto ps = pulses(kFig2);
  ps.erase(ps.begin() + 6);  // pulse 7 (+X) missing: the engine's 7th is +Y
  const Row r = judge(fig2(), expect(fig2()), 4e3, commands(11), run_of("core", ps, 1));
  EXPECT_EQ(r.verdict, Verdict::Fail);
  ASSERT_TRUE(r.divergence);
  EXPECT_EQ(r.divergence->index, 7u);
  EXPECT_EQ(r.divergence->summary, "pulse 7: model +X, core +Y");
  EXPECT_NE(r.divergence->context.find("> #7"), std::string::npos) << r.divergence->context;
}

TEST(Scoreboard, SwappedPulsesAreCaught) {
  auto ps = pulses(kFig5);
  std::swap(ps[4], ps[5]);  // +Y -X becomes -X +Y at pulses 5, 6
  const Row r = judge(fig5(), expect(fig5()), 1e3, commands(12), run_of("cpu", ps, 0));
  EXPECT_EQ(r.verdict, Verdict::Fail);
  ASSERT_TRUE(r.divergence);
  EXPECT_EQ(r.divergence->summary, "pulse 5: model +Y, cpu -X");
  EXPECT_EQ(r.mismatches, 2u);
}

TEST(Scoreboard, ExtraPulseIsAMismatch) {
  auto ps = pulses(kFig2);
  ps.push_back(Pulse{Axis::X, 1});
  const Row r = judge(fig2(), expect(fig2()), 1e3, commands(11), run_of("iss", ps, 0));
  EXPECT_EQ(r.verdict, Verdict::Fail);
  ASSERT_TRUE(r.divergence);
  EXPECT_EQ(r.divergence->index, 12u);
}

TEST(Scoreboard, LossesFlaggedOneForOneAreFlaggedNotFailed) {
  auto ps = pulses(kFig2);
  ps.resize(8);  // a prefix: 3 command pulses gave nothing
  const Row ok = judge(fig2(), expect(fig2()), 50e3, commands(11), run_of("cpu", ps, 3));
  EXPECT_EQ(ok.verdict, Verdict::Flagged) << ok.note;
  EXPECT_EQ(ok.lost, 3u);
  const Row under = judge(fig2(), expect(fig2()), 50e3, commands(11), run_of("cpu", ps, 2));
  EXPECT_EQ(under.verdict, Verdict::Fail);
  const Row over = judge(fig2(), expect(fig2()), 50e3, commands(11), run_of("cpu", pulses(kFig2), 1));
  EXPECT_EQ(over.verdict, Verdict::Fail);
}

TEST(Scoreboard, TheCoreMayNotLoseUpTo250kppsEvenIfFlagged) {
  auto ps = pulses(kFig2);
  ps.resize(10);
  EXPECT_EQ(judge(fig2(), expect(fig2()), 250e3, commands(11), run_of("core", ps, 1)).verdict, Verdict::Fail);
  EXPECT_EQ(judge(fig2(), expect(fig2()), 500e3, commands(11), run_of("core", ps, 1)).verdict, Verdict::Flagged);
  EXPECT_EQ(judge(fig2(), expect(fig2()), 1e3, commands(11), run_of("iss", ps, 1)).verdict, Verdict::Fail);
}

// The keep-up rule follows the programmed output stage: at STEP_LEN =
// STEP_SPACE = 4095 clocks (the registers' largest) the core carries
// 50M / 8210 = 6090 pps, so a flagged loss at 20 kpps is FLAGGED, not
// FAIL; at 5 kpps it must keep up.
TEST(Scoreboard, TheCoreKeepsUpOnlyToWhatItsOutputStageCarries) {
  auto ps = pulses(kFig2);
  ps.resize(6);
  const double carry = core_carry_rate(50e6, 4095, 4095, 10, 10);
  EXPECT_NEAR(carry, 6090.1, 0.1);
  EXPECT_EQ(judge(fig2(), expect(fig2()), 20e3, commands(11), run_of("core", ps, 5), carry).verdict, Verdict::Flagged);
  EXPECT_EQ(judge(fig2(), expect(fig2()), 5e3, commands(11), run_of("core", ps, 5), carry).verdict, Verdict::Fail);
  EXPECT_EQ(keep_up_rate("core", kDefaultCoreCarry), 250e3);
}

TEST(Scoreboard, EachEngineHasAStatedCommandRateLimit) {
  EXPECT_EQ(max_rate("core", 50e6), 25e6);  // the pin, sampled at 50 MHz
  EXPECT_EQ(max_rate("iss", 50e6), 250e3);
  EXPECT_EQ(max_rate("cpu", 50e6), 250e3);
  EXPECT_EQ(max_rate("model", 50e6), 50e6);
  const Row r = not_run(fig2(), expect(fig2()), "iss", 1e6, 250e3);
  EXPECT_EQ(r.verdict, Verdict::NotRun);
  EXPECT_FALSE(r.acceptable());
  EXPECT_FALSE(r.ran());
  std::vector<Row> rows(2);
  rows[0].verdict = Verdict::Pass;
  rows[1] = r;
  EXPECT_EQ(verdict_line(rows), "100.00% PASS 1 PASSED, 0 FAILED, 1 NOT RUN");
}

// A swap loses nothing: the limit table must not call it a loss.
TEST(Scoreboard, AMismatchIsNotALoss) {
  auto ps = pulses(kFig2);
  std::swap(ps[2], ps[3]);
  std::vector<Row> rows = {judge(fig2(), expect(fig2()), 1e3, commands(11), run_of("core", ps, 0))};
  const Limit l = limit_of(rows, "fig2", "core");
  EXPECT_EQ(l.first_loss, 0.0);
  EXPECT_EQ(l.first_mismatch, 1e3);
  EXPECT_EQ(l.agree_up_to, 0.0);
}

// The report draws a case in its first move's frame: Fig. 5 from (6, 0) to
// (0, 6) as in paper A (it once started at (0, 0) and ended at (-6, 6)).
TEST(Report, PathsAreDrawnInTheMovesOwnFrame) {
  const auto p5 = drawn_pulse_path(fig5(), expect(fig5()));
  ASSERT_EQ(p5.size(), 13u);
  EXPECT_EQ(p5.front(), (std::pair<double, double>{6, 0}));
  EXPECT_EQ(p5.back(), (std::pair<double, double>{0, 6}));
  const auto p2 = drawn_pulse_path(fig2(), expect(fig2()));
  EXPECT_EQ(p2.front(), (std::pair<double, double>{0, 0}));
  EXPECT_EQ(p2.back(), (std::pair<double, double>{6, 5}));
}

// Coverage from an engine's pulses, checked against paper A's Fig. 5
// (-X +Y +Y +Y +Y -X +Y -X +Y -X -X -X, D before the pulses 0, -11, -10,
// -7, -2, 5, -4, 5, -2, 9, 4, 1): all in Q1 CCW, 6 inward (-X) and 6
// outward, one D = 0 tie (the first pulse), no end-point rule, one
// crossing, landing on the end (0, 6).
TEST(Coverage, PaperFig5HitsItsBins) {
  Coverage cov;
  const auto exp = expect(fig5());
  const auto run = run_of("cpu", pulses(kFig5), 0);
  cov.add(fig5(), exp, run, judge(fig5(), exp, 1e3, commands(12), run));
  const auto& b = cov.bins();
  auto hits = [&](std::size_t i) { return b[i].total(); };
  EXPECT_EQ(hits(bin::kArcDir + 0 * 4 + 0 * 2 + 0), 6u);  // Q1 CCW inward
  EXPECT_EQ(hits(bin::kArcDir + 0 * 4 + 0 * 2 + 1), 6u);  // Q1 CCW outward
  EXPECT_EQ(hits(bin::kArcTie), 1u);
  EXPECT_EQ(hits(bin::kArcEndOut) + hits(bin::kArcEndIn), 0u);
  EXPECT_EQ(hits(bin::kArcK + 1), 1u);
  EXPECT_EQ(hits(bin::kArcCrossOntoEnd), 1u);
  EXPECT_EQ(cov.hit(), 5u);
  EXPECT_EQ(b[bin::kArcTie].hits.at("cpu"), 1u);
  // A failed run counts nothing.
  Coverage none;
  auto bad = pulses(kFig5);
  std::swap(bad[0], bad[1]);
  const auto bad_run = run_of("cpu", bad, 0);
  none.add(fig5(), exp, bad_run, judge(fig5(), exp, 1e3, commands(12), bad_run));
  EXPECT_EQ(none.hit(), 0u);
  EXPECT_EQ(none.percent(), 0.0);
}

// The end-point rule, from the contract's own reasoning: on (10, 0) to
// (8, 7) CCW the walk reaches x = 8 with D >= 0 and must go outward; on
// (10, 0) to (3, 9) it reaches y = 9 with D < 0 and must go inward. Fig. 2
// (a line) ties at D = 0 on its first pulse (X) and runs X+ Y+.
TEST(Coverage, EndPointRulesAndLines) {
  const Suite s = suite("smoke");
  auto find_case = [&](const std::string& n) {
    for (const auto& c : s.cases)
      if (c.name == n) return c;
    throw std::runtime_error(n);
  };
  Coverage cov;
  for (const char* n : {"arc-k0", "arc-k0-y"}) {
    const Case c = find_case(n);
    const auto exp = expect(c);
    const auto run = run_of("model", exp.pulses, 0);
    cov.add(c, exp, run, judge(c, exp, 1e3, commands(exp.pulses.size()), run));
  }
  EXPECT_GE(cov.bins()[bin::kArcEndOut].total(), 1u);
  EXPECT_GE(cov.bins()[bin::kArcEndIn].total(), 1u);
  EXPECT_EQ(cov.bins()[bin::kArcK + 0].total(), 2u);
  const auto exp2 = expect(fig2());
  const auto run2 = run_of("core", pulses(kFig2), 0);
  cov.add(fig2(), exp2, run2, judge(fig2(), exp2, 1e3, commands(11), run2));
  EXPECT_EQ(cov.bins()[bin::kLineSigns + 0].total(), 1u);
  EXPECT_GE(cov.bins()[bin::kLineTie].total(), 1u);
}

// The verilator_coverage points the report counts: v_line and v_branch as
// lines, v_toggle as toggles, a count of 0 as not hit.
TEST(Report, ReadsTheCoresLineAndToggleCoverage) {
  const std::string path = ::testing::TempDir() + "/contour-cov-" + std::to_string(::getpid()) + ".dat";
  {
    std::ofstream f(path);
    f << "# SystemC::Coverage-3\n"
      << "C '\001f\002a.v\001l\0021\001page\002v_line/m__W8\001o\002block' 38\n"
      << "C '\001f\002a.v\001l\0022\001page\002v_branch/m__W8\001o\002if' 0\n"
      << "C '\001f\002a.v\001l\0023\001page\002v_toggle/m__W8\001o\002q[0]' 5\n";
  }
  const auto c = read_rtl_coverage(path);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->lines, 2u);
  EXPECT_EQ(c->lines_hit, 1u);
  EXPECT_EQ(c->toggles, 1u);
  EXPECT_EQ(c->toggles_hit, 1u);
  EXPECT_EQ(c->uncovered, (std::vector<std::string>{"v_branch/m__W8 a.v:2 if"}));
  std::filesystem::remove(path);
  EXPECT_FALSE(read_rtl_coverage(path));
}

TEST(Scoreboard, WrongFinalPositionFails) {
  auto run = run_of("core", pulses(kFig2), 0);
  run.position_known = true;
  run.x = 6;
  run.y = 4;
  const Row r = judge(fig2(), expect(fig2()), 1e3, commands(11), run);
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_NE(r.note.find("final position (6, 4), model (6, 5)"), std::string::npos) << r.note;
}

TEST(Scoreboard, VerdictLine) {
  std::vector<Row> rows(40);
  for (auto& r : rows) r.verdict = Verdict::Pass;
  EXPECT_EQ(verdict_line(rows), "100.00% PASS 40 PASSED, 0 FAILED");
  rows[3].verdict = Verdict::Fail;
  EXPECT_EQ(verdict_line(rows), "97.50% FAIL 39 PASSED, 1 FAILED");
}

TEST(Options, BadInputIsAOneLineUsageError) {
  bool help = false;
  EXPECT_THROW(parse_options({"--suite", "paper"}, help), UsageError);            // no rate
  EXPECT_THROW(parse_options({"--suite", "nope", "--sweep"}, help), UsageError);  // unknown suite
  EXPECT_THROW(parse_options({"--suite", "paper", "--rate", "fast"}, help), UsageError);
  EXPECT_THROW(parse_options({"--suite", "paper", "--rate", "0"}, help), UsageError);
  EXPECT_THROW(parse_options({"--suite", "paper", "--rate", "1k", "--sweep"}, help), UsageError);
  EXPECT_THROW(parse_options({"--suite", "paper", "--sweep", "--inject", "core:melt:3"}, help), UsageError);
  EXPECT_THROW(parse_options({"--suite", "paper", "--sweep", "--case", "fig9"}, help), UsageError);
  // Empty lists and items, hex and exponents, negative pulse numbers, a
  // report path that is a file.
  EXPECT_THROW(parse_options({"--suite", "paper", "--rate", "1k", "--engines", ""}, help), UsageError);
  EXPECT_THROW(parse_options({"--suite", "paper", "--rate", "1k", "--case", ""}, help), UsageError);
  EXPECT_THROW(parse_options({"--suite", "paper", "--rate", "1k,"}, help), UsageError);
  EXPECT_THROW(parse_options({"--suite", "paper", "--rate", "1k", "--engines", "model,,core"}, help), UsageError);
  EXPECT_THROW(parse_options({"--suite", "paper", "--rate", "0x10"}, help), UsageError);
  EXPECT_THROW(parse_options({"--suite", "paper", "--rate", "1e3"}, help), UsageError);
  EXPECT_THROW(parse_options({"--suite", "paper", "--rate", "1k", "--inject", "core:drop:-1"}, help), UsageError);
  EXPECT_THROW(parse_options({"--suite", "paper", "--rate", "1k", "--report", "/proc/self/status"}, help), UsageError);
  const Options o = parse_options({"--suite", "paper", "--rate", "250k,1M,3.5k"}, help);
  EXPECT_EQ(o.rates, (std::vector<double>{250e3, 1e6, 3.5e3}));
}

// --- whole runs, one per forked child -------------------------------------------------

struct ChildRow {
  std::string case_name, engine, verdict, summary;
  double rate = 0;
  std::uint64_t pulses = 0, lost = 0, mismatches = 0, div_index = 0;
  std::int64_t overruns = 0;
  double lat_min = -1, lat_max = -1;
};

// Runs `opt` in a child process; returns its rows.
std::vector<ChildRow> run_child(Options opt) {
  int fd[2];
  if (::pipe(fd) != 0) ADD_FAILURE() << "pipe";
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fd[0]);
    std::ostringstream o;
    int code = 0;
    try {
      const CosimOutcome out = run_cosim(opt);
      for (const auto& r : out.rows)
        o << r.case_name << '\t' << r.engine << '\t' << r.rate_pps << '\t' << to_string(r.verdict) << '\t'
          << r.pulses << '\t' << r.lost << '\t' << r.overruns << '\t' << r.mismatches << '\t'
          << (r.divergence ? r.divergence->index : 0) << '\t'
          << (r.divergence ? r.divergence->summary : std::string("-")) << '\t'
          << (r.has_latency ? r.lat_min_us : -1) << '\t' << (r.has_latency ? r.lat_max_us : -1) << '\n';
    } catch (const std::exception& e) {
      o << "ERROR\t" << e.what() << '\n';
      code = 3;
    }
    const std::string s = o.str();
    for (std::size_t done = 0; done < s.size();) {
      const auto n = ::write(fd[1], s.data() + done, s.size() - done);
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    ::close(fd[1]);
    std::_Exit(code);
  }
  ::close(fd[1]);
  std::string text;
  char buf[4096];
  for (ssize_t n; (n = ::read(fd[0], buf, sizeof buf)) > 0;) text.append(buf, static_cast<std::size_t>(n));
  ::close(fd[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << text;
  std::vector<ChildRow> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream l(line);
    ChildRow r;
    std::string f;
    std::vector<std::string> fs;
    while (std::getline(l, f, '\t')) fs.push_back(f);
    if (fs.size() != 12) continue;
    r.case_name = fs[0];
    r.engine = fs[1];
    r.rate = std::stod(fs[2]);
    r.verdict = fs[3];
    r.pulses = std::stoull(fs[4]);
    r.lost = std::stoull(fs[5]);
    r.overruns = std::stoll(fs[6]);
    r.mismatches = std::stoull(fs[7]);
    r.div_index = std::stoull(fs[8]);
    r.summary = fs[9];
    r.lat_min = std::stod(fs[10]);
    r.lat_max = std::stod(fs[11]);
    rows.push_back(r);
  }
  return rows;
}

const ChildRow* find(const std::vector<ChildRow>& rows, const std::string& c, const std::string& e, double rate) {
  for (const auto& r : rows)
    if (r.case_name == c && r.engine == e && r.rate == rate) return &r;
  return nullptr;
}

Options paper_at(std::vector<double> rates) {
  Options o;
  o.suite = "paper";
  o.rates = std::move(rates);
  return o;
}

// The paper suite at a few rates on every engine: the model and the core
// agree everywhere up to 250 kpps; the 8085 (ISS and Verilog board) agrees
// at 1 kpps and flags every loss at 250 kpps; ISS and board agree on it.
TEST(CosimRun, ReducedSweepOfThePaperSuite) {
  const std::vector<double> rates = {1e3, 4e3, 20e3, 250e3};
  const auto rows = run_child(paper_at(rates));
  ASSERT_EQ(rows.size(), 2u * 4u * 4u);
  for (const auto& r : rows) {
    EXPECT_NE(r.verdict, "FAIL") << r.case_name << " " << r.engine << " @ " << r.rate << ": " << r.summary;
    if (r.engine == "model" || r.engine == "core") {
      EXPECT_EQ(r.lost, 0u) << r.case_name << " " << r.engine << " @ " << r.rate;
      EXPECT_EQ(r.mismatches, 0u);
    }
  }
  for (const char* c : {"fig2", "fig5"}) {
    for (const char* e : {"iss", "cpu"}) {
      const ChildRow* slow = find(rows, c, e, 1e3);
      const ChildRow* fast = find(rows, c, e, 250e3);
      ASSERT_TRUE(slow && fast);
      EXPECT_EQ(slow->verdict, "PASS");
      EXPECT_EQ(fast->verdict, "FLAGGED");  // 4 us between commands: the routine takes tens
      EXPECT_GT(fast->lost, 0u);
      EXPECT_EQ(static_cast<std::int64_t>(fast->lost), fast->overruns);
    }
    // The same program on two T-state exact CPUs: the same verdict at every
    // rate (above the limit the counts may differ by a pulse: the ISS does
    // an instruction's I/O at its first T-state, the board at the real one).
    for (double rate : rates) {
      const ChildRow* iss = find(rows, c, "iss", rate);
      const ChildRow* board = find(rows, c, "cpu", rate);
      ASSERT_TRUE(iss && board);
      EXPECT_EQ(iss->verdict, board->verdict) << c << " @ " << rate;
      if (iss->lost == 0 || board->lost == 0) {
        EXPECT_EQ(iss->lost, board->lost) << c << " @ " << rate;
      }
    }
    // The core answers within a few of its 20 ns clocks: well inside 4 us.
    const ChildRow* core = find(rows, c, "core", 250e3);
    ASSERT_TRUE(core);
    EXPECT_GT(core->lat_min, 0.0);
    EXPECT_LT(core->lat_max, 1.0);
  }
}

// A line of more than 65 536 P steps: the 8085's host runs it as two
// segments, one mailbox slot each, back to back; both 8085 engines agree
// with the model pulse by pulse and end on the line's end point.
TEST(CosimRun, LongLineRunsAsSegmentsOnBoth8085Engines) {
  Options o;
  o.suite = "long";
  o.rates = {12e3};
  o.engines = {"model", "iss", "cpu"};
  const auto rows = run_child(o);
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& r : rows) {
    EXPECT_EQ(r.verdict, "PASS") << r.engine << ": " << r.summary;
    EXPECT_EQ(r.pulses, 65540u + 3u) << r.engine;  // |XE| + |YE|
    EXPECT_EQ(r.lost, 0u) << r.engine;
  }
}

// The paper suite at `rate` on the model and the engine that `fault`
// corrupts (only `cases`, when given).
std::vector<ChildRow> run_with_fault(const std::string& fault, double rate, std::vector<std::string> cases = {}) {
  Options o = paper_at({rate});
  o.faults = {parse_fault(fault)};
  o.engines = {"model", o.faults[0].engine};
  o.cases = std::move(cases);
  return run_child(o);
}

// `engine` failed on `case_name` at `rate`, first diverging at pulse `index`.
void expect_caught(const std::vector<ChildRow>& rows, const std::string& case_name, const std::string& engine,
                   double rate, std::uint64_t index, const std::string& summary) {
  const ChildRow* r = find(rows, case_name, engine, rate);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->verdict, "FAIL");
  EXPECT_EQ(r->div_index, index);
  EXPECT_EQ(r->summary, summary);
}

// A corrupted engine is caught, with the right first divergence.
TEST(CosimRun, DroppedPulseOnTheIssIsCaught) {
  const auto rows = run_with_fault("iss:drop:3", 1e3);
  expect_caught(rows, "fig2", "iss", 1e3, 3, "pulse 3: model +X, iss +Y");
  const ChildRow* m = find(rows, "fig2", "model", 1e3);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->verdict, "PASS");
}

TEST(CosimRun, SwappedPulsesOnTheCoreAreCaught) {
  expect_caught(run_with_fault("core:swap:5", 250e3), "fig5", "core", 250e3, 5, "pulse 5: model +Y, core -X");
}

TEST(CosimRun, FlippedSignOnTheBoardIsCaught) {
  expect_caught(run_with_fault("cpu:flip:12", 1e3, {"fig5"}), "fig5", "cpu", 1e3, 12, "pulse 12: model -X, cpu +X");
}

std::string read_text(const std::string& path) {
  std::ifstream f(path);
  std::ostringstream o;
  o << f.rdbuf();
  return o.str();
}

std::string temp_dir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("contour-cosim-test-" + std::to_string(::getpid()) + "-" + name);
  std::filesystem::remove_all(d);
  return d.string();
}

// An injected swap is a mismatch, not a loss, and the page says a fault was
// injected.
TEST(CosimRun, InjectedSwapIsReportedAsAMismatchOnAPageThatSaysSo) {
  Options o = paper_at({1e3});
  o.faults = {parse_fault("core:swap:3")};
  o.engines = {"model", "core"};
  o.cases = {"fig2"};
  o.report_dir = temp_dir("swap");
  const auto rows = run_child(o);
  const ChildRow* r = find(rows, "fig2", "core", 1e3);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->verdict, "FAIL");
  EXPECT_EQ(r->lost, 0u);
  const std::string html = read_text(o.report_dir + "/report.html");
  EXPECT_NE(html.find("A fault was injected: <code>--inject core:swap:3</code>"), std::string::npos);
  EXPECT_NE(html.find("<th>core: agrees up to</th><th>first loss</th><th>first mismatch</th>"), std::string::npos);
  const std::string json = read_text(o.report_dir + "/report.json");
  EXPECT_NE(json.find("{\"case\": \"fig2\", \"engine\": \"core\", \"agrees_up_to_pps\": 0, \"first_loss_pps\": null, "
                      "\"first_mismatch_pps\": 1000}"),
            std::string::npos)
      << json;
  std::filesystem::remove_all(o.report_dir);
}

// The report: rows only for the rates that ran, the header counts what ran,
// a re-run command and absolute times for each failing row, links to the
// traces, schema_version in the JSON, time in every JUnit testcase.
TEST(CosimRun, ReportShowsWhatRanAndHowToReRunAFailure) {
  Options o = paper_at({2e3, 1e6});
  o.faults = {parse_fault("iss:flip:2")};
  o.engines = {"model", "iss"};
  o.cases = {"fig5"};
  o.trace = true;  // no Verilated engine: no trace file
  o.report_dir = temp_dir("report");
  const auto rows = run_child(o);
  ASSERT_EQ(rows.size(), 4u);
  const ChildRow* nr = find(rows, "fig5", "iss", 1e6);
  ASSERT_TRUE(nr);
  EXPECT_EQ(nr->verdict, "NOT RUN");
  const std::string html = read_text(o.report_dir + "/report.html");
  EXPECT_NE(html.find("1 case(s), 2 (case, rate) run(s) at 2 rate(s) from 2k to 1M pps; 3 row(s) ran (2 passed, 1 "
                      "failed), 1 NOT RUN"),
            std::string::npos)
      << html.substr(0, 3000);
  EXPECT_NE(html.find("Re-run this row alone: <code>contour cosim --suite paper --case fig5 --rate 2k --engines "
                      "model,iss --inject iss:flip:2</code>"),
            std::string::npos);
  EXPECT_NE(html.find("the first divergence came at "), std::string::npos);
  EXPECT_NE(html.find(">command rate (kpps)</text>"), std::string::npos);  // as the tables
  EXPECT_EQ(html.find("e+06"), std::string::npos);
  EXPECT_EQ(html.find("<tr><td>250k</td>"), std::string::npos);  // no row for a rate that did not run
  EXPECT_NE(html.find("<td class=\"NOTRUN\""), std::string::npos);
  const std::string json = read_text(o.report_dir + "/report.json");
  EXPECT_EQ(json.rfind("{\n  \"schema_version\": 2,\n", 0), 0u) << json.substr(0, 200);
  EXPECT_NE(json.find("\"rerun\": \"contour cosim --suite paper --case fig5 --rate 2k --engines model,iss --inject "
                      "iss:flip:2\""),
            std::string::npos);
  EXPECT_NE(json.find("\"sim_time_us\": "), std::string::npos);
  const std::string junit = read_text(o.report_dir + "/junit.xml");
  std::size_t cases = 0, timed = 0;
  for (std::size_t at = 0; (at = junit.find("<testcase ", at)) != std::string::npos; ++at, ++cases)
    timed += junit.compare(junit.find('>', at) - 1, 1, "\"") == 0 &&
             junit.substr(at, junit.find('>', at) - at).find(" time=\"") != std::string::npos;
  EXPECT_EQ(cases, 4u);
  EXPECT_EQ(timed, 4u) << junit;
  EXPECT_NE(junit.find("<skipped message="), std::string::npos);
  std::filesystem::remove_all(o.report_dir);
}

// The core's FST trace is linked from the page, relative to it.
TEST(CosimRun, ReportLinksTheTraces) {
  Options o = paper_at({100e3});
  o.engines = {"model", "core"};
  o.cases = {"fig2"};
  o.trace = true;
  o.report_dir = temp_dir("trace");
  run_child(o);
  EXPECT_TRUE(std::filesystem::exists(o.report_dir + "/core.fst"));
  EXPECT_NE(read_text(o.report_dir + "/report.html").find("<a href=\"core.fst\">core.fst</a>"), std::string::npos);
  std::filesystem::remove_all(o.report_dir);
}

// STEP_LEN = STEP_SPACE = 4095 clocks (the registers' largest): the output
// stage carries 6090 pps, so at 20 kpps the core loses pulses, flags each
// one, and does not FAIL.
TEST(CosimRun, SlowOutputTimingIsNotAFalseFail) {
  Options o = paper_at({20e3});
  o.engines = {"model", "core"};
  o.timing.len = o.timing.space = 4095;
  const auto rows = run_child(o);
  ASSERT_EQ(rows.size(), 4u);
  for (const char* c : {"fig2", "fig5"}) {
    const ChildRow* r = find(rows, c, "core", 20e3);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->verdict, "FLAGGED") << c << ": " << r->summary;
    EXPECT_GT(r->lost, 0u);
    EXPECT_EQ(static_cast<std::int64_t>(r->lost), r->overruns);
  }
}

// The core's clock runs only after command pulses and bus accesses (a
// speed-up); a free-running clock must give the same pulses at the same times.
TEST(CosimRun, GatedCoreClockEqualsFreeRunning) {
  Options o;
  o.suite = "smoke";
  o.cases = {"arc-3q"};
  o.rates = {20e3, 1e6};
  o.engines = {"model", "core"};
  const auto gated = run_child(o);
  o.free_clock = true;
  const auto free = run_child(o);
  ASSERT_EQ(gated.size(), free.size());
  ASSERT_FALSE(gated.empty());
  for (std::size_t i = 0; i < gated.size(); ++i) {
    EXPECT_EQ(gated[i].verdict, free[i].verdict);
    EXPECT_EQ(gated[i].pulses, free[i].pulses);
    EXPECT_EQ(gated[i].lost, free[i].lost);
    EXPECT_EQ(gated[i].overruns, free[i].overruns);
    EXPECT_DOUBLE_EQ(gated[i].lat_min, free[i].lat_min);
    EXPECT_DOUBLE_EQ(gated[i].lat_max, free[i].lat_max);
  }
}

}  // namespace
}  // namespace contour::cosim
