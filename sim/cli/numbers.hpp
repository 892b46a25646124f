// The one set of number rules for every numeric command-line argument of
// `contour` and `contour-cosim` (rates, accelerations, coordinates, counts,
// durations). Header-only so that sim/cosim's option parser uses the same
// rules without linking the CLI. Each reader returns nothing for text that
// breaks the rules; the caller names the argument in its message.
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace contour::cli {

// For help texts: the rules, stated once.
inline constexpr const char* kNumberRules =
    "Numbers are decimal: integers as 12 or -12; reals as 1.5, -0.25, .5 or 3; a real may\n"
    "end in k (x 1000) or M (x 1000000): 250k, 1.5M. Durations carry a unit: ns, us, ms\n"
    "or s (2us, 1500ns). No hex (0x10), no exponent (1e3), no '+', no spaces, no empty\n"
    "item in a comma list.\n";

// True when `s` is [-]digits, or with `fraction` [-]digits[.digits] / [-].digits.
inline bool is_decimal(std::string_view s, bool fraction) {
  if (!s.empty() && s[0] == '-') s.remove_prefix(1);
  bool digit = false, point = false;
  for (const char c : s) {
    if (c >= '0' && c <= '9') digit = true;
    else if (c == '.' && fraction && !point) point = true;
    else return false;
  }
  return digit;
}

enum class IntRead : std::uint8_t { Ok, NotInteger, OutOfRange };

// A decimal integer into `v` (int64 range).
inline IntRead read_int(const std::string& text, std::int64_t& v) {
  if (!is_decimal(text, false)) return IntRead::NotInteger;
  errno = 0;
  const long long r = std::strtoll(text.c_str(), nullptr, 10);
  if (errno == ERANGE) return IntRead::OutOfRange;
  v = static_cast<std::int64_t>(r);
  return IntRead::Ok;
}

// A decimal real with an optional k or M suffix ("250k" -> 250000).
inline std::optional<double> read_real(std::string text) {
  double scale = 1;
  if (!text.empty() && (text.back() == 'k' || text.back() == 'K')) scale = 1e3;
  else if (!text.empty() && text.back() == 'M') scale = 1e6;
  if (scale != 1) text.pop_back();
  if (!is_decimal(text, true)) return std::nullopt;
  const double v = std::strtod(text.c_str(), nullptr) * scale;
  if (!std::isfinite(v)) return std::nullopt;
  return v;
}

// A duration with its unit (ns, us, ms, s) in nanoseconds: "2us" -> 2000.
inline std::optional<double> read_duration_ns(const std::string& text) {
  static const std::pair<const char*, double> units[] = {{"ns", 1}, {"us", 1e3}, {"ms", 1e6}, {"s", 1e9}};
  for (const auto& [unit, ns] : units) {
    const std::string u(unit);
    if (text.size() <= u.size() || text.compare(text.size() - u.size(), u.size(), u) != 0) continue;
    const std::string num = text.substr(0, text.size() - u.size());
    if (!is_decimal(num, true)) return std::nullopt;
    return std::strtod(num.c_str(), nullptr) * ns;
  }
  return std::nullopt;
}

// Splits a comma list; nothing when an item is empty ("1k," or ",1k").
inline std::optional<std::vector<std::string>> read_list(const std::string& text) {
  std::vector<std::string> items;
  std::size_t from = 0;
  for (;;) {
    const std::size_t comma = text.find(',', from);
    items.push_back(text.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
    if (items.back().empty()) return std::nullopt;
    if (comma == std::string::npos) return items;
    from = comma + 1;
  }
}

}  // namespace contour::cli
