// Intel HEX reader for 8085 programs (16-bit address space).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace i8085 {

// A malformed or unsupported HEX file. The message names the file and line.
class HexError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct HexChunk {
  std::uint16_t address = 0;
  std::vector<std::uint8_t> data;
};

struct HexImage {
  std::vector<HexChunk> chunks;          // one per data record, in file order
  std::optional<std::uint32_t> start;    // from a type 03/05 record, if any
  std::size_t size() const;              // total data bytes
  std::uint16_t lowest() const;          // lowest address written (0 if empty)
  // Copies every chunk into a 64 KiB memory image.
  void load_into(std::array<std::uint8_t, 65536>& mem) const;
};

// Parses Intel HEX text. Accepts record types 00 (data), 01 (end of file,
// required), 02/04 (extended address: only 0, the 8085 has 64 KiB) and
// 03/05 (start address). Rejects bad characters, odd digit counts, length
// and checksum mismatches, data past 0xFFFF, a byte defined twice, text after
// the end record. `name` is used in messages ("prog.hex:12: ...").
HexImage parse_hex(std::string_view text, const std::string& name = "<hex>");

// Reads and parses a file; throws HexError if it cannot be read.
HexImage read_hex_file(const std::string& path);

}  // namespace i8085
