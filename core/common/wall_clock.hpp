// Wall-clock time in seconds: what runs report as wall_time_s, and the clocks a resumed run
// continues from its checkpoint.
#pragma once

#include <algorithm>
#include <chrono>
#include <optional>

namespace rbcsim {

using WallClock = std::chrono::steady_clock;

inline double seconds_since(WallClock::time_point start) {
  return std::chrono::duration<double>(WallClock::now() - start).count();
}

// The start of a span that has lasted `seconds` by now: restored from a checkpoint, a span's
// wall time goes on from what it had when the checkpoint was written.
inline WallClock::time_point started_seconds_ago(double seconds) {
  return WallClock::now() -
         std::chrono::duration_cast<WallClock::duration>(std::chrono::duration<double>(seconds));
}

// A point of a run's progress: how far it is in its own measure (simulated time, strain, ...)
// and the wall seconds it took to get there.
struct ProgressPoint {
  double measure = 0.0;
  double wall_s = 0.0;
};

// The wall seconds a run needs to reach `total` of its measure at the rate it went from `first`
// to `now`; none before the measure has moved (nothing to extrapolate from), 0 past the total.
inline std::optional<double> wall_time_left_s(ProgressPoint first, ProgressPoint now,
                                              double total) {
  const double measure_done = now.measure - first.measure;
  if (!(measure_done > 0.0)) return std::nullopt;
  return (now.wall_s - first.wall_s) / measure_done * std::max(0.0, total - now.measure);
}

}  // namespace rbcsim
