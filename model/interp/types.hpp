// Shared value types of the interpolators: pulses, observable state, errors.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace contour {

enum class Axis : std::uint8_t { X = 0, Y = 1, Z = 2 };

// One output pulse: an axis and a direction (+1 or -1).
struct Pulse {
  Axis axis = Axis::X;
  std::int8_t sign = +1;
  friend bool operator==(const Pulse&, const Pulse&) = default;
};

// "+X", "-Y", ... as printed by `--format steps`.
std::string to_string(const Pulse& p);

// Observable state after a command pulse, the same for every engine
// (docs/algorithm.md, "Observable state"). Positions are signed: for a line
// relative to its start, for an arc relative to the centre.
struct State {
  std::int64_t x = 0;
  std::int64_t y = 0;
  std::int64_t d = 0;              // discriminant D
  std::uint8_t quadrant = 0;       // arc: current quadrant 0..3 (Q1..Q4); line: 0
  std::uint8_t crossings = 0;      // arc: quadrant boundaries still to cross (the contract's k)
  std::uint64_t pulses = 0;        // output pulses so far
  bool done = false;
  friend bool operator==(const State&, const State&) = default;
};

std::string to_string(const State& s);

// An input outside the accepted domain of docs/algorithm.md. The message
// names the offending value and the rule it breaks.
class InputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A register left its stated width. Inside the accepted domain this cannot
// happen; the model checks every update so that the claim is tested.
class OverflowError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

// Throws OverflowError naming the register and the state. Out of line and
// cold, so that the checks cost the stepping code one compare each.
[[noreturn]] [[gnu::cold]] [[gnu::noinline]] void throw_overflow(const char* what, const State& s);

// Largest magnitude a W-bit register holds: 2^W - 1.
constexpr std::int64_t max_magnitude(unsigned width) { return (std::int64_t{1} << width) - 1; }

// Throws InputError unless |v| <= max_magnitude(width); `name` is the
// input's name in the message ("XE").
void check_coord(std::int64_t v, const char* name, unsigned width);

// True when v fits in a `bits`-wide two's-complement register.
constexpr bool fits_signed(std::int64_t v, unsigned bits) {
  return v >= -(std::int64_t{1} << (bits - 1)) && v < (std::int64_t{1} << (bits - 1));
}

}  // namespace contour
