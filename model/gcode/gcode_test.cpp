#include "gcode/gcode.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace contour::gcode {
namespace {

// Expects parse(text) to fail at (line, column) with a message containing `what`.
void expect_error(const std::string& text, int line, int column, const std::string& what) {
  try {
    parse(text);
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const Error& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.column(), column) << e.what();
    EXPECT_NE(e.problem().find(what), std::string::npos) << "message: " << e.what() << "\nwanted: " << what;
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
    EXPECT_EQ(std::string(e.what()).rfind("line " + std::to_string(line) + ", column " + std::to_string(column), 0),
              0u);
  }
}

TEST(GcodeGrammar, PaperBExampleIsA3DArc) {
  const auto b = parse("G00X50.Y0.Z0.\nG03X0.Y-47.246Z-16.366I-50J0.K0.F6000\nG00X0.Y0.Z0.\n");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b[0].motion, Motion::Rapid);
  EXPECT_EQ(b[0].end, (Vec3{50, 0, 0}));
  EXPECT_EQ(b[1].motion, Motion::ArcCCW);
  EXPECT_TRUE(b[1].arc3d);
  EXPECT_EQ(b[1].start, (Vec3{50, 0, 0}));
  EXPECT_EQ(b[1].centre, (Vec3{0, 0, 0}));
  EXPECT_DOUBLE_EQ(b[1].feed_mm_s, 100.0);
  EXPECT_NEAR(b[1].r_start, 50.0, 1e-12);
  EXPECT_NEAR(b[1].r_end, 50.0, 1e-3);
  EXPECT_EQ(b[1].line, 2);
  EXPECT_EQ(b[2].end, (Vec3{0, 0, 0}));
}

TEST(GcodeGrammar, CommentsLineNumbersBlanksCaseAndCrlf) {
  const auto b = parse("%\r\nn10 g1 x 1.5 y-.5 f 60 (a comment) z+2 ; tail\r\n(only a comment)\n\n N20\tG0X0Y0Z0\n%\n");
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].end, (Vec3{1.5, -0.5, 2}));
  EXPECT_DOUBLE_EQ(b[0].feed_mm_s, 1.0);
  EXPECT_EQ(b[0].line, 2);
  EXPECT_EQ(b[1].line, 5);
  EXPECT_EQ(b[1].end, (Vec3{0, 0, 0}));
}

TEST(GcodeGrammar, ModalMotionIncrementalAndInches) {
  const auto b = parse("G20\nG91 G1 X1 F10\nY2\nG90 G21 X0 Y0\n");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b[0].end, (Vec3{25.4, 0, 0}));
  EXPECT_NEAR(b[0].feed_mm_s, 10 * 25.4 / 60, 1e-12);
  EXPECT_EQ(b[1].end, (Vec3{25.4, 50.8, 0}));
  EXPECT_EQ(b[2].motion, Motion::Line);
  EXPECT_EQ(b[2].end, (Vec3{0, 0, 0}));
}

TEST(GcodeGrammar, ZeroLengthLineMovesNothing) { EXPECT_TRUE(parse("G1 X0 F10\n").empty()); }

TEST(GcodeGrammar, FullCircleAndHelixAndPlanes) {
  auto b = parse("G0 X50\nG3 X50 Y0 I-50 J0 F6000\n");
  ASSERT_EQ(b.size(), 2u);
  EXPECT_TRUE(b[1].full_circle);
  EXPECT_FALSE(b[1].arc3d);
  b = parse("G1 X10 F100\nG2 X20 Z5 I5 J0\n");
  EXPECT_FALSE(b[1].arc3d);
  EXPECT_FALSE(b[1].full_circle);
  EXPECT_EQ(b[1].centre, (Vec3{15, 0, 0}));
  b = parse("G18 G3 X10 Z10 I5 K5 F100\n");  // in G18, K is the plane's first offset
  EXPECT_EQ(b[0].plane, Plane::ZX);
  EXPECT_EQ(b[0].centre, (Vec3{5, 0, 5}));
  b = parse("G19 G2 Y10 Z0 J5 K0 F100\n");
  EXPECT_EQ(b[0].plane, Plane::YZ);
  EXPECT_EQ(b[0].centre, (Vec3{0, 5, 0}));
}

TEST(GcodeGrammar, RadiusFormCentreBothSigns) {
  // From (0,0) to (10,0), R 5 ... the centre is the midpoint; with R 5.
  // A quarter circle from (10,0) to (0,10), R 10: CCW short arc has its
  // centre at (0,0); R -10 (long arc) at (10,10). CW short at (10,10).
  auto c = [](const std::string& prog) { return parse(prog)[1].centre; };
  const Vec3 ccw_short = c("G0 X10\nG3 X0 Y10 R10 F1\n");
  EXPECT_NEAR(ccw_short.x, 0, 1e-12);
  EXPECT_NEAR(ccw_short.y, 0, 1e-12);
  const Vec3 ccw_long = c("G0 X10\nG3 X0 Y10 R-10 F1\n");
  EXPECT_NEAR(ccw_long.x, 10, 1e-12);
  EXPECT_NEAR(ccw_long.y, 10, 1e-12);
  const Vec3 cw_short = c("G0 X10\nG2 X0 Y10 R10 F1\n");
  EXPECT_NEAR(cw_short.x, 10, 1e-12);
  EXPECT_NEAR(cw_short.y, 10, 1e-12);
}

// F and G20/G21 on one line: LinuxCNC sets the feed (step 3 of its order of
// execution) before the units (step 12), so F is read in the units before the
// line; rs274 prints SET_FEED_RATE(6) then USE_LENGTH_UNITS(INCHES) for
// `G20 F6`, and the feed stays 6 mm/min on the inch moves.
TEST(GcodeFeedOrder, FeedIsReadInTheUnitsBeforeTheLine) {
  auto b = parse("G20 F6 G1 X1\n");
  ASSERT_EQ(b.size(), 1u);
  EXPECT_NEAR(b[0].feed_mm_s, 6.0 / 60, 1e-12);
  EXPECT_NEAR(b[0].end.x, 25.4, 1e-12);
  b = parse("G20\nG21 F100 G1 X2\nX3\n");  // 100 in/min, kept after G21
  ASSERT_EQ(b.size(), 2u);
  EXPECT_NEAR(b[0].feed_mm_s, 100 * 25.4 / 60, 1e-12);
  EXPECT_NEAR(b[1].feed_mm_s, 100 * 25.4 / 60, 1e-12);
  b = parse("G20\nF6 G1 X1\n");  // F on a line after G20: inches
  EXPECT_NEAR(b[0].feed_mm_s, 6 * 25.4 / 60, 1e-12);
}

// R-format arcs by LinuxCNC's rule (measured with rs274: half chord 10 mm,
// R 9.99875 taken, R 9.9987 refused; the tolerance is 0.00005 in).
TEST(GcodeRFormat, RadiusShortOfHalfTheChord) {
  // 25 um short: refused, naming R and the half chord (it was run at radius
  // R about the midpoint, the path jumping by 25 um).
  expect_error("G0 X10 Y0\nG2 X-10 Y0 R9.975 F600\n", 2, 12, "too small to reach the end point: |R|=9.9750");
  expect_error("G0 X10 Y0\nG2 X-10 Y0 R9.9987 F600\n", 2, 12, "half the chord 10.0000");
  // 1 um short: the half circle on the chord, radius 10 both ends.
  const auto b = parse("G0 X10 Y0\nG2 X-10 Y0 R9.999 F600\n");
  ASSERT_EQ(b.size(), 2u);
  EXPECT_NEAR(b[1].centre.x, 0, 1e-12);
  EXPECT_NEAR(b[1].centre.y, 0, 1e-12);
  EXPECT_NEAR(b[1].r_start, 10, 1e-12);
  EXPECT_NEAR(b[1].r_end, 10, 1e-12);
  // A semicircle whose end is rounded by 1 um: radius half the chord.
  const auto c = parse("G0 X10 Y0\nG3 X-10.001 Y0 R10 F600\n");
  EXPECT_NEAR(c[1].centre.x, -0.0005, 1e-12);
  EXPECT_NEAR(c[1].r_start, 10.0005, 1e-12);
  EXPECT_NEAR(c[1].r_end, 10.0005, 1e-12);
  // Inches: 0.00005 in.
  EXPECT_NO_THROW(parse("G20 G0 X0.5\nG2 X-0.5 Y0 R0.49996 F6\n"));
  expect_error("G20 G0 X0.5\nG2 X-0.5 Y0 R0.49994 F6\n", 2, 13, "too small");
}

TEST(GcodeRadiusRule, LinuxCncRuleBothWays) {
  // Within tol (0.0283 mm): accepted.
  EXPECT_EQ(check_radii(10.0, 10.02, false), "");
  // Over tol but under 0.1 % of the radius (R 100, diff 0.05): accepted.
  EXPECT_EQ(check_radii(100.0, 100.05, false), "");
  // Over tol and over 0.1 % (R 10, diff 0.03): rejected.
  EXPECT_NE(check_radii(10.0, 10.03, false), "");
  // Under 0.1 % but over 100 x tol = 2.83 mm (R 10000, diff 3): rejected.
  EXPECT_NE(check_radii(10000.0, 10003.0, false), "");
  EXPECT_EQ(check_radii(10000.0, 10002.8, false), "");
  // Inches: tol 0.00283 in.
  EXPECT_EQ(check_radii(1.0, 1.002, true), "");
  EXPECT_NE(check_radii(1.0, 1.003, true), "");
  // The message gives both radii.
  const std::string m = check_radii(10.0, 10.03, false);
  EXPECT_NE(m.find("r1=10.0000"), std::string::npos) << m;
  EXPECT_NE(m.find("r2=10.0300"), std::string::npos) << m;
}

TEST(GcodeRadiusRule, ReaderAppliesItToPlaneAnd3DArcs) {
  EXPECT_NO_THROW(parse("G2 X10.02 Y0 I5 J0 F100\n"));  // r1 5, r2 5.02
  expect_error("G2 X10.04 Y0 I5 J0 F100\n", 1, 1, "r1=5.0000 mm r2=5.0400 mm");
  expect_error("G0 X50\nG3 X0 Y-47.246 Z-17 I-50 J0 K0 F6000\n", 2, 1, "radius to end of arc differs");
  // In inches the tolerance is 0.00283 in: 0.002 passes, 0.004 fails.
  EXPECT_NO_THROW(parse("G20 G2 X2.002 Y0 I1 J0 F10\n"));
  expect_error("G20\nG2 X2.004 Y0 I1 J0 F10\n", 2, 1, "r2=1.0040 in");
}

TEST(GcodeErrors, EveryErrorNamesLineAndColumn) {
  expect_error("G1 X1 F10\nG1 M98\n", 2, 4, "unsupported M code M98");
  expect_error("G1 X1 A3 F10\n", 1, 7, "unsupported word 'A' (this reader has the axes X Y Z)");
  expect_error("G1 X F10\n", 1, 4, "word 'X' has no number");
  expect_error("G1 X1 X2 F10\n", 1, 7, "two X words");
  expect_error("G1 G2 X1 F10\n", 1, 4, "both motion words");
  expect_error("G17 G18\n", 1, 5, "both plane words");
  expect_error("G4\n", 1, 1, "G4 needs P");
  expect_error("G5 X1\n", 1, 1, "unsupported G code G5");
  expect_error("G1.5 X1\n", 1, 1, "unsupported G code");
  expect_error("X1\n", 1, 1, "no motion mode");
  expect_error("G1 X1\n", 1, 1, "no feed rate");
  expect_error("G1 X1 F0\n", 1, 7, "feed F must be > 0");
  expect_error("G1 X1 F-5\n", 1, 7, "feed F must be > 0");
  expect_error("G1 X1 (open\n", 1, 7, "comment '(' is not closed");
  expect_error("G1 X1 (a (b) c)\n", 1, 10, "comments do not nest");
  expect_error("G1 X1 F1 )\n", 1, 10, "')' without a matching '('");
  expect_error("G1 X1 F1 N5\n", 1, 10, "line number N must be the first word");
  expect_error("N1.5 G0 X1\n", 1, 1, "whole number");
  expect_error("G1 X1 F1 #\n", 1, 11, "expression ends early");
  expect_error("G1 X1 F1 $\n", 1, 10, "unexpected character '$'");
  expect_error("%x\n", 1, 2, "text after '%'");
  expect_error("G1 X1 I2 F10\n", 1, 7, "only allowed with G2/G3");
  expect_error("G2 X1 F10\n", 1, 1, "needs the centre offsets");
  expect_error("G2 X10 I5 R5 F10\n", 1, 11, "R or I/J/K offsets, not both");
  expect_error("G2 X10 K5 F10\n", 1, 8, "K offset is off the G17 plane");
  expect_error("G2 X10 Y0 F10 R0\n", 1, 15, "radius R is zero");
  expect_error("G2 X10 Y0 F10 R4\n", 1, 15, "too small to reach the end point");
  expect_error("G2 X0 Y0 Z1 F10 R4\n", 1, 17, "cannot be a full circle");
  expect_error("G2 X1 Y1 I0 J0 F10\n", 1, 1, "radius is zero");
  expect_error("G0 X1\n   G1 Y1 X1e5 F1\n", 2, 12, "unsupported word 'E'");
  expect_error("G1 X12345678901234567890123456789012 F1\n", 1, 5, "too long");
}

TEST(GcodeErrors, ThreeDArcPlaneChecks) {
  // The arc from (10,0,0) to (0,0,10) about the origin lies in the XZ plane,
  // which contains Z, the normal of G17: no sense of rotation.
  expect_error("G0 X10\nG3 X0 Y0 Z10 I-10 J0 K0 F60\n", 2, 1, "contains the Z axis");
  // The same arc is fine in G18 (normal Y).
  EXPECT_NO_THROW(parse("G0 X10\nG18 G3 X0 Y0 Z10 I-10 J0 K0 F60\n"));
  // A 3D half circle: start, centre and end in one line.
  expect_error("G0 X10\nG3 X-10 Y0 Z0.0001 I-10 J0 K0.00005 F60\n", 2, 1, "in one line");
}

// The non-motion language: events in LinuxCNC's order, not refusals.
std::string codes(const Program& p) {
  std::string s;
  for (const auto& e : p.events) s += (s.empty() ? "" : ",") + e.code;
  return s;
}

TEST(GcodeLanguage, SpindleCoolantToolAndStopWordsAreEvents) {
  // Order within a line: S, T, M6, M3, M8 (LinuxCNC's steps 4-8), then the stop.
  const Program p = read("M8 M3 M6 T2 S12000 G1 X1 F100 M1\n");
  EXPECT_EQ(codes(p), "S12000,T2,M6 T2,M3,M8,M1");
  // Stops (M6, M3, M1) are dwells of 0 s: the machine comes to rest.
  ASSERT_EQ(p.blocks.size(), 4u);
  EXPECT_TRUE(p.blocks[0].is_dwell());
  EXPECT_EQ(p.blocks[0].dwell_s, 0);
  EXPECT_TRUE(p.blocks[1].is_dwell());
  EXPECT_EQ(p.blocks[2].motion, Motion::Line);
  EXPECT_TRUE(p.blocks[3].is_dwell());
  EXPECT_EQ(p.events[5].before, 3u);  // M1 after the move
  EXPECT_FALSE(p.ended);
}

TEST(GcodeLanguage, NothingAfterProgramEndRuns) {
  for (const char* end : {"M2", "M30"}) {
    const Program p = read(std::string("G1 X1 F100\n") + end + "\nG1 X5\nthis is not G-code\n");
    EXPECT_TRUE(p.ended) << end;
    ASSERT_EQ(p.blocks.size(), 1u) << end;
    EXPECT_EQ(codes(p), end);
  }
  // A program between '%' lines ends at the second one.
  const Program q = read("%\nG1 X1 F100\n%\nG1 X9 junk\n");
  EXPECT_TRUE(q.ended);
  EXPECT_EQ(q.blocks.size(), 1u);
}

TEST(GcodeLanguage, DwellFeedModeCutterCompAndPathControl) {
  const Program p = read("G94 G40 G1 X1 F60\nG4 P0.5\nG61 X2\nG64 P0.01 Q0.01 X3\nG64 X4\nG61.1 X5\n");
  ASSERT_EQ(p.blocks.size(), 6u);
  EXPECT_TRUE(p.blocks[1].is_dwell());
  EXPECT_DOUBLE_EQ(p.blocks[1].dwell_s, 0.5);
  EXPECT_EQ(p.blocks[0].path, PathMode::Blend);
  EXPECT_EQ(p.blocks[2].path, PathMode::ExactStop);
  EXPECT_EQ(p.blocks[3].path, PathMode::Blend);
  EXPECT_DOUBLE_EQ(p.blocks[3].blend_tol_mm, 0.01);
  EXPECT_LT(p.blocks[4].blend_tol_mm, 0);
  EXPECT_EQ(p.blocks[5].path, PathMode::ExactStop);
  EXPECT_DOUBLE_EQ(read("G20 G64 P0.001 G1 X1 F1\n").blocks[0].blend_tol_mm, 0.0254);
  expect_error("G93 G1 X1 F1\n", 1, 1, "inverse time feed (G93) is not supported");
  expect_error("G1 X1 F1\nG41 D1 X2\n", 2, 1, "cutter radius compensation (G41/G42) is not supported");
  expect_error("G42 X2\n", 1, 1, "G41/G42");
  expect_error("G4 P-1\n", 1, 4, "dwell P must be >= 0");
  expect_error("G1 X1 F1 P2\n", 1, 10, "P word with no G4, G10, G64, G82, G89 or arc");
  expect_error("G84 X1 Y1 Z-1 R1 F10\n", 1, 1, "cycle G84 is not supported");
}

TEST(GcodeLanguage, WorkOffsetsAndMachineCoordinates) {
  // G10 L2 P2 sets G55's offset; G55 then reads X0 as machine X10.
  const Program p = read(
      "G10 L2 P2 X10 Y20 Z-5\nG55 G0 X0 Y0 Z0\nG53 G0 Z0\nG54 G0 X1\n"
      "G0 X3 Y4\nG10 L20 P1 X0 Y0\nG0 X1 Y1\nG59.3 G0 X0\n");
  ASSERT_EQ(p.blocks.size(), 6u);
  EXPECT_EQ(p.blocks[0].end, (Vec3{10, 20, -5}));
  EXPECT_EQ(p.blocks[1].end, (Vec3{10, 20, 0}));    // G53: machine Z0
  EXPECT_EQ(p.blocks[2].end, (Vec3{1, 20, 0}));     // G54, offset 0
  EXPECT_EQ(p.blocks[3].end, (Vec3{3, 4, 0}));
  EXPECT_EQ(p.blocks[4].end, (Vec3{4, 5, 0}));      // L20: (3,4) now reads (0,0)
  EXPECT_EQ(p.blocks[5].end, (Vec3{0, 5, 0}));      // G59.3: offset 0
  EXPECT_EQ(codes(p), "G10 L2 P2,G55,G54,G10 L20 P1,G59.3");
  expect_error("G53 G2 X1 Y1 I1 F1\n", 1, 1, "G53 needs G0 or G1");
  expect_error("G91 G53 G0 X1\n", 1, 5, "incremental");
  expect_error("G10 L1 P1 Z3\n", 1, 5, "G10 L1 is not supported");
  expect_error("G10 L2 P10 X1\n", 1, 8, "G10 P must be 0..9");
  expect_error("G92 X0\n", 1, 1, "G92 offsets are not supported");
}

TEST(GcodeLanguage, HomePositions) {
  // G28 through (5,5,5) to the stored position (0 until G28.1 stores one).
  Program p = read("G0 X1 Y2 Z3\nG28 X5 Y5\n");
  ASSERT_EQ(p.blocks.size(), 3u);
  EXPECT_EQ(p.blocks[1].end, (Vec3{5, 5, 3}));
  EXPECT_EQ(p.blocks[2].end, (Vec3{0, 0, 3}));  // only the named axes go home
  p = read("G0 X1 Y2 Z3\nG30.1\nG0 X7\nG30\n");
  ASSERT_EQ(p.blocks.size(), 3u);
  EXPECT_EQ(p.blocks[2].end, (Vec3{1, 2, 3}));
  expect_error("G28 G1 X1 F1\n", 1, 5, "both use the axis words");
}

TEST(GcodeLanguage, ToolLengthOffsetFromTheTable) {
  Options o;
  o.tools = read_tool_table("T1 P1 Z12.5 D6 ;end mill\nT2 P2 Z-1.25\n\n");
  ASSERT_EQ(o.tools.size(), 2u);
  const Program p = read("T1 M6\nG43 H1 G0 Z0\nG43 G0 Z1\nG43 H2 Z1\nG49 Z1\n", o);
  ASSERT_EQ(p.blocks.size(), 5u);  // stop for M6, then four moves
  EXPECT_DOUBLE_EQ(p.blocks[1].end.z, 12.5);
  EXPECT_DOUBLE_EQ(p.blocks[2].end.z, 13.5);   // G43 without H: the loaded tool 1
  EXPECT_DOUBLE_EQ(p.blocks[3].end.z, -0.25);
  EXPECT_DOUBLE_EQ(p.blocks[4].end.z, 1);
  try {
    read("G43 H3\n", o);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.column(), 5);
    EXPECT_NE(std::string(e.what()).find("tool 3 is not in the tool table"), std::string::npos);
  }
  expect_error("G43 H1\n", 1, 5, "give one with --tool-table");
  expect_error("G1 H1 X1 F1\n", 1, 4, "H word with no G43");
  EXPECT_THROW(read_tool_table("T1 P1 Z1\nT1 P2 Z2\n"), Error);
  EXPECT_THROW(read_tool_table("P2 Z2\n"), Error);
}

TEST(GcodeLanguage, ArcCentreModesBlockDeleteAndLineEnds) {
  // G90.1: I J absolute (in the work system); G91.1 (default): relative.
  Program p = read("G10 L2 P1 X100\nG0 X10 Y0\nG90.1 G3 X0 Y10 I0 J0 F10\nG91.1 G3 X-10 Y0 I0 J-10\n");
  ASSERT_EQ(p.blocks.size(), 3u);
  EXPECT_EQ(p.blocks[1].centre, (Vec3{100, 0, 0}));
  EXPECT_EQ(p.blocks[2].centre, (Vec3{100, 0, 0}));
  // '/' lines are skipped (block delete on), CR CR LF ends read.
  p = read("G1 X1 F10\r\r\n/G1 X5\r\r\nG1 Y1\r\r\n");
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_EQ(p.blocks[1].end, (Vec3{1, 1, 0}));
  Options keep;
  keep.block_delete = false;
  EXPECT_EQ(read("G1 X1 F10\n/G1 X5\n", keep).blocks.size(), 2u);
  expect_error("O100 sub\n", 1, 1, "O100 sub is not closed");
  expect_error("G1 @1 ^2 F1\n", 1, 4, "polar coordinates");
}

TEST(GcodeParameters, NumberedNamedAndExpressions) {
  const Program p = read(
      "#1 = 10 #<depth> = -2.5 #<_cut_feed>=[100*3]\n"
      "G1 X#1 Y[#1 / 4 + 1] Z#<depth> F#<_cut_feed>\n"
      "#2 = [2 ** 3 MOD 5] #3 = [1 + 2 * 3 - 4 / 2]\n"
      "G0 X#2 Y#3 Z[SIN[30] * 2]\n"
      "#4 = ATAN[1]/[1] #5 = [SQRT[16] + ABS[-2] + FIX[2.7] + FUP[2.2] + ROUND[2.5]]\n"
      "G0 X#4 Y#5 Z[[3 GT 2] + [2 EQ 2] + [1 AND 0] + [1 OR 0] + [1 XOR 1]]\n"
      "#1 = 1 #6 = #1\n"  // #6 gets the old #1: settings apply after the line
      "G0 X#6 Y-#1 Z-[#1 + 1]\n"
      "#[2 + 5] = EXISTS[#<depth>] #8 = EXISTS[#<nope>] #9 = ##1\n"
      "G0 X#7 Y#8 Z#9\n");
  ASSERT_EQ(p.blocks.size(), 5u);
  EXPECT_EQ(p.blocks[0].end, (Vec3{10, 3.5, -2.5}));
  EXPECT_DOUBLE_EQ(p.blocks[0].feed_mm_s, 5);
  EXPECT_EQ(p.blocks[1].end.x, 3);  // 2 ** 3 = 8, MOD 5 = 3
  EXPECT_EQ(p.blocks[1].end.y, 5);
  EXPECT_NEAR(p.blocks[1].end.z, 1, 1e-12);
  EXPECT_NEAR(p.blocks[2].end.x, 45, 1e-12);
  EXPECT_EQ(p.blocks[2].end.y, 4 + 2 + 2 + 3 + 3);
  EXPECT_EQ(p.blocks[2].end.z, 3);
  EXPECT_EQ(p.blocks[3].end, (Vec3{10, -1, -2}));
  EXPECT_EQ(p.blocks[4].end, (Vec3{1, 0, 1}));  // #9 = #[#1] = #1 = 1
}

TEST(GcodeParameters, ErrorsNameWhere) {
  expect_error("G1 X[1/0] F1\n", 1, 7, "division by zero");
  expect_error("G1 X#<nope> F1\n", 1, 5, "named parameter #<nope> is not set");
  expect_error("G1 X[SQRT[-1]] F1\n", 1, 6, "SQRT of -1.0000 is undefined");
  expect_error("G1 X[1 + 2 F1\n", 1, 12, "expected ']'");
  expect_error("#5400 = 1\n", 1, 2, "system parameter #5400 is not supported");
  expect_error("#<_feed> = 1\n", 1, 2, "cannot assign to read-only parameter #<_feed>");
  expect_error("G0 X#<_x>\n", 1, 5, "predefined parameter #<_x> is not supported");
  expect_error("#1.5 = 1\n", 1, 2, "whole number");
  expect_error("#1 2\n", 1, 4, "expected '='");
  expect_error("G1 X[FOO[1]] F1\n", 1, 6, "unknown function 'FOO'");
  std::string deep = "G1 X";
  for (int k = 0; k < 100; ++k) deep += "[";
  deep += "1";
  for (int k = 0; k < 100; ++k) deep += "]";
  try {
    read(deep + " F1\n");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("nested deeper than 64"), std::string::npos) << e.what();
  }
}

// Canned cycles as LinuxCNC expands them (rs274 agrees on the corpus).
std::string moves(const Program& p) {
  std::string s;
  char b[96];
  for (const Block& m : p.blocks) {
    if (m.is_dwell()) std::snprintf(b, sizeof b, "D%g ", m.dwell_s);
    else std::snprintf(b, sizeof b, "%s%g,%g,%g ", m.motion == Motion::Rapid ? "R" : "F", m.end.x, m.end.y, m.end.z);
    s += b;
  }
  return s;
}

TEST(GcodeCycles, DrillDwellPeckReamAndRetractModes) {
  // G98 from Z10: to X Y at 10, down to R, feed to Z, back to 10.
  EXPECT_EQ(moves(read("G0 Z10\nG98 G81 X5 Y5 Z-3 R2 F100\nX10\n")),
            "R0,0,10 R5,5,10 R5,5,2 F5,5,-3 R5,5,10 R10,5,10 R10,5,2 F10,5,-3 R10,5,10 ");
  // G99 from below R: first straight up to R; retract to R.
  EXPECT_EQ(moves(read("G99 G82 X5 Y0 Z-3 R2 P0.5 F100\n")), "R0,0,2 R5,0,2 F5,0,-3 D0.5 R5,0,2 ");
  // G83: back to R after each peck, rapid to 0.254 mm above the last depth.
  EXPECT_EQ(moves(read("G0 Z5\nG99 G83 X0 Y0 Z-2 R1 Q1.5 F100\n")),
            "R0,0,5 R0,0,1 F0,0,-0.5 R0,0,1 R0,0,-0.246 F0,0,-2 R0,0,1 ");
  // G73: 0.254 mm chip-break retract.
  EXPECT_EQ(moves(read("G0 Z5\nG99 G73 X0 Y0 Z-2 R1 Q1.5 F100\n")),
            "R0,0,5 R0,0,1 F0,0,-0.5 R0,0,-0.246 F0,0,-2 R0,0,1 ");
  // G85 feeds out to R, G89 dwells and feeds out to the clear level.
  EXPECT_EQ(moves(read("G0 Z5\nG98 G85 X0 Y0 Z-2 R1 F100\n")), "R0,0,5 R0,0,1 F0,0,-2 F0,0,1 R0,0,5 ");
  EXPECT_EQ(moves(read("G0 Z5\nG98 G89 X0 Y0 Z-2 R1 P1 F100\n")), "R0,0,5 R0,0,1 F0,0,-2 D1 F0,0,5 ");
  expect_error("G81 X1 Y1 Z-2 F100\n", 1, 1, "G81 needs R");
  expect_error("G83 X1 Y1 Z-2 R1 F100\n", 1, 1, "G83 needs Q");
  expect_error("G81 X1 Y1 Z3 R2 F100\n", 1, 1, "the bottom Z is above the retract plane R");
  expect_error("G91 G81 X1 Y1 Z-3 R2 F100\n", 1, 5, "incremental mode (G91) are not supported");
  expect_error("G18 G81 X1 Y1 Z-3 R2 F100\n", 1, 5, "G17 plane only");
  expect_error("G81 X1 Y1 Z-3 R2 L3 F100\n", 1, 18, "repeats L other than 1");
}

// O-words: subroutines with arguments and local parameters, if/elseif/else,
// while, do-while, repeat, break, continue; the bounds against runaways.
TEST(GcodeOWords, SubroutinesAndControlFlow) {
  const Program p = read(
      "#<depth> = 7\n"
      "o<hole> sub\n"
      "  #<depth> = [#1 * 2]\n"  // a local: the caller's #<depth> is kept
      "  G0 X#1 Y#2\n"
      "  o10 if [#3 GT 0]\n"
      "    G1 Z-#3 F100\n"
      "  o10 elseif [#3 EQ 0]\n"
      "    G1 Z-0.5 F100\n"
      "  o10 else\n"
      "    o<hole> return\n"
      "  o10 endif\n"
      "  G0 Z1\n"
      "o<hole> endsub\n"
      "o<hole> call [1] [2] [3]\n"
      "o<hole> call [4] [5] [0]\n"
      "o<hole> call [6] [7] [-1]\n"
      "G0 X#<depth> Y#1\n"
      "#9 = 0\n"
      "o20 while [#9 LT 3]\n"
      "  #9 = [#9 + 1]\n"
      "  o20 if [#9 EQ 2]\n"
      "    o20 continue\n"
      "  o20 endif\n"
      "  G0 X[10 + #9]\n"
      "o20 endwhile\n"
      "o30 repeat [2]\n"
      "  G0 Y[#9 + 10]\n"
      "  #9 = [#9 + 1]\n"
      "o30 endrepeat\n"
      "o40 do\n"
      "  #9 = [#9 + 1]\n"
      "  o40 if [#9 GT 7]\n"
      "    o40 break\n"
      "  o40 endif\n"
      "  G0 Z#9\n"
      "o40 while [1]\n"
      "M2\n");
  EXPECT_EQ(moves(p),
            "R1,2,0 F1,2,-3 R1,2,1 R4,5,1 F4,5,-0.5 R4,5,1 R6,7,1 R7,0,1 R11,0,1 R13,0,1 R13,13,1 R13,14,1 "
            "R13,14,6 R13,14,7 ");
  EXPECT_TRUE(p.ended);
}

TEST(GcodeOWords, RunawayBoundsAndStructureErrors) {
  expect_error("o1 while [1]\no1 endwhile\n", 1, 1, "more than 10^7 lines");
  expect_error("o<r> sub\no<r> call\no<r> endsub\no<r> call\n", 2, 1, "nested deeper than 64");
  expect_error("o1 repeat [3000000]\nG0 X1\nG0 X2\no1 endrepeat\n", 3, 1, "more than 2*10^6 moves");
  expect_error("o1 if [1]\n", 1, 1, "O1 if is not closed");
  expect_error("o1 endif\n", 1, 1, "without its opening O1");
  expect_error("o1 if [1]\no2 endif\n", 2, 1, "without its opening O2");
  expect_error("o1 while [1]\no1 endif\n", 2, 1, "does not close O1 while");
  expect_error("o1 break\n", 1, 1, "outside an O1 loop");
  expect_error("o<x> call\n", 1, 1, "subroutine O<x> is not defined");
  expect_error("o1 return\n", 1, 1, "return outside a subroutine");
  expect_error("o1 frobnicate\n", 1, 1, "unknown O-word keyword 'frobnicate'");
  // Found by the fuzzer: a number too long for a long (it threw out_of_range).
  expect_error("o4444444444444444444444444444444444101 sub\n", 1, 1, "O-word number is too long");
  EXPECT_EQ(read("o0100 sub\nG0 X1\no100 endsub\no100 call\n").blocks.size(), 1u);
  expect_error("G0 X1 o1 if [1]\n", 1, 7, "an O-word must begin its line");
}

}  // namespace
}  // namespace contour::gcode
