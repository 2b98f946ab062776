// Wall-clock time in seconds: what runs report as wall_time_s, and the clocks a resumed run
// continues from its checkpoint.
#pragma once

#include <chrono>

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

}  // namespace rbcsim
