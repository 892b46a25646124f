#include "i8085/hex.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace i8085 {

namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

[[noreturn]] void fail(const std::string& name, std::size_t line, const std::string& what) {
  throw HexError(name + ":" + std::to_string(line) + ": " + what);
}

}  // namespace

std::size_t HexImage::size() const {
  std::size_t n = 0;
  for (const auto& c : chunks) n += c.data.size();
  return n;
}

std::uint16_t HexImage::lowest() const {
  std::uint32_t low = 0x10000;
  for (const auto& c : chunks)
    if (!c.data.empty() && c.address < low) low = c.address;
  return low == 0x10000 ? 0 : static_cast<std::uint16_t>(low);
}

void HexImage::load_into(std::array<std::uint8_t, 65536>& mem) const {
  for (const auto& c : chunks)
    for (std::size_t i = 0; i < c.data.size(); ++i) mem[(c.address + i) & 0xFFFF] = c.data[i];
}

HexImage parse_hex(std::string_view text, const std::string& name) {
  HexImage img;
  std::vector<bool> defined(65536, false);
  bool ended = false;
  std::size_t line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    std::string_view line = text.substr(pos, eol - pos);
    pos = eol + 1;
    ++line_no;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
      line.remove_suffix(1);
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    if (line.empty()) {
      if (eol == text.size()) break;
      continue;
    }
    if (ended) fail(name, line_no, "text after the end-of-file record");
    if (line.front() != ':') fail(name, line_no, "a record must start with ':'");
    line.remove_prefix(1);
    if (line.size() % 2 != 0) fail(name, line_no, "odd number of hex digits");
    std::vector<std::uint8_t> bytes;
    for (std::size_t i = 0; i < line.size(); i += 2) {
      const int hi = hex_digit(line[i]), lo = hex_digit(line[i + 1]);
      if (hi < 0 || lo < 0)
        fail(name, line_no, "'" + std::string(line.substr(i, 2)) + "' is not a hex byte");
      bytes.push_back(static_cast<std::uint8_t>(hi << 4 | lo));
    }
    if (bytes.size() < 5) fail(name, line_no, "record shorter than 5 bytes");
    const std::size_t len = bytes[0];
    if (bytes.size() != len + 5)
      fail(name, line_no,
           "length byte says " + std::to_string(len) + " data bytes, record has " +
               std::to_string(bytes.size() - 5));
    unsigned sum = 0;
    for (auto b : bytes) sum += b;
    if ((sum & 0xFF) != 0) fail(name, line_no, "checksum mismatch");
    const std::uint32_t addr = static_cast<std::uint32_t>(bytes[1] << 8 | bytes[2]);
    const std::uint8_t type = bytes[3];
    const std::uint8_t* data = bytes.data() + 4;
    switch (type) {
      case 0x00: {
        if (addr + len > 0x10000) fail(name, line_no, "data runs past address FFFF");
        HexChunk chunk;
        chunk.address = static_cast<std::uint16_t>(addr);
        for (std::size_t i = 0; i < len; ++i) {
          if (defined[addr + i]) {
            char a[8];
            std::snprintf(a, sizeof a, "%04X", static_cast<unsigned>(addr + i));
            fail(name, line_no, std::string("address ") + a + " is defined twice");
          }
          defined[addr + i] = true;
          chunk.data.push_back(data[i]);
        }
        if (len != 0) img.chunks.push_back(std::move(chunk));
        break;
      }
      case 0x01:
        if (len != 0) fail(name, line_no, "end-of-file record with data");
        ended = true;
        break;
      case 0x02:
      case 0x04:
        if (len != 2) fail(name, line_no, "extended address record needs 2 data bytes");
        if (data[0] != 0 || data[1] != 0)
          fail(name, line_no, "extended address beyond 64 KiB (the 8085 has a 16-bit bus)");
        break;
      case 0x03:
      case 0x05:
        if (len != 4) fail(name, line_no, "start address record needs 4 data bytes");
        img.start = type == 0x05
                        ? static_cast<std::uint32_t>(data[0] << 24 | data[1] << 16 | data[2] << 8 | data[3])
                        : static_cast<std::uint32_t>((data[0] << 8 | data[1]) * 16 + (data[2] << 8 | data[3]));
        break;
      default:
        fail(name, line_no, "unknown record type " + std::to_string(type));
    }
    if (eol == text.size()) break;
  }
  if (!ended) fail(name, line_no, "missing end-of-file record (:00000001FF)");
  return img;
}

HexImage read_hex_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw HexError(path + ": cannot open");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_hex(ss.str(), path);
}

}  // namespace i8085
