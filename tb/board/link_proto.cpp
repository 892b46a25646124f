#include "link_proto.hpp"

namespace contour::board {

std::uint16_t crc16(const std::uint8_t* data, std::size_t n, std::uint16_t crc) {
  for (std::size_t i = 0; i < n; ++i) {
    crc = static_cast<std::uint16_t>(crc ^ (data[i] << 8));
    for (int b = 0; b < 8; ++b)
      crc = static_cast<std::uint16_t>((crc & 0x8000u) ? ((crc << 1) ^ BOARD_CRC_POLY) : (crc << 1));
  }
  return crc;
}

Bytes slip_encode(const Bytes& frame) {
  Bytes out;
  out.reserve(frame.size() + 4);
  out.push_back(BOARD_SLIP_END);
  for (std::uint8_t b : frame) {
    if (b == BOARD_SLIP_END) {
      out.push_back(BOARD_SLIP_ESC);
      out.push_back(BOARD_SLIP_ESC_END);
    } else if (b == BOARD_SLIP_ESC) {
      out.push_back(BOARD_SLIP_ESC);
      out.push_back(BOARD_SLIP_ESC_ESC);
    } else {
      out.push_back(b);
    }
  }
  out.push_back(BOARD_SLIP_END);
  return out;
}

std::optional<Bytes> SlipDecoder::feed(std::uint8_t c) {
  if (c == BOARD_SLIP_END) {
    const bool any = !cur_.empty() || bad_;
    Bytes f;
    f.swap(cur_);
    last_bad_ = bad_ || esc_;
    bad_ = esc_ = false;
    if (!any) return std::nullopt;
    return f;
  }
  if (esc_) {
    esc_ = false;
    if (c == BOARD_SLIP_ESC_END) cur_.push_back(BOARD_SLIP_END);
    else if (c == BOARD_SLIP_ESC_ESC) cur_.push_back(BOARD_SLIP_ESC);
    else bad_ = true;
  } else if (c == BOARD_SLIP_ESC) {
    esc_ = true;
  } else {
    cur_.push_back(c);
  }
  return std::nullopt;
}

std::size_t request_size(const std::vector<Op>& ops) {
  std::size_t n = 3;
  for (const Op& o : ops) n += o.write ? 5 : 1;
  return n;
}

Bytes make_request(std::uint8_t seq, const std::vector<Op>& ops) {
  Bytes f{seq};
  for (const Op& o : ops) {
    f.push_back(static_cast<std::uint8_t>((o.write ? BOARD_OP_WRITE : 0u) | (o.word & BOARD_OP_ADDR)));
    if (o.write)
      for (int s = 24; s >= 0; s -= 8) f.push_back(static_cast<std::uint8_t>(o.data >> s));
  }
  const std::uint16_t c = crc16(f.data(), f.size());
  f.push_back(static_cast<std::uint8_t>(c >> 8));
  f.push_back(static_cast<std::uint8_t>(c));
  return slip_encode(f);
}

namespace {

std::uint32_t be32(const std::uint8_t* p) {
  return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | p[3];
}

// The trailer's fields (board.def's REPLY lines) from its first byte.
void parse_trailer(const std::uint8_t* t, Reply& r) {
  static_assert(BOARD_REPLY_POS_X_BYTES == 4 && BOARD_REPLY_POS_Y_BYTES == 4 && BOARD_REPLY_POS_Z_BYTES == 4);
  r.level3 = t[BOARD_REPLY_LEVEL3];
  r.level2 = t[BOARD_REPLY_LEVEL2];
  r.flags = t[BOARD_REPLY_FLAGS];
  r.pos = {static_cast<std::int32_t>(be32(t + BOARD_REPLY_POS_X)), static_cast<std::int32_t>(be32(t + BOARD_REPLY_POS_Y)),
           static_cast<std::int32_t>(be32(t + BOARD_REPLY_POS_Z))};
  r.next_seq = t[BOARD_REPLY_NEXT_SEQ];
}

}  // namespace

std::optional<Reply> parse_reply(const Bytes& f) {
  // seq, status, [detail | data], trailer, CRC (2)
  constexpr std::size_t kFixed = 2 + BOARD_REPLY_TRAILER + 2;
  if (f.size() < kFixed || crc16(f.data(), f.size()) != 0) return std::nullopt;
  Reply r;
  r.seq = f[0];
  r.status = f[1];
  const std::size_t body = f.size() - kFixed;
  std::size_t at = 2;
  if (r.status != BOARD_ERR_OK) {
    if (body != 1) return std::nullopt;
    r.detail = f[at++];
  } else {
    if (body % 4 != 0) return std::nullopt;
    for (std::size_t k = 0; k < body / 4; ++k, at += 4) r.data.push_back(be32(&f[at]));
  }
  parse_trailer(&f[at], r);
  return r;
}

std::string status_name(std::uint8_t s) {
  switch (s) {
    case BOARD_ERR_OK: return "OK";
    case BOARD_ERR_CRC: return "CRC";
    case BOARD_ERR_LEN: return "LEN";
    case BOARD_ERR_REG: return "REG";
    case BOARD_ERR_SEQ: return "SEQ";
    case BOARD_ERR_DUP: return "DUP";
    default: return std::to_string(s);
  }
}

std::optional<std::uint32_t> pack_chord(std::int64_t dx, std::int64_t dy, std::int64_t dz) {
  auto fits = [](std::int64_t v) { return v >= -512 && v <= 511; };
  if (!fits(dx) || !fits(dy) || !fits(dz)) return std::nullopt;
  auto f = [](std::int64_t v, unsigned lsb) { return (static_cast<std::uint32_t>(v) & 0x3FFu) << lsb; };
  return f(dx, BOARD_AXIS3_CHORD_CX_LSB) | f(dy, BOARD_AXIS3_CHORD_CY_LSB) | f(dz, BOARD_AXIS3_CHORD_CZ_LSB);
}

}  // namespace contour::board
