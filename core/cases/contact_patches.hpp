// Where the optical tweezers hold the cell (docs/physics.md, "Stretch"): two contact patches at the
// two ends of the pull axis x, chosen by a named rule (one table, contact_patches.cpp):
//   "contact-diameter"  (default) the vertices within a Euclidean distance diameter_um / 2 of the
//                       end vertex (the vertex of largest, resp. smallest, x): the membrane under
//                       a bead contact of that diameter (2 um as in Mills et al. 2004 and the
//                       simulations of Dao et al. 2003 / Fedosov et al. 2010). The number of
//                       vertices grows with the resolution; the patch area does not.
//   "extreme-vertices"  the extreme_vertex_count vertices of largest (smallest) x, HemoCell's
//                       rule (its stretchCell case uses 7: the end vertex and its ring). Ties in x
//                       are broken by vertex index, so the choice is deterministic.
// Each patch carries the total force F, split equally over its vertices (tweezer_forces_pN).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/vec3.hpp"

namespace rbcsim::cases {

struct ContactSettings {
  std::string rule = "contact-diameter";
  double diameter_um = 2.0;      // "contact-diameter"
  int extreme_vertex_count = 7;  // "extreme-vertices"
  // The bead holds its patch rigid (the membrane is glued to the silica bead over the contact,
  // Mills et al. 2004, Dao et al. 2003): the patch translates as one body under F plus the
  // membrane's pull on it. false: every patch vertex moves freely under its share F/n (HemoCell,
  // Fedosov et al. 2010, the default); the patch then narrows into a tether-like tip (1.6 to
  // 1.1 um wide, 0.3 to 1.3 um long at 193 pN). Quasi-static mode only.
  bool rigid = false;
};

struct ContactPatches {
  std::vector<std::int32_t> positive_end;  // at largest x, pulled towards +x
  std::vector<std::int32_t> negative_end;  // at smallest x, pulled towards -x
};

std::vector<std::string> contact_rule_names();

// Throws InputError naming the option when the rule is unknown or the two patches would share a
// vertex (a contact diameter or vertex count too large for the cell).
ContactPatches select_contact_patches(std::span<const Vec3> positions_um,
                                      const ContactSettings& settings);

// The patches as groups that move rigidly (membrane::RelaxationSettings::rigid_groups), or none
// when settings.rigid is false.
std::vector<std::vector<std::int32_t>> rigid_contact_groups(const ContactPatches& patches,
                                                            const ContactSettings& settings);

// Per-vertex external forces: +F/n x on each of the n vertices of the positive patch, -F/m x on
// each of the m of the negative one (total +F and -F: no net force).
std::vector<Vec3> tweezer_forces_pN(std::size_t vertex_count, const ContactPatches& patches,
                                    double force_pN);

}  // namespace rbcsim::cases
