// hex2memh: converts an asm80 Intel HEX file into the $readmemh image of the
// board's 8 KiB ROM (rtl/board8085/board8085_rom.v): 8192 lines of two hex
// digits, unprogrammed bytes 0xFF.
//
//   hex2memh IN.hex OUT.memh
//
// Exit status 0, or 1 with one line on stderr naming the file and the
// problem (unreadable or malformed HEX, a byte outside 0x0000-0x1FFF).
#include <array>
#include <cstdio>
#include <exception>
#include <fstream>

#include "i8085/hex.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: hex2memh IN.hex OUT.memh\n");
    return 2;
  }
  constexpr std::size_t kRomSize = 0x2000;
  try {
    const i8085::HexImage img = i8085::read_hex_file(argv[1]);
    std::array<std::uint8_t, kRomSize> rom;
    rom.fill(0xFF);
    for (const i8085::HexChunk& c : img.chunks) {
      for (std::size_t i = 0; i < c.data.size(); ++i) {
        const std::size_t a = c.address + i;
        if (a >= kRomSize) {
          std::fprintf(stderr, "hex2memh: %s: byte at 0x%04zX is outside the board ROM (0x0000-0x1FFF)\n",
                       argv[1], a);
          return 1;
        }
        rom[a] = c.data[i];
      }
    }
    std::ofstream out(argv[2]);
    if (!out) {
      std::fprintf(stderr, "hex2memh: cannot write %s\n", argv[2]);
      return 1;
    }
    char buf[4];
    for (std::uint8_t b : rom) {
      std::snprintf(buf, sizeof buf, "%02X", b);
      out << buf << '\n';
    }
    out.close();
    if (!out) {
      std::fprintf(stderr, "hex2memh: error writing %s\n", argv[2]);
      return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hex2memh: %s\n", e.what());
    return 1;
  }
  return 0;
}
