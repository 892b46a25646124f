// The words of one G-code line, as read (no meaning yet): G and M words in
// the order given, every other letter at most once, the column of each.
// Comments, blanks, a leading N number and a trailing ';' comment are
// skipped; a leading '/' marks the line for block delete.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace contour::gcode {

struct Word {
  double value = 0;
  int column = 0;  // 1-based column of the letter
};

struct LineWords {
  std::vector<Word> g, m;
  std::array<std::optional<Word>, 26> letter;  // A..Z except G and M
  int first_column = 0;                        // column of the first word (0: none)
  bool block_delete = false;                   // the line starts with '/'
  bool percent = false;                        // the line is '%'

  const std::optional<Word>& operator[](char c) const { return letter[c - 'A']; }
};

// Reads one line (without its line end). Throws Error(line, column, ...) on
// a character or word it cannot read.
LineWords read_words(std::string_view text, int line);

}  // namespace contour::gcode
