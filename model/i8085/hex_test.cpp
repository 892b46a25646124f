// Intel HEX reader: records written by asm80 (an independent tool), and
// every malformed input it must reject with the line named.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "i8085/hex.hpp"

namespace i8085 {
namespace {

// A record with its checksum (two's complement of the byte sum).
std::string record(std::uint8_t type, std::uint16_t addr, const std::vector<std::uint8_t>& data) {
  std::vector<std::uint8_t> b = {static_cast<std::uint8_t>(data.size()), static_cast<std::uint8_t>(addr >> 8),
                                 static_cast<std::uint8_t>(addr), type};
  b.insert(b.end(), data.begin(), data.end());
  unsigned sum = 0;
  for (auto x : b) sum += x;
  b.push_back(static_cast<std::uint8_t>(-sum));
  std::string s = ":";
  char buf[4];
  for (auto x : b) {
    std::snprintf(buf, sizeof buf, "%02X", x);
    s += buf;
  }
  return s;
}

const std::string kEof = ":00000001FF";

// The first lines asm80 1.11.14 wrote for a small test file (MVI A,12h;
// RIM; SIM; LXI H,010A; OUT 0; HLT; DB "hi$"; DS 3; DW 0100h), no final
// newline.
const std::string kAsm80 = ":0D0100003E122030210A01D30076686924E8\n:020110000001EC\n:00000001FF";

std::string message_of(const std::string& text) {
  try {
    parse_hex(text, "t.hex");
  } catch (const HexError& e) {
    return e.what();
  }
  return "";
}

TEST(Hex, ReadsAsm80Output) {
  const HexImage img = parse_hex(kAsm80, "t.hex");
  ASSERT_EQ(img.chunks.size(), 2u);
  EXPECT_EQ(img.chunks[0].address, 0x0100);
  EXPECT_EQ(img.chunks[0].data,
            (std::vector<std::uint8_t>{0x3E, 0x12, 0x20, 0x30, 0x21, 0x0A, 0x01, 0xD3, 0x00, 0x76, 0x68, 0x69, 0x24}));
  EXPECT_EQ(img.chunks[1].address, 0x0110);
  EXPECT_EQ(img.size(), 15u);
  EXPECT_EQ(img.lowest(), 0x0100);
  std::array<std::uint8_t, 65536> mem{};
  img.load_into(mem);
  EXPECT_EQ(mem[0x0100], 0x3E);
  EXPECT_EQ(mem[0x0111], 0x01);
  EXPECT_EQ(mem[0x010D], 0x00);  // DS leaves a gap
}

TEST(Hex, AcceptsCrLfBlankLinesAndLowerCase) {
  const std::string text = "\r\n" + record(0, 0x0000, {0xAB, 0xCD}) + "\r\n\r\n:00000001ff\r\n";
  const HexImage img = parse_hex(text);
  ASSERT_EQ(img.chunks.size(), 1u);
  EXPECT_EQ(img.chunks[0].data[1], 0xCD);
}

TEST(Hex, ZeroExtendedAddressAndStartRecordsAreAccepted) {
  const std::string text = record(4, 0, {0, 0}) + "\n" + record(2, 0, {0, 0}) + "\n" +
                           record(3, 0, {0, 0, 0x01, 0x00}) + "\n" + record(0, 0x10, {1}) + "\n" + kEof + "\n";
  const HexImage img = parse_hex(text);
  ASSERT_TRUE(img.start.has_value());
  EXPECT_EQ(*img.start, 0x0100u);
}

TEST(Hex, RejectsBadChecksum) {
  std::string r = record(0, 0x0100, {1, 2, 3});
  r.back() = r.back() == '0' ? '1' : '0';
  EXPECT_EQ(message_of(r + "\n" + kEof), "t.hex:1: checksum mismatch");
}

TEST(Hex, RejectsMissingEndRecord) {
  EXPECT_EQ(message_of(record(0, 0, {1}) + "\n"), "t.hex:2: missing end-of-file record (:00000001FF)");
}

TEST(Hex, RejectsMissingColon) {
  EXPECT_EQ(message_of(kEof + "\n").empty(), true);
  EXPECT_EQ(message_of("00000001FF\n"), "t.hex:1: a record must start with ':'");
}

TEST(Hex, RejectsNonHexAndOddDigits) {
  EXPECT_EQ(message_of(":0G000001FF\n"), "t.hex:1: '0G' is not a hex byte");
  EXPECT_EQ(message_of(":00000001F\n"), "t.hex:1: odd number of hex digits");
}

TEST(Hex, RejectsLengthMismatch) {
  // Length 02 but one data byte.
  EXPECT_EQ(message_of(":0200000001FD\n" + kEof), "t.hex:1: length byte says 2 data bytes, record has 1");
}

TEST(Hex, RejectsDataPastFFFF) {
  EXPECT_EQ(message_of(record(0, 0xFFFF, {1, 2}) + "\n" + kEof), "t.hex:1: data runs past address FFFF");
}

TEST(Hex, RejectsAByteDefinedTwice) {
  const std::string text = record(0, 0x0100, {1, 2}) + "\n" + record(0, 0x0101, {3}) + "\n" + kEof;
  EXPECT_EQ(message_of(text), "t.hex:2: address 0101 is defined twice");
}

TEST(Hex, RejectsAddressesBeyond64K) {
  EXPECT_EQ(message_of(record(4, 0, {0, 1}) + "\n" + kEof),
            "t.hex:1: extended address beyond 64 KiB (the 8085 has a 16-bit bus)");
}

TEST(Hex, RejectsTextAfterTheEnd) {
  EXPECT_EQ(message_of(kEof + "\n" + record(0, 0, {1})), "t.hex:2: text after the end-of-file record");
}

TEST(Hex, RejectsUnknownType) {
  EXPECT_EQ(message_of(record(6, 0, {}) + "\n" + kEof), "t.hex:1: unknown record type 6");
}

TEST(Hex, MissingFileIsAnError) {
  EXPECT_THROW(read_hex_file("/nonexistent/x.hex"), HexError);
}

}  // namespace
}  // namespace i8085
