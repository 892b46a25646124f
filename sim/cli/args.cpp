#include "args.hpp"

#include <cctype>

#include "numbers.hpp"

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
    // Messages name the option as it was spelled ("-o", "--output").
    const std::size_t dashes = a.rfind("--", 0) == 0 ? 2 : 1;
    std::string name = a.substr(dashes);
    std::optional<std::string> value;
    if (auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
    }
    const std::string spelled = a.substr(0, dashes) + name;
    if (flags.count(name)) {
      if (value) throw UsageError("option " + spelled + " takes no value");
      flags_.insert(name);
    } else if (options.count(name)) {
      if (!value) {
        if (i + 1 >= argv.size()) throw UsageError("option " + spelled + " needs a value");
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
  std::int64_t v = 0;
  switch (read_int(text, v)) {
    case IntRead::Ok:
      return v;
    case IntRead::OutOfRange:
      throw UsageError(what + ": '" + text + "' is out of range");
    case IntRead::NotInteger:
      break;
  }
  throw UsageError(what + ": '" + text + "' is not an integer (decimal digits, optional leading '-')");
}

double parse_real(const std::string& text, const std::string& what) {
  if (const auto v = read_real(text)) return *v;
  throw UsageError(what + ": '" + text + "' is not a number (decimal, optional k or M suffix: 1.5, 250k)");
}

}  // namespace contour::cli
