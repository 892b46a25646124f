// gcode::read: the program's lines ('%' delimiters), O-word control flow
// (sub/endsub/call/return, if/elseif/else/endif, while/endwhile, do/while,
// repeat/endrepeat, break/continue) and the bounds against runaway
// programs; every other line goes to the line interpreter.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "gcode/gcode.hpp"
#include "gcode/interpreter.hpp"
#include "gcode/words.hpp"

namespace contour::gcode {

namespace {

// An O-word line: 'O<label> keyword [expression...]'.
struct OWord {
  std::string label;    // "100" or "<name>" (case folded)
  std::string keyword;  // sub, endsub, call, if, ...
  std::size_t rest = 0; // position after the keyword (arguments, condition)
  int column = 0;
};

// The O-word at the start of a line (after blanks and an N number), if any.
std::optional<OWord> o_word(std::string_view s, int lineno) {
  std::size_t p = s.find_first_not_of(" \t\r");
  if (p == std::string_view::npos) return std::nullopt;
  if (std::toupper(static_cast<unsigned char>(s[p])) == 'N') {  // a line number may come first
    std::size_t q = p + 1;
    while (q < s.size() && (std::isdigit(static_cast<unsigned char>(s[q])) || s[q] == ' ')) ++q;
    if (q < s.size() && std::toupper(static_cast<unsigned char>(s[q])) == 'O') p = q;
  }
  if (std::toupper(static_cast<unsigned char>(s[p])) != 'O') return std::nullopt;
  OWord o;
  o.column = static_cast<int>(p) + 1;
  std::size_t q = p + 1;
  while (q < s.size() && (s[q] == ' ' || s[q] == '\t')) ++q;
  if (q < s.size() && s[q] == '<') {
    const auto close = s.find('>', q);
    if (close == std::string_view::npos) throw Error(lineno, static_cast<int>(q) + 1, "O-word name '<' is not closed");
    for (std::size_t k = q; k <= close; ++k)
      if (s[k] != ' ' && s[k] != '\t') o.label += static_cast<char>(std::tolower(static_cast<unsigned char>(s[k])));
    q = close + 1;
  } else {
    while (q < s.size() && std::isdigit(static_cast<unsigned char>(s[q]))) o.label += s[q++];
    if (o.label.empty()) throw Error(lineno, o.column, "O-word without a number or <name>");
    if (o.label.size() > 18) throw Error(lineno, o.column, "O-word number is too long");
    o.label.erase(0, std::min(o.label.find_first_not_of('0'), o.label.size() - 1));  // o0100 is o100
  }
  while (q < s.size() && (s[q] == ' ' || s[q] == '\t')) ++q;
  while (q < s.size() && std::isalpha(static_cast<unsigned char>(s[q])))
    o.keyword += static_cast<char>(std::tolower(static_cast<unsigned char>(s[q++])));
  o.rest = q;
  static const char* const kKeywords[] = {"sub", "endsub", "call", "return", "if", "elseif", "else", "endif",
                                          "while", "endwhile", "do", "repeat", "endrepeat", "break", "continue"};
  if (std::find_if(std::begin(kKeywords), std::end(kKeywords), [&](const char* k) { return o.keyword == k; }) ==
      std::end(kKeywords))
    throw Error(lineno, o.column, "unknown O-word keyword '" + o.keyword + "'");
  return o;
}

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

struct Line {
  std::string_view text;
  int number = 0;
  std::optional<OWord> o;
  std::size_t end = kNone;   // an opening line (sub if elseif else while do repeat): its closing line
  std::size_t next = kNone;  // if, elseif: the next elseif, else or endif
  std::size_t loop = kNone;  // a closing line, break, continue: the opening line
};

// Splits the program into lines, honouring '%' delimiters; a line that is
// only '%' is checked and kept out.
std::vector<Line> split(std::string_view text, bool& closed) {
  std::vector<Line> out;
  int lineno = 0;
  std::size_t at = 0;
  bool delimited = false, first = true;
  while (at <= text.size()) {
    const auto nl = text.find('\n', at);
    const std::string_view line = text.substr(at, nl == std::string_view::npos ? std::string_view::npos : nl - at);
    ++lineno;
    const auto nonblank = line.find_first_not_of(" \t\r");
    if (nonblank != std::string_view::npos && line[nonblank] == '%') {
      read_words(line, lineno);  // checks that nothing follows
      if (first) delimited = true;
      else if (delimited) {  // the closing '%': the rest is not read
        closed = true;
        break;
      }
    } else {
      out.push_back({line, lineno, std::nullopt});
    }
    if (nonblank != std::string_view::npos) first = false;
    if (nl == std::string_view::npos) break;
    at = nl + 1;
  }
  return out;
}

// Pairs the O-word blocks by label and nesting; an error names the line.
class Structure {
 public:
  explicit Structure(std::vector<Line>& lines) : lines_(lines) {}

  void build() {
    for (std::size_t k = 0; k < lines_.size(); ++k) {
      lines_[k].o = o_word(lines_[k].text, lines_[k].number);
      if (lines_[k].o) place(k);
    }
    if (!open_.empty()) {
      const Line& l = lines_[open_.back()];
      fail(l, "O" + l.o->label + " " + l.o->keyword + " is not closed");
    }
  }

 private:
  [[noreturn]] void fail(const Line& l, const std::string& problem) const {
    throw Error(l.number, l.o ? l.o->column : 1, problem);
  }

  // The open block of this label and one of these keywords, innermost.
  std::size_t top(std::size_t k, std::initializer_list<const char*> kws) {
    const Line& l = lines_[k];
    if (open_.empty() || lines_[open_.back()].o->label != l.o->label)
      fail(l, "O" + l.o->label + " " + l.o->keyword + " without its opening O" + l.o->label);
    const std::string& kw = lines_[open_.back()].o->keyword;
    for (const char* want : kws)
      if (kw == want) return open_.back();
    fail(l, "O" + l.o->label + " " + l.o->keyword + " does not close O" + l.o->label + " " + kw);
  }

  void place(std::size_t k) {
    Line& l = lines_[k];
    const std::string& kw = l.o->keyword;
    if (kw == "sub" || kw == "if" || kw == "repeat" || kw == "do") return open_.push_back(k);
    if (kw == "while") {
      if (!open_.empty() && lines_[open_.back()].o->label == l.o->label && lines_[open_.back()].o->keyword == "do")
        return close(top(k, {"do"}), k);
      return open_.push_back(k);
    }
    if (kw == "elseif" || kw == "else") {
      lines_[chain_end(top(k, {"if"}))].next = k;
      return;
    }
    if (kw == "endif") return close(top(k, {"if"}), k);
    if (kw == "endwhile") return close(top(k, {"while"}), k);
    if (kw == "endrepeat") return close(top(k, {"repeat"}), k);
    if (kw == "endsub") return close(top(k, {"sub"}), k);
    if (kw == "break" || kw == "continue") return l.loop = enclosing_loop(k), void();
    if (kw == "return") {
      for (std::size_t o : open_)
        if (lines_[o].o->keyword == "sub") return;
      fail(l, "O" + l.o->label + " return outside a subroutine");
    }
  }

  // The last element of the if chain that starts at o.
  std::size_t chain_end(std::size_t o) {
    while (lines_[o].next != kNone) o = lines_[o].next;
    return o;
  }

  void close(std::size_t o, std::size_t k) {
    open_.pop_back();
    lines_[k].loop = o;
    for (std::size_t c = o; c != kNone;) {
      lines_[c].end = k;
      const std::size_t n = lines_[c].next;
      if (n == kNone) lines_[c].next = k;
      c = n;
    }
  }

  std::size_t enclosing_loop(std::size_t k) {
    const Line& l = lines_[k];
    for (auto it = open_.rbegin(); it != open_.rend(); ++it) {
      const Line& o = lines_[*it];
      const std::string& kw = o.o->keyword;
      if (o.o->label == l.o->label && (kw == "while" || kw == "do" || kw == "repeat")) return *it;
    }
    fail(l, "O" + l.o->label + " " + l.o->keyword + " outside an O" + l.o->label + " loop");
  }

  std::vector<Line>& lines_;
  std::vector<std::size_t> open_;
};

// Bounds against runaway programs (docs/paper-b.md): lines run, subroutine
// depth, moves emitted. Each stops the program with an Error (exit 2).
// (Options::max_lines_run, Options::max_blocks; the call depth here.)
constexpr std::size_t kMaxCallDepth = 64;

std::string count(std::size_t n) {
  if (n == 10'000'000) return "10^7";
  if (n == 2'000'000) return "2*10^6";
  return std::to_string(n);
}
constexpr int kLocals = 30;  // #1..#30 are a subroutine's own

struct Frame {
  std::size_t return_to = 0;
  std::array<double, kLocals + 1> saved{};
  std::map<std::string, double> saved_named;  // the caller's named locals (no leading '_')
  std::map<std::size_t, double> repeats;      // repeat line -> repeats left
};

class Runner {
 public:
  Runner(std::string_view text, const Options& o) : opt_(o), lines_(split(text, closed_)), run_(o) {
    frames_.emplace_back();
  }

  Program run() {
    Structure(lines_).build();
    std::size_t pc = 0, steps = 0;
    while (pc < lines_.size()) {
      const Line& l = lines_[pc];
      if (++steps > opt_.max_lines_run)
        fail(l, "the program runs more than " + count(opt_.max_lines_run) + " lines (an endless loop?)");
      if (run_.blocks() > opt_.max_blocks) fail(l, "the program makes more than " + count(opt_.max_blocks) + " moves");
      if (!l.o) {
        if (!run_.line(l.text, l.number)) return ended();
        ++pc;
        continue;
      }
      pc = control(pc);
    }
    return closed_ ? ended() : run_.take();
  }

 private:
  [[noreturn]] void fail(const Line& l, const std::string& problem) const {
    throw Error(l.number, l.o ? l.o->column : 1, problem);
  }

  Program ended() {
    Program p = run_.take();
    p.ended = true;
    return p;
  }

  double condition(const Line& l) {
    std::size_t pos = l.o->rest;
    return read_expression(l.text, l.number, pos, run_.params());
  }

  // Runs the O-word at pc; returns the next line to run.
  std::size_t control(std::size_t pc) {
    const Line& l = lines_[pc];
    const std::string& kw = l.o->keyword;
    if (kw == "sub") return subs_[l.o->label] = pc, l.end + 1;
    if (kw == "call") return call(pc);
    if (kw == "endsub" || kw == "return") return back(l);
    if (kw == "if") return branch(pc);
    if (kw == "elseif" || kw == "else") return l.end + 1;  // the taken branch ends here
    if (kw == "while" && l.end == kNone) return condition(l) != 0 ? l.loop + 1 : pc + 1;  // do ... while
    if (kw == "while") return condition(l) != 0 ? pc + 1 : l.end + 1;
    if (kw == "endwhile") return l.loop;
    if (kw == "repeat") return repeat(pc);
    if (kw == "endrepeat") {
      auto& reps = frames_.back().repeats;
      if (--reps[l.loop] > 0) return l.loop + 1;
      reps.erase(l.loop);
      return pc + 1;
    }
    if (kw == "break") return frames_.back().repeats.erase(l.loop), lines_[l.loop].end + 1;
    if (kw == "continue") return lines_[l.loop].o->keyword == "while" ? l.loop : lines_[l.loop].end;
    return pc + 1;  // endif, do
  }

  std::size_t branch(std::size_t pc) {
    std::size_t k = pc;
    while (true) {
      const Line& l = lines_[k];
      const std::string& kw = l.o->keyword;
      if (kw == "endif" || kw == "else") return k + 1;
      if (condition(l) != 0) return k + 1;
      k = l.next;
    }
  }

  std::size_t repeat(std::size_t pc) {
    const Line& l = lines_[pc];
    const double n = std::floor(condition(l));
    if (!(n >= 1)) return l.end + 1;
    frames_.back().repeats[pc] = n;
    return pc + 1;
  }

  std::size_t call(std::size_t pc) {
    const Line& l = lines_[pc];
    const auto it = subs_.find(l.o->label);
    if (it == subs_.end()) fail(l, "subroutine O" + l.o->label + " is not defined before its call");
    if (frames_.size() > kMaxCallDepth) fail(l, "subroutine calls nested deeper than 64 (runaway recursion?)");
    std::vector<double> args;
    std::size_t pos = l.o->rest;
    while (true) {
      const auto p = l.text.find_first_not_of(" \t\r", pos);
      if (p == std::string_view::npos || l.text[p] != '[') break;
      if (args.size() == kLocals) fail(l, "more than 30 arguments");
      args.push_back(read_expression(l.text, l.number, pos, run_.params()));
    }
    Params& params = run_.params();
    Frame f;
    f.return_to = pc + 1;
    for (int k = 1; k <= kLocals; ++k) {
      f.saved[k] = params.numbered[k];
      params.numbered[k] = k <= static_cast<int>(args.size()) ? args[k - 1] : 0.0;
    }
    for (auto n = params.named.begin(); n != params.named.end();) {
      if (n->first[0] == '_') ++n;
      else f.saved_named.insert(*n), n = params.named.erase(n);
    }
    frames_.push_back(std::move(f));
    return it->second + 1;
  }

  std::size_t back(const Line& l) {
    if (frames_.size() < 2) fail(l, "O" + l.o->label + " " + l.o->keyword + " outside a subroutine call");
    const auto p = l.text.find_first_not_of(" \t\r", l.o->rest);
    if (l.o->keyword == "return" && p != std::string_view::npos && l.text[p] == '[')
      fail(l, "a return value is not supported");
    Frame f = std::move(frames_.back());
    frames_.pop_back();
    Params& params = run_.params();
    for (int k = 1; k <= kLocals; ++k) params.numbered[k] = f.saved[k];
    for (auto n = params.named.begin(); n != params.named.end();)
      n = n->first[0] == '_' ? std::next(n) : params.named.erase(n);
    params.named.insert(f.saved_named.begin(), f.saved_named.end());
    return f.return_to;
  }

  const Options& opt_;
  bool closed_ = false;  // a closing '%' was read
  std::vector<Line> lines_;
  LineRunner run_;
  std::vector<Frame> frames_;
  std::map<std::string, std::size_t> subs_;
};

}  // namespace

Program read(std::string_view text, const Options& options) { return Runner(text, options).run(); }

}  // namespace contour::gcode
