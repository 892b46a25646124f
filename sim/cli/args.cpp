#include "args.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace contour::cli {

namespace {

bool looks_numeric(const std::string& s) {
  return s.size() >= 2 && s[0] == '-' && (std::isdigit(static_cast<unsigned char>(s[1])) || s[1] == '.');
}

}  // namespace

Args::Args(const std::vector<std::string>& argv, const std::set<std::string>& flags,
           const std::set<std::string>& options) {
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& a = argv[i];
    if (a == "--help" || a == "-h") {
      help_ = true;
      continue;
    }
    if (a.size() < 2 || a[0] != '-' || looks_numeric(a)) {
      positional_.push_back(a);
      continue;
    }
    // "--name", "--name=value", or a one-letter "-o" spelled as in `options`.
    std::string name = a.rfind("--", 0) == 0 ? a.substr(2) : a.substr(1);
    std::optional<std::string> value;
    if (auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
    }
    if (flags.count(name)) {
      if (value) throw UsageError("option --" + name + " takes no value");
      flags_.insert(name);
    } else if (options.count(name)) {
      if (!value) {
        if (i + 1 >= argv.size()) throw UsageError("option --" + name + " needs a value");
        value = argv[++i];
      }
      options_[name] = *value;
    } else {
      throw UsageError("unknown option '" + a + "'");
    }
  }
}

std::optional<std::string> Args::option(const std::string& name) const {
  auto it = options_.find(name);
  if (it == options_.end()) return std::nullopt;
  return it->second;
}

std::string Args::option_or(const std::string& name, const std::string& fallback) const {
  return option(name).value_or(fallback);
}

void Args::expect_positional(const std::vector<std::string>& names) const {
  if (positional_.size() < names.size())
    throw UsageError("missing argument " + names[positional_.size()]);
  if (positional_.size() > names.size())
    throw UsageError("unexpected argument '" + positional_[names.size()] + "'");
}

std::int64_t parse_int(const std::string& text, const std::string& what) {
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0') throw UsageError(what + ": '" + text + "' is not an integer");
  if (errno == ERANGE) throw UsageError(what + ": '" + text + "' is out of range");
  return static_cast<std::int64_t>(v);
}

double parse_real(const std::string& text, const std::string& what) {
  char* end = nullptr;
  double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end == text.c_str()) throw UsageError(what + ": '" + text + "' is not a number");
  std::string suffix(end);
  if (suffix == "k") v *= 1e3;
  else if (suffix == "M") v *= 1e6;
  else if (!suffix.empty()) throw UsageError(what + ": '" + text + "' is not a number");
  if (!std::isfinite(v)) throw UsageError(what + ": '" + text + "' is not finite");
  return v;
}

}  // namespace contour::cli
