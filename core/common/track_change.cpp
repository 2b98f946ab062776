#include "common/track_change.hpp"

#include <vector>

namespace rbcsim {

double mean_change_per_track(std::span<const TrackSample> samples) {
  struct Ends {
    TrackSample first;
    TrackSample last;
    bool seen = false;
  };
  std::vector<Ends> ends;
  for (const auto& sample : samples) {
    if (sample.track >= ends.size()) ends.resize(sample.track + 1);
    Ends& track = ends[sample.track];
    if (!track.seen || sample.time < track.first.time) track.first = sample;
    if (!track.seen || sample.time >= track.last.time) track.last = sample;
    track.seen = true;
  }
  double sum = 0.0;
  std::size_t tracks = 0;
  for (const Ends& track : ends) {
    if (!track.seen) continue;
    sum += track.last.value - track.first.value;
    ++tracks;
  }
  return tracks > 0 ? sum / static_cast<double>(tracks) : 0.0;
}

}  // namespace rbcsim
