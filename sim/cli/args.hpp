// Small command-line parser shared by the subcommands: positional arguments,
// boolean flags and options with a value (`--opt V` or `--opt=V`). Negative
// numbers are positional, not options. Every error names the argument.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace contour::cli {

// Bad command-line input: main() prints it on one line and exits with 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Args {
 public:
  // `flags` take no value, `options` take one. Unknown --names are errors.
  Args(const std::vector<std::string>& argv, const std::set<std::string>& flags,
       const std::set<std::string>& options);

  bool help() const { return help_; }
  bool flag(const std::string& name) const { return flags_.count(name) != 0; }
  std::optional<std::string> option(const std::string& name) const;
  std::string option_or(const std::string& name, const std::string& fallback) const;
  const std::vector<std::string>& positional() const { return positional_; }

  // Requires exactly `n` positional arguments, named for the error message.
  void expect_positional(const std::vector<std::string>& names) const;

 private:
  bool help_ = false;
  std::set<std::string> flags_;
  std::map<std::string, std::string> options_;
  std::vector<std::string> positional_;
};

// Parses a decimal integer; the error names `what` and quotes the text.
std::int64_t parse_int(const std::string& text, const std::string& what);
// Parses a real number (plain or with an SI suffix k/M: "250k" -> 250000).
double parse_real(const std::string& text, const std::string& what);

}  // namespace contour::cli
