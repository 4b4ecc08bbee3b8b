// The checks every core (planning, world files, behaviour constants, navigation) makes of the
// numbers it is given, in one message style: "<field>: must be <rule>, got <value>", thrown as
// util::InvalidInput (invalid_input.h). Valid input builds no strings: a field is a string_view
// and the message is made only when a check fails (the planner validates every request).
#pragma once

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::util {

/// A number as show() prints it when that reads back as the same number ("0.17", "1e+06",
/// "nan"), else with as many digits as it takes ("1000000.0000000012"): show() rounds to 6
/// digits, which made "must be in [-1e+06, 1e+06] m, got 1e+06" of a value just above 10⁶.
inline std::string showExact(double value) {
  std::string text = show(value);
  for (int digits = 7;
       digits <= 17 && std::isfinite(value) && std::strtod(text.c_str(), nullptr) != value;
       ++digits) {
    std::ostringstream out;
    out.precision(digits);
    out << value;
    text = out.str();
  }
  return text;
}

/// Throws InvalidInput(field, "must be <rule>, got <value>"), the value exact (showExact).
[[noreturn]] inline void failRule(std::string_view field, std::string_view rule, double value) {
  throw InvalidInput(std::string(field),
                     "must be " + std::string(rule) + ", got " + showExact(value));
}

/// Unless `ok`: "<field>: must be <rule>, got <value>".
inline void require(bool ok, std::string_view field, std::string_view rule, double value) {
  if (!ok) failRule(field, rule, value);
}

/// "<field>: must be finite, got nan" unless `value` is finite.
inline void requireFinite(std::string_view field, double value) {
  if (!std::isfinite(value)) failRule(field, "finite", value);
}

/// "<field>: must be in [lo, hi] <unit>, got <value>" unless lo ≤ value ≤ hi (NaN fails).
inline void requireInRange(std::string_view field, double value, double lo, double hi,
                           std::string_view unit = "") {
  if (value >= lo && value <= hi) return;
  failRule(
      field,
      "in [" + show(lo) + ", " + show(hi) + "]" + (unit.empty() ? "" : " ") + std::string(unit),
      value);
}

/// The same for a whole number, printed whole: "<field>: must be in [0, 5000000], got -1".
template <class Int, std::enable_if_t<std::is_integral_v<Int>, int> = 0>
void requireInRange(std::string_view field, Int value, long long lo, long long hi,
                    std::string_view unit = "") {
  if (value >= lo && value <= hi) return;
  throw InvalidInput(std::string(field), "must be in [" + std::to_string(lo) + ", " +
                                             std::to_string(hi) + "]" + (unit.empty() ? "" : " ") +
                                             std::string(unit) + ", got " + std::to_string(value));
}

/// 0 < value ≤ max (NaN fails): "<field>: must be finite and > 0, got <value>" without a finite
/// max, else "<field>: must be in (0, max] <unit>, got <value>".
inline void requirePositive(std::string_view field, double value,
                            double max = std::numeric_limits<double>::infinity(),
                            std::string_view unit = "") {
  if (std::isfinite(value) && value > 0 && value <= max) return;
  if (!std::isfinite(max)) failRule(field, "finite and > 0", value);
  failRule(field, "in (0, " + show(max) + "]" + (unit.empty() ? "" : " ") + std::string(unit),
           value);
}

}  // namespace roomba_rrt::util
