// Runs a command line and captures its exit status, stdout and stderr.
#pragma once

#include <string>

namespace contour::test {

struct Outcome {
  int status = -1;
  std::string out;
  std::string err;
};

// `args` is appended to the contour executable's path and run by /bin/sh.
Outcome contour(const std::string& args);

}  // namespace contour::test
