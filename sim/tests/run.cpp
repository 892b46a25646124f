#include "run.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

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
  // CONTOUR_TEST_EXE runs the tests against another build (e.g. an older
  // one, to see a test fail without the fix it checks).
  const char* exe = std::getenv("CONTOUR_TEST_EXE");
  const std::string cmd = std::string(exe && *exe ? exe : CONTOUR_EXE) + " " + args + " >" + out_tpl + " 2>" + err_tpl + " </dev/null";
  ProcessResult o;
  // fork + wait4 rather than system(): wait4 reports the largest resident
  // set of the shell and of what it waited for (contour).
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int raw = 0;
  struct rusage ru {};
  if (::wait4(pid, &raw, 0, &ru) != pid) throw std::runtime_error("wait4 failed");
  o.max_rss_kb = ru.ru_maxrss;
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  o.out = slurp(out_tpl);
  o.err = slurp(err_tpl);
  std::remove(out_tpl);
  std::remove(err_tpl);
  return o;
}

}  // namespace contour::test
