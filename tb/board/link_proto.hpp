// The host side of the board's link protocol (docs/board.md, "Protocol"):
// CRC-16, SLIP framing, requests of register ops and their replies. The
// constants and register addresses come from the one table,
// rtl/board/board.def, through the generated gen/board_proto.h; the RTL
// reads the same table (rtl/board/board_proto.vh). Plain C++, no hardware:
// used by `contour stream`, `contour board-sim` and the tests.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "board_proto.h"

namespace contour::board {

using Bytes = std::vector<std::uint8_t>;

// CRC-16/CCITT-FALSE of `data` (poly 0x1021, init 0xFFFF, MSB first).
std::uint16_t crc16(const std::uint8_t* data, std::size_t n, std::uint16_t crc = BOARD_CRC_INIT);

// SLIP: `frame` escaped and closed by END (and opened by one, to flush noise).
Bytes slip_encode(const Bytes& frame);

// SLIP decoder of a byte stream: whole frames as they end.
class SlipDecoder {
 public:
  // Feeds one character; returns the frame it ends, if any (empty frames
  // are skipped). A bad escape marks the frame corrupt (`bad()`).
  std::optional<Bytes> feed(std::uint8_t c);
  bool last_bad() const { return last_bad_; }

 private:
  Bytes cur_;
  bool esc_ = false, bad_ = false, last_bad_ = false;
};

// One register op: a read, or a write of a 32-bit word, by word address.
struct Op {
  bool write = false;
  std::uint8_t word = 0;
  std::uint32_t data = 0;
};

// A request: the sequence number and the ops, framed with the CRC.
Bytes make_request(std::uint8_t seq, const std::vector<Op>& ops);
std::size_t request_size(const std::vector<Op>& ops);  // unescaped bytes, CRC included

// A reply, parsed and checked.
struct Reply {
  std::uint8_t seq = 0;
  std::uint8_t status = BOARD_ERR_OK;
  std::uint8_t detail = 0;              // refused: the op's byte index, or the expected sequence
  std::vector<std::uint32_t> data;      // the reads' words, in order
  std::uint8_t level3 = 0, level2 = 0;  // chord queue, block queue
  std::uint8_t flags = 0;
  std::array<std::int32_t, 3> pos{};    // X, Y, Z of the STEP/DIR pins' peripheral (board.def REPLY POS_*)
  std::uint8_t next_seq = 0;            // the sequence number the board expects next
  bool flag(unsigned bit) const { return (flags >> bit) & 1u; }
};

// Parses an unescaped reply frame; nullopt if its CRC or length is wrong
// (a status OK reply has 4 bytes for each read op of its request). The
// trailer's layout is board.def's REPLY lines (BOARD_REPLY_*).
std::optional<Reply> parse_reply(const Bytes& frame);

// "OK", "CRC", "LEN", "REG", "SEQ", "DUP", or the number.
std::string status_name(std::uint8_t status);

// The packed CHORD word, if the chord fits its 10-bit fields.
std::optional<std::uint32_t> pack_chord(std::int64_t dx, std::int64_t dy, std::int64_t dz);

}  // namespace contour::board
