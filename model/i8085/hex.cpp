#include "i8085/hex.hpp"

#include <fstream>
#include <sstream>

#include "i8085/hex_text.hpp"

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

// A line without its surrounding blanks (and a CR before the newline).
std::string_view trim(std::string_view line) {
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
  while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
  return line;
}

// The bytes of one record ":LLAAAATT<data>CC", its length and checksum
// checked.
std::vector<std::uint8_t> decode_record(std::string_view line, const std::string& name, std::size_t line_no) {
  if (line.front() != ':') fail(name, line_no, "a record must start with ':'");
  line.remove_prefix(1);
  if (line.size() % 2 != 0) fail(name, line_no, "odd number of hex digits");
  std::vector<std::uint8_t> bytes;
  for (std::size_t i = 0; i < line.size(); i += 2) {
    const int hi = hex_digit(line[i]), lo = hex_digit(line[i + 1]);
    if (hi < 0 || lo < 0) fail(name, line_no, "'" + std::string(line.substr(i, 2)) + "' is not a hex byte");
    bytes.push_back(static_cast<std::uint8_t>(hi << 4 | lo));
  }
  if (bytes.size() < 5) fail(name, line_no, "record shorter than 5 bytes");
  const std::size_t len = bytes[0];
  if (bytes.size() != len + 5)
    fail(name, line_no,
         "length byte says " + std::to_string(len) + " data bytes, record has " + std::to_string(bytes.size() - 5));
  unsigned sum = 0;
  for (auto b : bytes) sum += b;
  if ((sum & 0xFF) != 0) fail(name, line_no, "checksum mismatch");
  return bytes;
}

// Reads decoded records into an image; remembers which addresses are taken
// and whether the end record was seen.
class RecordReader {
 public:
  RecordReader(HexImage& img, const std::string& name) : img_(img), name_(name) {}
  bool ended() const { return ended_; }

  void read(const std::vector<std::uint8_t>& bytes, std::size_t line_no) {
    const std::size_t len = bytes[0];
    const std::uint32_t addr = static_cast<std::uint32_t>(bytes[1] << 8 | bytes[2]);
    const std::uint8_t type = bytes[3];
    const std::uint8_t* data = bytes.data() + 4;
    switch (type) {
      case 0x00: read_data(addr, data, len, line_no); break;
      case 0x01:
        if (len != 0) fail(name_, line_no, "end-of-file record with data");
        ended_ = true;
        break;
      case 0x02:
      case 0x04:
        if (len != 2) fail(name_, line_no, "extended address record needs 2 data bytes");
        if (data[0] != 0 || data[1] != 0)
          fail(name_, line_no, "extended address beyond 64 KiB (the 8085 has a 16-bit bus)");
        break;
      case 0x03:
      case 0x05:
        if (len != 4) fail(name_, line_no, "start address record needs 4 data bytes");
        img_.start = type == 0x05
                         ? static_cast<std::uint32_t>(data[0] << 24 | data[1] << 16 | data[2] << 8 | data[3])
                         : static_cast<std::uint32_t>((data[0] << 8 | data[1]) * 16 + (data[2] << 8 | data[3]));
        break;
      default:
        fail(name_, line_no, "unknown record type " + std::to_string(type));
    }
  }

 private:
  void read_data(std::uint32_t addr, const std::uint8_t* data, std::size_t len, std::size_t line_no) {
    if (addr + len > 0x10000) fail(name_, line_no, "data runs past address FFFF");
    HexChunk chunk;
    chunk.address = static_cast<std::uint16_t>(addr);
    for (std::size_t i = 0; i < len; ++i) {
      const std::size_t a = addr + i;
      if (defined_[a]) fail(name_, line_no, "address " + hex4(static_cast<unsigned>(a)) + " is defined twice");
      defined_[a] = true;
      chunk.data.push_back(data[i]);
    }
    if (len != 0) img_.chunks.push_back(std::move(chunk));
  }

  HexImage& img_;
  const std::string& name_;
  std::vector<bool> defined_ = std::vector<bool>(65536, false);
  bool ended_ = false;
};

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
  RecordReader reader(img, name);
  std::size_t line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    const std::string_view line = trim(text.substr(pos, eol - pos));
    pos = eol + 1;
    ++line_no;
    if (line.empty()) {
      if (eol == text.size()) break;
      continue;
    }
    if (reader.ended()) fail(name, line_no, "text after the end-of-file record");
    reader.read(decode_record(line, name, line_no), line_no);
    if (eol == text.size()) break;
  }
  if (!reader.ended()) fail(name, line_no, "missing end-of-file record (:00000001FF)");
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
