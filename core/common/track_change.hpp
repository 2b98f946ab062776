// How far a set of tracked things moved: one sample is a track (a cell, say), a time and a value
// (a coordinate), in any order. The suspension reports with it how far the flow carried its
// cells, and the report recomputes it from an older run's cells_timeseries.csv.
#pragma once

#include <cstddef>
#include <span>

namespace rbcsim {

struct TrackSample {
  std::size_t track = 0;
  double time = 0.0;
  double value = 0.0;
};

// The mean over the tracks of (value at the track's latest time - value at its earliest); ties
// in time keep the first sample met as the earliest and the last met as the latest. 0 without
// samples.
double mean_change_per_track(std::span<const TrackSample> samples);

}  // namespace rbcsim
