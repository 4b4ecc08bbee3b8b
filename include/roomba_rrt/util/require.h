// The checks every core (planning, world files, behaviour constants, navigation) makes of the
// numbers it is given, in one message style: "<field>: must be <rule>, got <value>", thrown as
// util::InvalidInput (invalid_input.h). Valid input builds no strings: a field is a string_view
// and the message is made only when a check fails (the planner validates every request).
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::util {

/// Throws InvalidInput(field, "must be <rule>, got <value>").
[[noreturn]] inline void failRule(std::string_view field, std::string_view rule, double value) {
  throw InvalidInput(std::string(field), "must be " + std::string(rule) + ", got " + show(value));
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
