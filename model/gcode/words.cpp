#include "gcode/words.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "gcode/gcode.hpp"

namespace contour::gcode {

namespace {

std::string printable(char c) {
  if (std::isprint(static_cast<unsigned char>(c))) return std::string(1, c);
  char buf[8];
  std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned>(static_cast<unsigned char>(c)));
  return buf;
}

// Why a character that is not a letter cannot start a word.
std::string not_a_word(char c) {
  switch (c) {
    case ')': return "')' without a matching '('";
    case '#': return "parameters ('#') are not supported";
    case '[': return "expressions ('[') are not supported";
    case '@': case '^': return "polar coordinates ('@', '^') are not supported";
    default: return std::string("unexpected character '") + printable(c) + "' (a word starts with a letter)";
  }
}

class LineReader {
 public:
  LineReader(std::string_view text, int line) : s_(text), line_(line) {}

  LineWords read() {
    LineWords w;
    skip_blank();
    if (pos_ < s_.size() && s_[pos_] == '/') w.block_delete = true, ++pos_;
    skip_blank();
    if (!w.block_delete && pos_ < s_.size() && s_[pos_] == '%') {
      ++pos_;
      skip_blank();
      if (pos_ < s_.size() && s_[pos_] != ';') fail("text after '%' (a '%' line holds nothing else)");
      w.percent = true;
      return w;
    }
    bool first = true;
    while (true) {
      skip_blank_and_comments();
      if (pos_ >= s_.size() || s_[pos_] == ';') break;
      const int col = column();
      const char raw = s_[pos_];
      if (!std::isalpha(static_cast<unsigned char>(raw))) fail(not_a_word(raw));
      const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(raw)));
      if (c == 'O') fail("O-words (subroutines, loops) are not supported");
      ++pos_;
      const double v = number(c, col);
      if (c == 'N') {
        if (!first) fail_at(col, "line number N must be the first word of the line");
        if (v < 0 || v != std::floor(v)) fail_at(col, "line number N must be a whole number >= 0");
        first = false;
        continue;
      }
      first = false;
      if (w.first_column == 0) w.first_column = col;
      put(w, c, Word{v, col});
    }
    return w;
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw Error(line_, column(), problem); }
  [[noreturn]] void fail_at(int col, const std::string& problem) const { throw Error(line_, col, problem); }

  void put(LineWords& w, char c, const Word& word) const {
    if (c == 'G') return w.g.push_back(word);
    if (c == 'M') return w.m.push_back(word);
    auto& slot = w.letter[c - 'A'];
    if (slot) fail_at(word.column, std::string("two ") + c + " words in one line");
    slot = word;
  }
  int column() const { return static_cast<int>(pos_) + 1; }
  void skip_blank() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\r')) ++pos_;
  }
  void skip_blank_and_comments() {
    while (true) {
      skip_blank();
      if (pos_ < s_.size() && s_[pos_] == '(') {
        const int col = column();
        const auto close = s_.find_first_of("()", pos_ + 1);
        if (close == std::string_view::npos) fail_at(col, "comment '(' is not closed on its line");
        if (s_[close] == '(') fail_at(static_cast<int>(close) + 1, "'(' inside a comment (comments do not nest)");
        pos_ = close + 1;
        continue;
      }
      return;
    }
  }
  double number(char letter, int letter_col) {
    skip_blank();
    const std::size_t start = pos_;
    std::string digits;
    if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) digits += s_[pos_++];
    skip_blank();
    std::size_t n_int = 0, n_frac = 0;
    while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) digits += s_[pos_++], ++n_int;
    if (pos_ < s_.size() && s_[pos_] == '.') {
      digits += s_[pos_++];
      while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) digits += s_[pos_++], ++n_frac;
    }
    if (n_int + n_frac == 0) {
      if (pos_ < s_.size() && (s_[pos_] == '#' || s_[pos_] == '['))
        fail(std::string("the value of '") + letter + "' is a parameter or expression (not supported)");
      fail_at(letter_col, std::string("word '") + letter + "' has no number");
    }
    if (n_int + n_frac > 30) fail_at(static_cast<int>(start) + 1, std::string("number of '") + letter + "' is too long");
    const double v = std::strtod(digits.c_str(), nullptr);
    if (!std::isfinite(v)) fail_at(static_cast<int>(start) + 1, std::string("number of '") + letter + "' is out of range");
    return v;
  }

  std::string_view s_;
  int line_;
  std::size_t pos_ = 0;
};

}  // namespace

LineWords read_words(std::string_view text, int line) { return LineReader(text, line).read(); }

}  // namespace contour::gcode
