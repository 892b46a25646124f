#include "gcode/words.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "gcode/gcode.hpp"

namespace contour::gcode {

namespace {

std::string printable(char c) {
  if (std::isprint(static_cast<unsigned char>(c))) return std::string(1, c);
  char buf[8];
  std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned>(static_cast<unsigned char>(c)));
  return buf;
}

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

// Binary operators by LinuxCNC's precedence: 4 (**), 3 (* / MOD), 2 (+ -),
// 1 (EQ NE GT GE LT LE), 0 (AND OR XOR).
struct BinaryOp {
  const char* name;
  int precedence;
};
constexpr BinaryOp kBinaryOps[] = {{"**", 4}, {"*", 3},  {"/", 3},  {"MOD", 3}, {"+", 2},  {"-", 2},  {"EQ", 1},
                                   {"NE", 1}, {"GT", 1}, {"GE", 1}, {"LT", 1},  {"LE", 1}, {"AND", 0}, {"OR", 0},
                                   {"XOR", 0}};

constexpr double kDeg = std::numbers::pi / 180;

// LinuxCNC 2.9's predefined named parameters (read-only; not kept here).
bool predefined(const std::string& n) {
  static const char* const kNames[] = {
      "_vmajor", "_vminor", "_line", "_motion_mode", "_plane", "_ccomp", "_metric", "_imperial", "_absolute",
      "_incremental", "_inverse_time", "_units_per_minute", "_units_per_rev", "_coord_system", "_tool_offset",
      "_retract_r_plane", "_retract_old_z", "_spindle_rpm_mode", "_spindle_css_mode", "_ijk_absolute_mode",
      "_lathe_diameter_mode", "_lathe_radius_mode", "_spindle_on", "_spindle_cw", "_mist", "_flood",
      "_speed_override", "_feed_override", "_adaptive_feed", "_feed_hold", "_feed", "_rpm", "_x", "_y", "_z",
      "_a", "_b", "_c", "_u", "_v", "_w", "_abs_x", "_abs_y", "_abs_z", "_abs_a", "_abs_b", "_abs_c",
      "_abs_u", "_abs_v", "_abs_w", "_current_tool", "_current_pocket", "_selected_tool", "_selected_pocket",
      "_value", "_value_returned", "_task", "_call_level", "_remap_level"};
  for (const char* k : kNames)
    if (n == k) return true;
  return false;
}

class LineReader {
 public:
  LineReader(std::string_view text, int line, const Params* params) : s_(text), line_(line), params_(params) {}

  // The bracketed expression at pos (after blanks); pos moves past it.
  double expression_at(std::size_t& pos) {
    pos_ = pos;
    skip_blank();
    if (peek() != '[') fail("expected '[' (an expression)");
    const double v = bracketed(0);
    pos = pos_;
    return v;
  }

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
      if (s_[pos_] == '#' && params_) {
        w.assignments.push_back(assignment());
        first = false;
        continue;
      }
      first = word(w, first);
    }
    return w;
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw Error(line_, column(), problem); }
  [[noreturn]] void fail_at(int col, const std::string& problem) const { throw Error(line_, col, problem); }

  // One word (a letter and its value); returns false (no longer first).
  bool word(LineWords& w, bool first) {
    const int col = column();
    const char raw = s_[pos_];
    if (!std::isalpha(static_cast<unsigned char>(raw))) fail(not_a_word(raw));
    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(raw)));
    if (c == 'O') fail("an O-word must begin its line");
    ++pos_;
    const double v = value(c, col);
    if (c == 'N') {
      if (!first) fail_at(col, "line number N must be the first word of the line");
      if (v < 0 || v != std::floor(v)) fail_at(col, "line number N must be a whole number >= 0");
      return false;
    }
    if (w.first_column == 0) w.first_column = col;
    put(w, c, Word{v, col});
    return false;
  }

  // Why a character that is not a letter cannot start a word.
  std::string not_a_word(char c) const {
    switch (c) {
      case ')': return "')' without a matching '('";
      case '#': return "parameters ('#') are not supported here";
      case '[': return "an expression ('[') must be the value of a word";
      case '@': case '^': return "polar coordinates ('@', '^') are not supported";
      default: return std::string("unexpected character '") + printable(c) + "' (a word starts with a letter)";
    }
  }

  void put(LineWords& w, char c, const Word& word) const {
    if (c == 'G') return w.g.push_back(word);
    if (c == 'M') return w.m.push_back(word);
    auto& slot = w.letter[c - 'A'];
    if (slot) fail_at(word.column, std::string("two ") + c + " words in one line");
    slot = word;
  }

  int column() const { return static_cast<int>(pos_) + 1; }
  char peek() const { return pos_ < s_.size() ? s_[pos_] : '\0'; }
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

  // The value of a word: a number, or with parameters a parameter, an
  // expression or a function, optionally signed.
  double value(char letter, int letter_col) {
    skip_blank();
    if (!params_) return number(letter, letter_col);
    const char c = peek();
    if (c == '[' || c == '#' || function_follows()) return operand(0);
    if ((c == '+' || c == '-') && !number_follows()) {
      ++pos_;
      skip_blank();
      const double v = operand(0);
      return c == '-' ? -v : v;
    }
    return number(letter, letter_col);
  }

  // A function name (then '[') at the cursor.
  bool function_follows() const {
    static const char* const kNames[] = {"ABS", "ACOS", "ASIN", "ATAN", "COS", "EXISTS", "EXP", "FIX",
                                         "FUP", "LN",   "ROUND", "SIN", "SQRT", "TAN"};
    std::string n;
    for (std::size_t p = pos_; p < s_.size() && std::isalpha(static_cast<unsigned char>(s_[p])); ++p)
      n += static_cast<char>(std::toupper(static_cast<unsigned char>(s_[p])));
    for (const char* k : kNames)
      if (n == k) return true;
    return false;
  }

  bool number_follows() const {
    std::size_t p = pos_ + 1;
    while (p < s_.size() && (s_[p] == ' ' || s_[p] == '\t')) ++p;
    return p < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[p])) || s_[p] == '.');
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
        fail(std::string("the value of '") + letter + "' is a parameter or expression (not supported here)");
      fail_at(letter_col, std::string("word '") + letter + "' has no number");
    }
    if (n_int + n_frac > 30) fail_at(static_cast<int>(start) + 1, std::string("number of '") + letter + "' is too long");
    const double v = std::strtod(digits.c_str(), nullptr);
    if (!std::isfinite(v)) fail_at(static_cast<int>(start) + 1, std::string("number of '") + letter + "' is out of range");
    return v;
  }

  // An operand: [expr], #param, FUNC[expr], a signed operand or a number.
  double operand(int depth) {
    if (depth > kMaxExpressionDepth) fail("expression nested deeper than 64 levels");
    skip_blank();
    const char c = peek();
    if (c == '[') return bracketed(depth + 1);
    if (c == '#') return parameter_value(depth + 1);
    if (c == '-' || c == '+') {
      ++pos_;
      const double v = operand(depth + 1);
      return c == '-' ? -v : v;
    }
    if (std::isalpha(static_cast<unsigned char>(c))) return function(depth + 1);
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number('#', column());
    if (c == '\0') fail("expression ends early");
    fail(std::string("unexpected character '") + printable(c) + "' in an expression");
  }

  double bracketed(int depth) {
    ++pos_;  // '['
    const double v = expression(depth, 0);
    skip_blank();
    if (peek() != ']') fail("expected ']'");
    ++pos_;
    return v;
  }

  // Precedence climbing over kBinaryOps.
  double expression(int depth, int min_prec) {
    double lhs = operand(depth);
    while (true) {
      skip_blank();
      const int op_col = column();
      const BinaryOp* op = match_binary();
      if (!op || op->precedence < min_prec) {
        if (op) pos_ -= std::string_view(op->name).size();
        return lhs;
      }
      const double rhs = expression(depth + 1, op->precedence + 1);
      lhs = apply(*op, lhs, rhs, op_col);
    }
  }

  const BinaryOp* match_binary() {
    for (const BinaryOp& op : kBinaryOps) {
      const std::string_view n(op.name);
      if (s_.size() - pos_ < n.size()) continue;
      bool same = true;
      for (std::size_t k = 0; k < n.size(); ++k)
        same = same && std::toupper(static_cast<unsigned char>(s_[pos_ + k])) == n[k];
      if (same) {
        pos_ += n.size();
        return &op;
      }
    }
    return nullptr;
  }

  double apply(const BinaryOp& op, double a, double b, int col) const {
    const std::string n = op.name;
    double v = 0;
    if (n == "**") {
      if (a < 0 && b != std::floor(b)) fail_at(col, "negative number to a fractional power");
      v = std::pow(a, b);
    } else if (n == "*") v = a * b;
    else if (n == "/" || n == "MOD") {
      if (b == 0) fail_at(col, "division by zero");
      v = n == "/" ? a / b : a - b * std::floor(a / b);
    } else if (n == "+") v = a + b;
    else if (n == "-") v = a - b;
    else if (n == "EQ") v = a == b;
    else if (n == "NE") v = a != b;
    else if (n == "GT") v = a > b;
    else if (n == "GE") v = a >= b;
    else if (n == "LT") v = a < b;
    else if (n == "LE") v = a <= b;
    else if (n == "AND") v = (a != 0) && (b != 0);
    else if (n == "OR") v = (a != 0) || (b != 0);
    else v = (a != 0) != (b != 0);
    if (!std::isfinite(v)) fail_at(col, "expression result is out of range");
    return v;
  }

  std::string name_at() {
    std::string n;
    while (std::isalpha(static_cast<unsigned char>(peek()))) n += static_cast<char>(std::toupper(s_[pos_++]));
    return n;
  }

  double function(int depth) {
    const int col = column();
    const std::string f = name_at();
    skip_blank();
    if (f == "EXISTS") return exists();
    if (peek() != '[') fail_at(col, "unknown function or word '" + f + "' in an expression");
    const double a = bracketed(depth);
    if (f == "ATAN") {
      skip_blank();
      if (peek() != '/') fail("ATAN needs two arguments: ATAN[y]/[x]");
      ++pos_;
      skip_blank();
      if (peek() != '[') fail("ATAN needs two arguments: ATAN[y]/[x]");
      return std::atan2(a, bracketed(depth)) / kDeg;
    }
    return unary(f, a, col);
  }

  double unary(const std::string& f, double a, int col) const {
    auto domain = [&](bool ok) {
      if (!ok) fail_at(col, f + " of " + fmt(a) + " is undefined");
    };
    if (f == "ABS") return std::fabs(a);
    if (f == "ACOS") return domain(a >= -1 && a <= 1), std::acos(a) / kDeg;
    if (f == "ASIN") return domain(a >= -1 && a <= 1), std::asin(a) / kDeg;
    if (f == "COS") return std::cos(a * kDeg);
    if (f == "SIN") return std::sin(a * kDeg);
    if (f == "TAN") return std::tan(a * kDeg);
    if (f == "EXP") {
      const double v = std::exp(a);
      return domain(std::isfinite(v)), v;
    }
    if (f == "FIX") return std::floor(a);
    if (f == "FUP") return std::ceil(a);
    if (f == "LN") return domain(a > 0), std::log(a);
    if (f == "ROUND") return std::round(a);
    if (f == "SQRT") return domain(a >= 0), std::sqrt(a);
    fail_at(col, "unknown function '" + f + "'");
  }

  // EXISTS[#<name>]: 1 when the named parameter is set.
  double exists() {
    if (peek() != '[') fail("EXISTS needs [#<name>]");
    ++pos_;
    skip_blank();
    if (peek() != '#') fail("EXISTS needs [#<name>]");
    ++pos_;
    const std::string n = param_name();
    skip_blank();
    if (peek() != ']') fail("expected ']'");
    ++pos_;
    return params_->named.count(n) ? 1 : 0;
  }

  // After '#': '<name>' or a value (the number of the parameter).
  std::string param_name() {
    skip_blank();
    if (peek() != '<') fail("expected '<' of a parameter name");
    const std::size_t close = s_.find('>', pos_);
    if (close == std::string_view::npos) fail("parameter name '<' is not closed with '>'");
    std::string n;
    for (std::size_t k = pos_ + 1; k < close; ++k)
      if (s_[k] != ' ' && s_[k] != '\t') n += static_cast<char>(std::tolower(static_cast<unsigned char>(s_[k])));
    if (n.empty()) fail("empty parameter name");
    pos_ = close + 1;
    return n;
  }

  int param_number(int depth) {
    const int col = column();
    const double v = operand(depth);
    if (v != std::floor(v) || v < 1) fail_at(col, "parameter number must be a whole number >= 1 (got " + fmt(v) + ")");
    if (v >= Params::kNumbered)
      fail_at(col, "system parameter #" + fmt(v).substr(0, fmt(v).find('.')) + " is not supported (#1..#5399)");
    return static_cast<int>(v);
  }

  double parameter_value(int depth) {
    const int col = column();
    ++pos_;  // '#'
    skip_blank();
    if (peek() == '<') {
      const std::string n = param_name();
      if (predefined(n)) fail_at(col, "predefined parameter #<" + n + "> is not supported");
      const auto it = params_->named.find(n);
      if (it == params_->named.end()) fail_at(col, "named parameter #<" + n + "> is not set");
      return it->second;
    }
    return params_->numbered[param_number(depth)];
  }

  Assignment assignment() {
    ++pos_;  // '#'
    Assignment a;
    skip_blank();
    const int col = column();
    if (peek() == '<') a.name = param_name();
    else a.number = param_number(1);
    if (predefined(a.name)) fail_at(col, "cannot assign to read-only parameter #<" + a.name + ">");
    skip_blank();
    if (peek() != '=') fail("expected '=' after the parameter");
    ++pos_;
    skip_blank();
    a.value = (peek() == '+' || peek() == '-') && number_follows() ? number('#', column()) : operand(0);
    return a;
  }

  std::string_view s_;
  int line_;
  const Params* params_;
  std::size_t pos_ = 0;
};

}  // namespace

LineWords read_words(std::string_view text, int line, const Params* params) {
  return LineReader(text, line, params).read();
}

double read_expression(std::string_view text, int line, std::size_t& pos, const Params& params) {
  return LineReader(text, line, &params).expression_at(pos);
}

}  // namespace contour::gcode
