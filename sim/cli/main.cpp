// contour: entry point. Dispatches to the registered subcommands.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "args.hpp"
#include "numbers.hpp"
#include "registry.hpp"

namespace contour::cli {

std::map<std::string, Command>& commands() {
  static std::map<std::string, Command> table;
  return table;
}

std::map<std::string, EngineInfo>& engines() {
  static std::map<std::string, EngineInfo> table;
  return table;
}

std::string engine_names() {
  std::string names;
  for (const auto& [name, info] : engines()) names += (names.empty() ? "" : "|") + name;
  return names;
}

std::string unknown_engine(const std::string& word, const std::string& known) {
  std::string msg = "--engine: unknown engine '" + word + "' (one of " + known + ")";
  if (word == "rtl") msg += "; 'rtl' is now 'core' (the Verilog interpolator) or 'cpu' (the Verilog 8085)";
  if (word == "8085") msg += "; '8085' is now 'cpu' (the Verilog 8085) or 'iss' (the C++ 8085)";
  return msg;
}

}  // namespace contour::cli

namespace {

void print_usage(std::FILE* out) {
  std::fprintf(out,
               "usage: contour COMMAND [ARGS...]\n"
               "Reference-pulse contour interpolators (Lee & Nho 1982): golden model,\n"
               "Verilog core and 8085 program, compared pulse by pulse.\n\ncommands:\n");
  for (const auto& [name, cmd] : contour::cli::commands())
    std::fprintf(out, "  %-10s %s\n", name.c_str(), cmd.summary.c_str());
  std::fprintf(out,
               "\n`contour COMMAND --help` describes each; `contour --version` prints the version.\n"
               "Bad input: one line on stderr naming it, exit status 2; a failed check: exit 1.\n\n%s",
               contour::cli::kNumberRules);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace contour::cli;
  if (argc < 2) {
    print_usage(stderr);
    return 2;
  }
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    print_usage(stdout);
    return 0;
  }
  if (name == "--version") {
    std::printf("contour %s\n", CONTOUR_VERSION);
    return 0;
  }
  auto it = commands().find(name);
  if (it == commands().end()) {
    std::fprintf(stderr, "contour: unknown command '%s' (try `contour --help`)\n", name.c_str());
    return 2;
  }
  std::vector<std::string> args(argv + 2, argv + argc);
  try {
    return it->second.run(args);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "contour %s: %s\n", name.c_str(), e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "contour %s: %s\n", name.c_str(), e.what());
    return 2;
  }
}
