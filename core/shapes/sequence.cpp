#include "shapes/sequence.hpp"

#include <vector>

namespace rbcsim::shapes {
namespace {

// Delta a0 of each class, read off rbcsim's own sequence at 2562 vertices (docs/validation.md,
// "Shapes from membrane mechanics"): each where the minimum has the class's defining measures.
// The paths: the soft one is needed for the discocyte (from the stiff one a 642-vertex cell stays
// a convex oblate of higher energy); on the cups it folds the lip through the wall, so those take
// the stiff path alone. The echinocyte III takes the continuation from the discocyte
// (docs/physics.md, "Shapes from membrane mechanics"): with the full drive on the near-spherical
// reference the stiff path buys area difference with single-vertex spikes the mesh does not
// resolve. The echinocytes I and II keep the stiff path their Delta a0 were placed on: walked
// from the discocyte, the minimum at Delta a0 9 and 10 is still a flat disc without crenation.
// The trials: the smooth shapes reach one minimum from every start (both discocyte paths end
// within 1 % of each other's energy); a spiculated body has many near-degenerate arrangements of
// its spicules (four seeds at 2562 vertices: 1172.8-1174.4 pN um), so the echinocytes take four
// starts and the lowest wins: its spicule count is then not one start's accident.
std::vector<SequenceShape> sequence_entries() {
  const std::vector<std::string> stiff = {"stiff"};
  const std::vector<std::string> continuation = {"continuation"};
  return {
      {"stomatocyte-III", "a cup with a deep introversion", -6.0, stiff},
      {"stomatocyte-II", "a cup with a deep invagination", -4.0, stiff},
      {"stomatocyte-I", "a shelvy cup", 0.0, stiff},
      {"discocyte", "the biconcave disc", 1.0, {"soft", "stiff"}},
      {"echinocyte-I", "a disc with irregularities on its rim", 9.0, stiff, 4},
      {"echinocyte-II", "an elliptical body with spicules over its surface", 10.0, stiff, 4},
      {"echinocyte-III", "a sphere with regularly spaced sharp spicules, about 30-50", 12.0,
       continuation, 4},
  };
}

}  // namespace

const Registry<SequenceShape>& shape_sequence() {
  static const Registry<SequenceShape> sequence("sequence shape", sequence_entries());
  return sequence;
}

}  // namespace rbcsim::shapes
