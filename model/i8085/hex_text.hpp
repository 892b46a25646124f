// Upper-case hex text of bytes and addresses, as the disassembler, the trace
// and the runners' messages print them ("0F", "01A0").
#pragma once

#include <cstdio>
#include <string>

namespace i8085 {

inline std::string hex2(unsigned v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%02X", v & 0xFFu);
  return buf;
}

inline std::string hex4(unsigned v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%04X", v & 0xFFFFu);
  return buf;
}

}  // namespace i8085
