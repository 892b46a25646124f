// Runs a command line and captures its exit status, stdout and stderr.
#pragma once

#include <string>

namespace contour::test {

struct ProcessResult {
  int status = -1;
  std::string out;
  std::string err;
  long max_rss_kb = 0;  // largest resident set of the process (and its children)
};

// `args` is appended to the contour executable's path and run by /bin/sh.
ProcessResult contour(const std::string& args);

}  // namespace contour::test
