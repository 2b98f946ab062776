// Wall-clock timing for the benchmarks (docs/performance.md: measure, don't assert). Calls are
// timed in short batches and the fastest batch counts: on a machine shared with other processes the
// mean mostly measures them (one descheduled thread stalls an OpenMP barrier for a whole time
// slice), while the fastest batch approaches the code's own cost.
#pragma once

#include <algorithm>
#include <chrono>
#include <limits>

namespace rbcsim {

struct BatchTiming {
  int calls_per_batch = 5;
  int minimum_batches = 3;
  double minimum_duration_s = 0.25;  // keep timing batches until this much time has passed
};

// Seconds per call of `call()` in the fastest batch. `after_batch(bool fastest_so_far)` runs after
// each batch, outside the timed region (to read or reset what the calls accumulated).
template <typename Call, typename AfterBatch = void (*)(bool)>
double fastest_batch_seconds_per_call(
    const Call& call, const BatchTiming& timing = {}, const AfterBatch& after_batch = [](bool) {}) {
  using Clock = std::chrono::steady_clock;
  using Seconds = std::chrono::duration<double>;
  const auto start = Clock::now();
  double fastest_batch_s = std::numeric_limits<double>::infinity();
  int batches = 0;
  do {
    const auto batch_start = Clock::now();
    for (int k = 0; k < timing.calls_per_batch; ++k) call();
    const double batch_s = Seconds(Clock::now() - batch_start).count();
    const bool fastest = batch_s < fastest_batch_s;
    fastest_batch_s = std::min(fastest_batch_s, batch_s);
    after_batch(fastest);
    ++batches;
  } while (batches < timing.minimum_batches ||
           Seconds(Clock::now() - start).count() < timing.minimum_duration_s);
  return fastest_batch_s / timing.calls_per_batch;
}

}  // namespace rbcsim
