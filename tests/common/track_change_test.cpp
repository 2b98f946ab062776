// How far tracked things moved: the mean over the tracks of last minus first value, with the
// samples in any order.
#include "common/track_change.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

using rbcsim::mean_change_per_track;
using rbcsim::TrackSample;

TEST(TrackChange, MeanOfEachTracksLastMinusFirstInAnyOrder) {
  // Track 0 goes 1 -> 4 -> 11 (10 along), track 2 goes 5 -> 3 (-2 along), shuffled; track 1
  // never appears and does not count.
  const std::vector<TrackSample> samples = {
      {2, 0.2, 3.0}, {0, 0.1, 4.0}, {0, 0.0, 1.0}, {2, 0.0, 5.0}, {0, 0.3, 11.0}};
  EXPECT_DOUBLE_EQ(mean_change_per_track(samples), (10.0 - 2.0) / 2.0);
}

TEST(TrackChange, NothingSampledMovedNothing) {
  EXPECT_EQ(mean_change_per_track({}), 0.0);
  const std::vector<TrackSample> one = {{3, 1.0, 7.0}};
  EXPECT_EQ(mean_change_per_track(one), 0.0);
}

}  // namespace
