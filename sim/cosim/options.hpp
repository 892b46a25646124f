// Command-line options of contour-cosim (and of `contour cosim`, which
// passes its arguments through).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "top.hpp"

namespace contour::cosim {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "250k" -> 250000, "1M", "3.5k", "4000". Throws UsageError naming `what`.
double parse_rate(const std::string& text, const std::string& what);

// Throws UsageError with a one-line message naming the bad argument.
// `help` is set (and nothing else checked) for -h/--help.
Options parse_options(const std::vector<std::string>& args, bool& help);

std::string usage();

}  // namespace contour::cosim
