// Wall-clock timing for the benchmarks (DESIGN.md §5: measure, don't assert). Calls are timed in
// short batches and the fastest batch counts: on a machine shared with other processes the mean
// mostly measures them (one descheduled thread stalls an OpenMP barrier for a whole time slice),
// while the fastest batch approaches the code's own cost.
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

// Seconds per call of `call()` in the fastest batch.
template <typename Call>
double fastest_batch_seconds_per_call(const Call& call, const BatchTiming& timing = {}) {
  using Clock = std::chrono::steady_clock;
  using Seconds = std::chrono::duration<double>;
  const auto start = Clock::now();
  double fastest_batch_s = std::numeric_limits<double>::infinity();
  int batches = 0;
  do {
    const auto batch_start = Clock::now();
    for (int k = 0; k < timing.calls_per_batch; ++k) call();
    fastest_batch_s = std::min(fastest_batch_s, Seconds(Clock::now() - batch_start).count());
    ++batches;
  } while (batches < timing.minimum_batches ||
           Seconds(Clock::now() - start).count() < timing.minimum_duration_s);
  return fastest_batch_s / timing.calls_per_batch;
}

}  // namespace rbcsim
