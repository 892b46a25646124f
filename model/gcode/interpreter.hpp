// The line interpreter behind gcode::read (interpreter.cpp): runs one line
// at a time, in LinuxCNC's order of execution, into the program's blocks
// and events; program.cpp drives it line by line (O-word control flow).
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>

#include "gcode/gcode.hpp"
#include "gcode/words.hpp"

namespace contour::gcode {

class Interpreter;

class LineRunner {
 public:
  explicit LineRunner(const Options& o);
  ~LineRunner();
  // Runs one line (no O-word); false after M2/M30.
  bool line(std::string_view text, int lineno);
  Params& params();
  std::size_t blocks() const;  // motion blocks and dwells so far
  Program take();

 private:
  std::unique_ptr<Interpreter> impl_;
};

}  // namespace contour::gcode
