// `contour cosim`: the SystemC co-simulation of the model, the Verilog core
// and the 8085 program (docs/cosim.md). The simulation is its own program,
// build/contour-cosim (sim/cosim/), because SystemC elaborates once per
// process and links its own main(); this command finds it next to the
// `contour` executable (or at $CONTOUR_COSIM), runs it with the same
// arguments, and returns its exit status: 0 every required equivalence
// holds, 1 one does not, 2 bad input.
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "args.hpp"
#include "registry.hpp"

namespace contour::cli {
namespace {

std::string cosim_program() {
  if (const char* env = std::getenv("CONTOUR_COSIM"); env && *env) return env;
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return "contour-cosim";
  return (self.parent_path() / "contour-cosim").string();
}

// The `contour cosim` subcommand: runs contour-cosim with `args` and returns
// its exit status (the co-simulation itself is cosim::run_cosim).
int run_cosim_command(const std::vector<std::string>& args) {
  const std::string prog = cosim_program();
  if (::access(prog.c_str(), X_OK) != 0) {
    for (const auto& a : args)
      if (a == "--help" || a == "-h") {
        std::printf("usage: contour cosim --suite paper|smoke|full|long (--rate R | --sweep) [--report DIR] [--trace]\n"
                    "  command rates: the core up to 25M pps, the 8085 engines up to 250k (docs/cosim.md)\n"
                    "  (the co-simulation program %s is not built: it needs Verilator and SystemC)\n",
                    prog.c_str());
        return 0;
      }
    std::fprintf(stderr,
                 "contour cosim: %s is not built (it needs Verilator and SystemC: `make deps build`)\n",
                 prog.c_str());
    return 1;
  }
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(prog.c_str()));
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = ::fork();
  if (pid < 0) {
    std::fprintf(stderr, "contour cosim: fork: %s\n", std::strerror(errno));
    return 1;
  }
  if (pid == 0) {
    ::execv(prog.c_str(), argv.data());
    std::fprintf(stderr, "contour cosim: cannot run %s: %s\n", prog.c_str(), std::strerror(errno));
    std::_Exit(1);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) {
      std::fprintf(stderr, "contour cosim: waitpid: %s\n", std::strerror(errno));
      return 1;
    }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  std::fprintf(stderr, "contour cosim: %s was killed by signal %d\n", prog.c_str(),
               WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  return 1;
}

const CommandRegistrar kCosim{{"cosim",
                               "SystemC co-simulation of model, Verilog core and 8085 at a command rate; reports",
                               run_cosim_command}};

}  // namespace
}  // namespace contour::cli
