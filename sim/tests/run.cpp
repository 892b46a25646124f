#include "run.hpp"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace contour::test {

namespace {

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace

ProcessResult contour(const std::string& args) {
  char out_tpl[] = "/tmp/contour-out-XXXXXX";
  char err_tpl[] = "/tmp/contour-err-XXXXXX";
  const int fo = mkstemp(out_tpl), fe = mkstemp(err_tpl);
  if (fo < 0 || fe < 0) throw std::runtime_error("mkstemp failed");
  const std::string cmd = std::string(CONTOUR_EXE) + " " + args + " >" + out_tpl + " 2>" + err_tpl + " </dev/null";
  const int raw = std::system(cmd.c_str());
  ProcessResult o;
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  o.out = slurp(out_tpl);
  o.err = slurp(err_tpl);
  std::remove(out_tpl);
  std::remove(err_tpl);
  return o;
}

}  // namespace contour::test
