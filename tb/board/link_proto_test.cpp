// The host side of the protocol alone: CRC against the catalogue's check
// value, SLIP round trips, requests and replies byte by byte.
#include <gtest/gtest.h>

#include <climits>
#include <cstdint>
#include <string>

#include "link_proto.hpp"

namespace contour::board {
namespace {

TEST(LinkProto, CrcIsCcittFalseByItsCheckValue) {
  // CRC-16/CCITT-FALSE of "123456789" is 0x29B1 (the CRC catalogue's check).
  const std::string s = "123456789";
  EXPECT_EQ(crc16(reinterpret_cast<const std::uint8_t*>(s.data()), s.size()), 0x29B1);
}

TEST(LinkProto, SlipEscapesEndAndEscAndDecodesBack) {
  const Bytes f{0x01, 0xC0, 0xDB, 0x02, 0xDC, 0xDD};
  const Bytes enc = slip_encode(f);
  EXPECT_EQ(enc, (Bytes{0xC0, 0x01, 0xDB, 0xDC, 0xDB, 0xDD, 0x02, 0xDC, 0xDD, 0xC0}));
  SlipDecoder d;
  std::optional<Bytes> got;
  for (std::uint8_t c : enc)
    if (auto x = d.feed(c)) got = x;
  ASSERT_TRUE(got);
  EXPECT_EQ(*got, f);
  EXPECT_FALSE(d.last_bad());
}

TEST(LinkProto, SlipMarksABadEscape) {
  SlipDecoder d;
  std::optional<Bytes> got;
  for (std::uint8_t c : Bytes{0xC0, 0x05, 0xDB, 0x07, 0xC0})
    if (auto x = d.feed(c)) got = x;
  ASSERT_TRUE(got);
  EXPECT_TRUE(d.last_bad());
}

TEST(LinkProto, RequestLayoutIsSeqOpsCrcBigEndian) {
  const Bytes b = make_request(7, {Op{true, 0x24, 0x11223344}, Op{false, 0x2C, 0}});
  // END, seq, write op, 4 data bytes, read op, CRC hi, CRC lo, END
  ASSERT_EQ(b.size(), 1u + 1 + 5 + 1 + 2 + 1);
  EXPECT_EQ(b[1], 7);
  EXPECT_EQ(b[2], 0x80 | 0x24);
  EXPECT_EQ(b[3], 0x11);
  EXPECT_EQ(b[6], 0x44);
  EXPECT_EQ(b[7], 0x2C);
  EXPECT_EQ(crc16(b.data() + 1, b.size() - 2), 0);  // the residue over frame + CRC
}

TEST(LinkProto, ReplyParsesAndRefusesABadCrc) {
  // seq, status, read data, levels, flags, positions X Y Z (big-endian), next seq
  Bytes f{3, 0, 0xDE, 0xAD, 0xBE, 0xEF, 5, 1, 0x02, 0, 0, 1, 2, 0xFF, 0xFF, 0xFF, 0xFE, 0x80, 0, 0, 0, 4};
  const std::uint16_t c = crc16(f.data(), f.size());
  f.push_back(static_cast<std::uint8_t>(c >> 8));
  f.push_back(static_cast<std::uint8_t>(c));
  auto r = parse_reply(f);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->seq, 3);
  ASSERT_EQ(r->data.size(), 1u);
  EXPECT_EQ(r->data[0], 0xDEADBEEFu);
  EXPECT_EQ(r->level3, 5);
  EXPECT_EQ(r->level2, 1);
  EXPECT_TRUE(r->flag(BOARD_FLAG_HOLD));
  EXPECT_EQ(r->pos[0], 258);
  EXPECT_EQ(r->pos[1], -2);
  EXPECT_EQ(r->pos[2], INT32_MIN);
  EXPECT_EQ(r->next_seq, 4);
  f[2] ^= 0x10;
  EXPECT_FALSE(parse_reply(f));
}

TEST(LinkProto, PackedChordFieldsAreTenBitTwosComplement) {
  EXPECT_EQ(*pack_chord(1, -1, 511), 1u | (0x3FFu << 10) | (511u << 20));
  EXPECT_EQ(*pack_chord(-512, 0, 0), 0x200u);
  EXPECT_FALSE(pack_chord(512, 0, 0));
  EXPECT_FALSE(pack_chord(0, 0, -513));
}

}  // namespace
}  // namespace contour::board
