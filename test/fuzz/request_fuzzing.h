// What the harnesses of the planners' service requests (plan_path_fuzzer, plan_coverage_fuzzer)
// share: drawing a number that is often one that breaks arithmetic, and the check that stops the
// run naming the harness (scripts/fuzz reports "<harness>: check failed: ...").
#pragma once

#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdio>
#include <cstdlib>

namespace roomba_rrt::fuzz {

/// One of `special` (zeros, denormals, 1e308, ±inf, NaN, the worlds' own sizes) a quarter of the
/// time, any double a quarter of the time, else one in [lo, hi].
template <std::size_t N>
double pickDouble(FuzzedDataProvider& in, const double (&special)[N], double lo, double hi) {
  switch (in.ConsumeIntegralInRange(0, 3)) {
    case 0:
      return in.PickValueInArray(special);
    case 1:
      return in.ConsumeFloatingPoint<double>();
    default:
      return in.ConsumeFloatingPointInRange(lo, hi);
  }
}

/// Aborts with "<harness>: check failed: <what>" unless `ok`: what a client relies on broke.
inline void require(bool ok, const char* harness, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "%s: check failed: %s\n", harness, what);
    std::abort();
  }
}

}  // namespace roomba_rrt::fuzz
