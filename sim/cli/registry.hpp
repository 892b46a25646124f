// The `contour` CLI's two seams: subcommands and engines. Each registers
// itself from its own .cpp with a static Registrar, so adding a subcommand or
// an engine never edits a shared file.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "interp/engine.hpp"

namespace contour::cli {

// A subcommand: `contour NAME args...`. `run` returns the process exit
// status: 0 success, 1 a failed check (e.g. a divergence), 2 bad input.
struct Command {
  std::string name;
  std::string summary;  // one line for `contour --help`
  std::function<int(const std::vector<std::string>& args)> run;
};

std::map<std::string, Command>& commands();

struct CommandRegistrar {
  explicit CommandRegistrar(Command c) { commands().emplace(c.name, std::move(c)); }
};

// An engine runs one move (line or arc) and returns its pulses and states.
using EngineFactory = std::function<std::unique_ptr<Engine>()>;

struct EngineInfo {
  std::string name;
  std::string summary;
  EngineFactory make;
};

std::map<std::string, EngineInfo>& engines();

struct EngineRegistrar {
  explicit EngineRegistrar(EngineInfo e) { engines().emplace(e.name, std::move(e)); }
};

// Names of the registered engines, "model|core|..." for help texts.
std::string engine_names();

// The engine words, the same in every subcommand (README, "The CLI"):
// model (the golden C++ model), core (a Verilog interpolator core), iss
// (the C++ 8085), cpu (the Verilog 8085). The message for a word that is
// none of `known`, with a hint for the words used before (rtl, 8085).
std::string unknown_engine(const std::string& word, const std::string& known);

}  // namespace contour::cli
