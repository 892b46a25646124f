// The host's end of the link (docs/board.md, "Protocol"): frames of
// register ops sent over a byte transport, replies matched by sequence
// number, go-back-N resends. A frame with writes takes the next sequence
// number; the board does it only in order (ERR_SEQ otherwise) and never
// twice (ERR_DUP), so a resend after a lost frame or a lost reply neither
// loses nor doubles a write. Frames of reads only are sent one at a time
// (transact) with the number the board expects and take none.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "link_proto.hpp"

namespace contour::board {

// A byte stream to the board: a serial port, a pty, or the simulated board.
class Transport {
 public:
  virtual ~Transport() = default;
  virtual void write(const Bytes& bytes) = 0;
  // What has come, waiting up to `timeout_s` for the first byte.
  virtual Bytes read(double timeout_s) = 0;
  virtual double now_s() = 0;  // the clock of the timeouts
};

// The board does not answer, or answers with an error the host cannot
// mend by a resend (exit status 2 of `contour stream`).
class LinkError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LinkTimes {
  double resend_s = 0.1;  // no reply to the oldest frame for this long: send again
  double dead_s = 3.0;    // no valid reply at all for this long: LinkError
};

struct LinkStats {
  std::uint64_t frames = 0, resends = 0, go_backs = 0, bad_replies = 0, refused = 0;
};

class LinkClient {
 public:
  explicit LinkClient(Transport& t, LinkTimes times = {});

  // Learns the board's expected sequence number (a read of `word`).
  void sync(std::uint8_t word);
  // Sends one frame and waits for its reply (all earlier frames first). A
  // frame with writes and reads whose reply was lost is answered DUP when
  // sent again (done once, no data): its reads are then sent alone, and
  // their reply is returned.
  Reply transact(const std::vector<Op>& ops);
  // Pipelined: sends a frame with writes (it must have one) now.
  void post(const std::vector<Op>& ops, std::size_t chords);
  // Reads and handles replies, resends when due; waits up to `timeout_s`.
  void pump(double timeout_s);
  void drain();  // until every posted frame is acknowledged

  std::size_t in_flight() const { return out_.size(); }
  std::uint8_t next_seq() const { return next_seq_; }  // the number post() gives the next frame
  std::size_t chords_in_flight() const;
  const Reply& last() const { return last_; }
  const LinkStats& stats() const { return stats_; }
  // Called for each reply to a frame with reads (its data, in op order).
  std::function<void(const Reply&)> on_data;
  // Called for every valid reply (flags, levels).
  std::function<void(const Reply&)> on_reply;

 private:
  struct Frame {
    std::uint8_t seq = 0;
    Bytes bytes;
    std::size_t reads = 0, chords = 0;
    std::uint64_t gen = 0;
    double sent_at = 0;
  };
  void send(Frame& f);
  void go_back();
  void handle(const Reply& r);
  void check_dead();
  static std::vector<Op> reads_of(const std::vector<Op>& ops);
  std::optional<Reply> transact_reply(const Reply& r, std::uint8_t seq, bool writes, std::size_t reads);
  static bool before(std::uint8_t a, std::uint8_t b) { return static_cast<std::int8_t>(a - b) < 0; }

  Transport& t_;
  LinkTimes times_;
  SlipDecoder dec_;
  std::deque<Frame> out_;
  std::uint8_t next_seq_ = 0;
  std::uint64_t gen_ = 0;
  double last_valid_ = 0;
  Reply last_;
  LinkStats stats_;
  unsigned len_refusals_ = 0;  // LEN refusals since the last OK reply

  void refuse_len(const Reply& r, std::uint8_t seq);
};

}  // namespace contour::board
