// The board's frame engine through its UART at the bit level: what it
// answers to good frames and to each kind of bad one, and that a refused
// frame writes nothing (docs/board.md, "Protocol").
#include <gtest/gtest.h>

#include "board_sim.hpp"

namespace contour::board {
namespace {

// Sends raw frame bytes; returns the first reply frame (unescaped), or none
// within `timeout_s` of simulated time.
std::optional<Bytes> round_trip(BoardSim& sim, const Bytes& bytes, double timeout_s = 0.01) {
  sim.send(bytes);
  SlipDecoder d;
  const double until = sim.seconds() + timeout_s;
  while (sim.seconds() < until) {
    sim.run(120);
    for (std::uint8_t c : sim.take_received())
      if (auto f = d.feed(c)) return f;
  }
  return std::nullopt;
}

Reply ask(BoardSim& sim, std::uint8_t seq, const std::vector<Op>& ops) {
  auto f = round_trip(sim, make_request(seq, ops));
  EXPECT_TRUE(f) << "no reply";
  if (!f) return {};
  auto r = parse_reply(*f);
  EXPECT_TRUE(r) << "reply with a bad CRC or length";
  return r ? *r : Reply{};
}

// A frame from raw bytes (seq, op bytes): CRC appended, optionally spoiled.
Bytes raw_frame(Bytes body, bool spoil_crc = false) {
  const std::uint16_t c = crc16(body.data(), body.size());
  body.push_back(static_cast<std::uint8_t>(c >> 8));
  body.push_back(static_cast<std::uint8_t>((c & 0xFF) ^ (spoil_crc ? 1 : 0)));
  return slip_encode(body);
}

std::uint32_t read1(BoardSim& sim, std::uint8_t word) {
  const Reply r = ask(sim, 0, {Op{false, word, 0}});
  EXPECT_EQ(r.status, BOARD_ERR_OK);
  return r.data.empty() ? 0xFFFFFFFFu : r.data[0];
}

TEST(BoardFrames, ReadsTheIdentities) {
  BoardSim sim;
  const Reply r = ask(sim, 0, {Op{false, BOARD_INTERP_ID, 0}, Op{false, BOARD_AXIS3_ID, 0}, Op{false, BOARD_LINK_ID, 0}});
  EXPECT_EQ(r.status, BOARD_ERR_OK);
  ASSERT_EQ(r.data.size(), 3u);
  EXPECT_EQ(r.data[0], 0x494E5450u);  // "INTP"
  EXPECT_EQ(r.data[1], 0x41583320u);  // "AX3 "
  EXPECT_EQ(r.data[2], 0x4C4E4B31u);  // "LNK1"
  EXPECT_EQ(r.next_seq, 0);           // reads take no sequence number
}

TEST(BoardFrames, WritesInOrderAndAdvancesTheSequence) {
  BoardSim sim;
  Reply r = ask(sim, 0, {Op{true, BOARD_AXIS3_CYCLE, 1234}, Op{false, BOARD_AXIS3_CYCLE, 0}});
  EXPECT_EQ(r.status, BOARD_ERR_OK);
  ASSERT_EQ(r.data.size(), 1u);
  EXPECT_EQ(r.data[0], 1234u);
  EXPECT_EQ(r.next_seq, 1);
  // Data bytes equal to END and ESC travel escaped (chords of -3904 and -3877 steps).
  r = ask(sim, 1, {Op{true, BOARD_AXIS3_CH_X, 0xFFFFF0C0u}, Op{true, BOARD_AXIS3_CH_Y, 0xFFFFF0DBu},
                   Op{false, BOARD_AXIS3_CH_X, 0}, Op{false, BOARD_AXIS3_CH_Y, 0}});
  EXPECT_EQ(r.status, BOARD_ERR_OK);
  ASSERT_EQ(r.data.size(), 2u);
  EXPECT_EQ(r.data[0], 0xFFFFF0C0u);
  EXPECT_EQ(r.data[1], 0xFFFFF0DBu);
}

TEST(BoardFrames, BadCrcIsRefusedAndWritesNothing) {
  BoardSim sim;
  ask(sim, 0, {Op{true, BOARD_AXIS3_CYCLE, 1234}});
  auto f = round_trip(sim, raw_frame({1, 0x80 | BOARD_AXIS3_CYCLE, 0, 0, 3, 0xE7}, true));
  ASSERT_TRUE(f);
  auto r = parse_reply(*f);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, BOARD_ERR_CRC);
  EXPECT_EQ(read1(sim, BOARD_AXIS3_CYCLE), 1234u);
  EXPECT_EQ(read1(sim, BOARD_LINK_REFUSED), 1u);
}

TEST(BoardFrames, UnknownRegisterIsRefusedAndWritesNothing) {
  BoardSim sim;
  // A good write first, then a write to a word no window has: nothing done.
  Reply r = ask(sim, 0, {Op{true, BOARD_AXIS3_CYCLE, 777}, Op{true, 0x7F, 1}});
  EXPECT_EQ(r.status, BOARD_ERR_REG);
  EXPECT_EQ(r.detail, 6);  // the op's byte index: seq, 5 bytes of the first op
  EXPECT_EQ(read1(sim, BOARD_AXIS3_CYCLE), 12000u);
  // A write to a read-only register, a read of a write-only one.
  EXPECT_EQ(ask(sim, 0, {Op{true, BOARD_AXIS3_ID, 1}}).status, BOARD_ERR_REG);
  EXPECT_EQ(ask(sim, 0, {Op{false, BOARD_AXIS3_PUSH, 0}}).status, BOARD_ERR_REG);
  EXPECT_EQ(ask(sim, 0, {Op{false, 0x35, 0}}).status, BOARD_ERR_REG);  // a hole in AXIS3
  EXPECT_EQ(read1(sim, BOARD_AXIS3_STATUS) >> BOARD_AXIS3_STATUS_LEVEL_LSB, 0u);
}

TEST(BoardFrames, LengthErrorsAreRefused) {
  BoardSim sim;
  auto status = [&](const Bytes& b) {
    auto f = round_trip(sim, b);
    if (!f) return -1;
    auto r = parse_reply(*f);
    return r ? int{r->status} : -2;
  };
  EXPECT_EQ(status(slip_encode({0, 1})), BOARD_ERR_LEN);             // shorter than seq + CRC
  EXPECT_EQ(status(raw_frame(Bytes(70, 0x01))), BOARD_ERR_LEN);      // longer than MAX_FRAME
  EXPECT_EQ(status(raw_frame({0, 0x80 | BOARD_AXIS3_CYCLE, 0, 0})), BOARD_ERR_LEN);  // write cut short
  EXPECT_EQ(read1(sim, BOARD_AXIS3_CYCLE), 12000u);
}

TEST(BoardFrames, OutOfOrderIsRefusedAndARepeatIsNotDoneTwice) {
  BoardSim sim;
  const std::uint32_t chord = *pack_chord(3, 0, 0);
  Reply r = ask(sim, 5, {Op{true, BOARD_AXIS3_CHORD, chord}});
  EXPECT_EQ(r.status, BOARD_ERR_SEQ);
  EXPECT_EQ(r.detail, 0);  // the expected number
  r = ask(sim, 0, {Op{true, BOARD_AXIS3_CHORD, chord}});
  EXPECT_EQ(r.status, BOARD_ERR_OK);
  EXPECT_EQ(r.level3, 1);
  r = ask(sim, 0, {Op{true, BOARD_AXIS3_CHORD, chord}});  // its reply was "lost": sent again
  EXPECT_EQ(r.status, BOARD_ERR_DUP);
  EXPECT_EQ(r.level3, 1);
  EXPECT_EQ(r.next_seq, 1);
}

TEST(BoardFrames, EmptyFramesAndNoiseBeforeAFrameAreIgnored) {
  BoardSim sim;
  Bytes b{0xC0, 0xC0, 0x55, 0x13};  // noise, then the frame's own leading END
  const Bytes f = make_request(0, {Op{false, BOARD_LINK_ID, 0}});
  b.insert(b.end(), f.begin(), f.end());
  auto first = round_trip(sim, b);
  ASSERT_TRUE(first);
  auto r1 = parse_reply(*first);
  ASSERT_TRUE(r1);
  EXPECT_EQ(r1->status, BOARD_ERR_LEN);  // the noise (2 bytes), refused
  SlipDecoder d;
  std::optional<Reply> r2;
  for (int i = 0; i < 100 && !r2; ++i) {
    sim.run(120);
    for (std::uint8_t c : sim.take_received())
      if (auto x = d.feed(c)) r2 = parse_reply(*x);
  }
  ASSERT_TRUE(r2);
  EXPECT_EQ(r2->status, BOARD_ERR_OK);
  ASSERT_EQ(r2->data.size(), 1u);
  EXPECT_EQ(r2->data[0], 0x4C4E4B31u);
}

// Replies longer than their requests fill the reply queue (256 bytes):
// frames of one read (6 characters) answered by 24 bytes. The frame engine
// waits while the queue is full (frames that end meanwhile are dropped) and
// never pushes past it: every reply that comes is whole and right.
TEST(BoardFrames, AFullReplyQueueLosesNoReplyByte) {
  BoardSim sim;
  for (int k = 0; k < 120; ++k) sim.send(make_request(static_cast<std::uint8_t>(k), {Op{false, BOARD_LINK_ID, 0}}));
  SlipDecoder d;
  std::vector<Reply> got;
  int bad = 0;
  for (int quiet = 0, i = 0; i < 2000 && quiet < 20; ++i) {  // until 20 x 100 us with nothing more
    sim.run(1200);
    const Bytes in = sim.take_received();
    quiet = (in.empty() && sim.line_idle()) ? quiet + 1 : 0;
    for (std::uint8_t c : in)
      if (auto f = d.feed(c)) {
        if (auto r = parse_reply(*f)) got.push_back(*r);
        else ++bad;
      }
  }
  EXPECT_EQ(bad, 0);
  EXPECT_GT(got.size(), 20u);
  EXPECT_LT(got.size(), 120u);  // some frames ended while the engine waited: dropped
  int last = -1;
  for (const Reply& r : got) {
    EXPECT_EQ(r.status, BOARD_ERR_OK);
    ASSERT_EQ(r.data.size(), 1u);
    EXPECT_EQ(r.data[0], 0x4C4E4B31u) << "reply to frame " << int{r.seq};
    EXPECT_GT(int{r.seq}, last);  // in order, each at most once
    last = r.seq;
    EXPECT_EQ(r.flags, 0);
    EXPECT_EQ(r.next_seq, 0);
  }
}

// With LINK CTRL.PINS the X and Y pins are interp_top's, and so are the
// replies' X and Y positions: a line of -300, +200 steps on interp_top.
TEST(BoardFrames, RepliesCarryInterpTopsPositionsWhenItHasThePins) {
  BoardSim sim;
  auto wr = [](std::uint8_t w, std::uint32_t d) { return Op{true, w, d}; };
  Reply r = ask(sim, 0,
                {wr(BOARD_LINK_CTRL, BOARD_LINK_CTRL_ENABLE_MASK | BOARD_LINK_CTRL_PINS_MASK),
                 wr(BOARD_INTERP_BLK_MODE, BOARD_INTERP_BLK_MODE_SXN_MASK), wr(BOARD_INTERP_BLK_TI, 300),
                 wr(BOARD_INTERP_BLK_TO, 200), wr(BOARD_INTERP_PUSH, 0)});
  ASSERT_EQ(r.status, BOARD_ERR_OK);
  r = ask(sim, 1, {wr(BOARD_INTERP_FEED, 1u << 26), wr(BOARD_INTERP_CTRL, 2)});  // a command every 64 clocks
  ASSERT_EQ(r.status, BOARD_ERR_OK);
  sim.run(3000);
  const std::uint64_t asked = sim.clocks();
  r = ask(sim, 0, {Op{false, BOARD_LINK_ID, 0}});  // mid-line
  const auto mid = pins_net(sim.steps());
  EXPECT_LT(mid[0], -10);
  EXPECT_GT(mid[0], -300);
  for (int a = 0; a < 2; ++a)
    EXPECT_TRUE(pins_net_seen(sim.steps(), a, asked, sim.clocks(), r.pos[a])) << "axis " << a << ": " << r.pos[a];
  sim.run(40000);
  r = ask(sim, 0, {Op{false, BOARD_INTERP_POS_X, 0}, Op{false, BOARD_INTERP_POS_Y, 0}});
  ASSERT_EQ(r.data.size(), 2u);
  EXPECT_EQ(static_cast<std::int32_t>(r.data[0]), -300);
  EXPECT_EQ(static_cast<std::int32_t>(r.data[1]), 200);
  EXPECT_EQ(r.pos, (std::array<std::int32_t, 3>{-300, 200, 0}));
  EXPECT_EQ(pins_net(sim.steps()), (std::array<std::int64_t, 3>{-300, 200, 0}));
  // Back to the chord peripheral's pins: its positions (none moved).
  r = ask(sim, 2, {wr(BOARD_LINK_CTRL, BOARD_LINK_CTRL_ENABLE_MASK)});
  EXPECT_EQ(r.pos, (std::array<std::int32_t, 3>{0, 0, 0}));
}

}  // namespace
}  // namespace contour::board
