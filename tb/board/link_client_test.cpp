// The host's link client against a scripted board (no RTL): what it does
// with each refusal, with silence, and that a resend neither loses nor
// doubles a write. The scripted board keeps the board's sequence rules
// (docs/board.md, "Protocol") in a few lines of its own.
#include <gtest/gtest.h>

#include <deque>
#include <string>

#include "link_client.hpp"

namespace contour::board {
namespace {

// Answers each request after `latency_s` of its own clock, with the status
// the script says for the next request (OK when the script is empty), or
// not at all (`silent`). Counts the write ops it has done.
class ScriptedBoard : public Transport {
 public:
  std::deque<std::uint8_t> script;  // statuses for the next requests
  bool silent = false;
  unsigned drop_replies = 0;  // this many replies lost on the wire (the request done)
  std::vector<std::uint32_t> done;  // the data of each write done, in order
  double latency_s = 0.001;

  void write(const Bytes& bytes) override {
    for (std::uint8_t c : bytes)
      if (auto f = dec_.feed(c)) answer(*f);
  }
  Bytes read(double timeout_s) override {
    clock_ += timeout_s;
    Bytes out;
    while (!pending_.empty() && pending_.front().first <= clock_) {
      out.insert(out.end(), pending_.front().second.begin(), pending_.front().second.end());
      pending_.pop_front();
    }
    return out;
  }
  double now_s() override { return clock_; }
  std::uint8_t expected() const { return exp_; }

 private:
  void answer(const Bytes& f) {
    if (silent || f.size() < 3) return;
    std::uint8_t status = BOARD_ERR_OK;
    if (!script.empty()) {
      status = script.front();
      script.pop_front();
    }
    const bool writes = f.size() > 4 && (f[1] & BOARD_OP_WRITE);  // the tests' frames: writes first
    if (status == BOARD_ERR_OK && writes && f[0] != exp_)
      status = f[0] == static_cast<std::uint8_t>(exp_ - 1) ? BOARD_ERR_DUP : BOARD_ERR_SEQ;
    std::size_t reads = 0;
    if (status == BOARD_ERR_OK) {
      for (std::size_t i = 1; i + 2 < f.size();) {
        if (f[i] & BOARD_OP_WRITE) {
          done.push_back(std::uint32_t{f[i + 1]} << 24 | std::uint32_t{f[i + 2]} << 16 | std::uint32_t{f[i + 3]} << 8 |
                         f[i + 4]);
          i += 5;
        } else {
          ++reads;
          ++i;
        }
      }
      if (writes) ++exp_;
    }
    Bytes r{f[0], status};
    if (status != BOARD_ERR_OK) r.push_back(status == BOARD_ERR_SEQ ? exp_ : 1);
    r.insert(r.end(), 4 * reads, 0);
    Bytes trailer(BOARD_REPLY_TRAILER, 0);
    trailer[BOARD_REPLY_NEXT_SEQ] = exp_;
    r.insert(r.end(), trailer.begin(), trailer.end());
    const std::uint16_t c = crc16(r.data(), r.size());
    r.push_back(static_cast<std::uint8_t>(c >> 8));
    r.push_back(static_cast<std::uint8_t>(c));
    if (drop_replies != 0) {
      --drop_replies;
      return;
    }
    pending_.push_back({clock_ + latency_s, slip_encode(r)});
  }

  SlipDecoder dec_;
  std::deque<std::pair<double, Bytes>> pending_;
  std::uint8_t exp_ = 0;
  double clock_ = 0;
};

Op wr(std::uint32_t d) { return Op{true, BOARD_AXIS3_CH_X, d}; }

TEST(LinkClient, AFrameRefusedForCrcOrLengthIsSentAgainAndDoneOnce) {
  ScriptedBoard b;
  b.script = {BOARD_ERR_CRC, BOARD_ERR_LEN, BOARD_ERR_CRC};
  LinkClient link(b);
  const Reply r = link.transact({wr(7)});
  EXPECT_EQ(r.status, BOARD_ERR_OK);
  EXPECT_EQ(b.done, (std::vector<std::uint32_t>{7}));
  EXPECT_EQ(link.stats().refused, 3u);
  EXPECT_EQ(link.stats().resends, 3u);
}

// A write and a read in one frame, its reply lost: sent again, the board
// answers DUP (done once, no data); the read is sent alone and its data
// returned.
TEST(LinkClient, AFrameOfWritesAndReadsWhoseReplyWasLostGetsItsReadsAgain) {
  ScriptedBoard b;
  b.drop_replies = 1;
  LinkClient link(b);
  const Reply r = link.transact({wr(7), Op{false, BOARD_AXIS3_STATUS, 0}});
  EXPECT_EQ(r.status, BOARD_ERR_OK);
  EXPECT_EQ(r.data.size(), 1u);
  EXPECT_EQ(b.done, (std::vector<std::uint32_t>{7}));
}

TEST(LinkClient, PipelinedFramesRefusedAreSentAgainInOrder) {
  ScriptedBoard b;
  b.script = {BOARD_ERR_OK, BOARD_ERR_CRC, BOARD_ERR_OK, BOARD_ERR_LEN};  // frames 1 and 3 refused
  LinkClient link(b);
  for (std::uint32_t k = 0; k < 6; ++k) link.post({wr(k)}, 0);
  link.drain();
  EXPECT_EQ(b.done, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_GT(link.stats().resends, 0u);
  // A lone frame refused: sent again after the resend time.
  b.script = {BOARD_ERR_CRC};
  link.post({wr(6)}, 0);
  link.drain();
  EXPECT_EQ(b.done.back(), 6u);
  EXPECT_EQ(b.done.size(), 7u);
}

TEST(LinkClient, ARegisterRefusalIsAnErrorNamingTheFrame) {
  ScriptedBoard b;
  b.script = {BOARD_ERR_REG};
  LinkClient link(b);
  try {
    link.transact({wr(1)});
    ADD_FAILURE() << "no error";
  } catch (const LinkError& e) {
    EXPECT_NE(std::string(e.what()).find("refused frame 0: REG"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(b.done.empty());
}

TEST(LinkClient, LengthRefusalsWithoutEndAreAnError) {
  ScriptedBoard b;
  b.script = std::deque<std::uint8_t>(40, BOARD_ERR_LEN);
  LinkClient link(b);
  EXPECT_THROW(link.transact({wr(1)}), LinkError);
  EXPECT_TRUE(b.done.empty());
}

TEST(LinkClient, SilenceIsAnErrorAfterTheDeadTime) {
  ScriptedBoard b;
  b.silent = true;
  LinkTimes times;
  times.dead_s = 1.5;
  LinkClient link(b, times);
  try {
    link.transact({Op{false, BOARD_LINK_ID, 0}});
    ADD_FAILURE() << "no error";
  } catch (const LinkError& e) {
    EXPECT_NE(std::string(e.what()).find("does not answer"), std::string::npos) << e.what();
  }
  EXPECT_GE(b.now_s(), 1.5);
  EXPECT_LT(b.now_s(), 1.6);
}

}  // namespace
}  // namespace contour::board
