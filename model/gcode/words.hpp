// The words of one G-code line, as read (no meaning yet): G and M words in
// the order given, every other letter at most once, the column of each.
// Comments, blanks, a leading N number and a trailing ';' comment are
// skipped; a leading '/' marks the line for block delete.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace contour::gcode {

struct Word {
  double value = 0;
  int column = 0;  // 1-based column of the letter
};

// Parameters (LinuxCNC's '#'): numbered #1..#5399 (0 until set) and named
// #<name> (blanks removed, case folded; an error until set). System
// parameters (#5400 and up) are not supported.
struct Params {
  static constexpr int kNumbered = 5400;
  std::vector<double> numbered = std::vector<double>(kNumbered, 0.0);
  std::map<std::string, double> named;
};

// A parameter setting of a line ('#1 = 2.5', '#<depth> = [#1 * 2]'):
// settings take effect after the whole line is read (LinuxCNC: '#1=1 #2=#1'
// sets #2 to the old #1).
struct Assignment {
  int number = 0;    // numbered, or 0
  std::string name;  // named
  double value = 0;
};

struct LineWords {
  std::vector<Word> g, m;
  std::array<std::optional<Word>, 26> letter;  // A..Z except G and M
  int first_column = 0;                        // column of the first word (0: none)
  bool block_delete = false;                   // the line starts with '/'
  bool percent = false;                        // the line is '%'
  std::vector<Assignment> assignments;         // parameter settings, in order

  const std::optional<Word>& operator[](char c) const { return letter[c - 'A']; }
};

// The bound on expression nesting ('[' inside '[', function inside
// function): deeper is an error, not a stack overflow.
constexpr int kMaxExpressionDepth = 64;

// Reads one line (without its line end). Throws Error(line, column, ...) on
// a character or word it cannot read. With params, word values may be
// parameters, expressions '[...]' with LinuxCNC's operators (** * / MOD + -
// EQ NE GT GE LT LE AND OR XOR) and functions (ABS ACOS ASIN ATAN[y]/[x]
// COS EXP FIX FUP LN ROUND SIN SQRT TAN EXISTS; angles in degrees), and the
// line may set parameters; without (a tool table) '#' and '[' are refused.
LineWords read_words(std::string_view text, int line, const Params* params = nullptr);

// The expression '[...]' at text[pos] (blanks before it skipped); pos moves
// past it. Throws Error like read_words.
double read_expression(std::string_view text, int line, std::size_t& pos, const Params& params);

}  // namespace contour::gcode
