// A circular tube along x with one smooth axisymmetric constriction: the non-uniform (stenosed)
// capillary of the paper's §3.3 and §3.4 (docs/physics.md, "Capillary").
//
// Over the constriction, of length L_c centred on x_c, let s = (x - x_c) / (L_c / 2) in [-1, 1].
// The lumen diameter is
//     D(x) = D_side - (D_side - D_throat) * narrowing(s),
// with D_side the inlet diameter upstream of the throat (s < 0) and the outlet diameter
// downstream (s > 0); narrowing(s) is 1 at the throat and 0 at both ends. Outside the
// constriction the tube is straight. The paper gives no profile; two are offered by name:
//   "cosine" (default)  narrowing = (1 + cos(pi s)) / 2, so for D_in = D_out
//                       D(x) = D_in - (D_in - D_throat) (1 + cos(2 pi (x - x_c) / L_c)) / 2.
//                       D and dD/dx are continuous everywhere (C1): the wall has no kink.
//   "linear"            narrowing = 1 - |s|: a cone in and a cone out (kinks at both ends and at
//                       the throat).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "geometry/axisymmetric_wall.hpp"

namespace rbcsim::geometry {

// The paper does not give the constriction length (its Figs. 12 and 14 only show a narrowing
// over the middle of the tube). Default: a third of the total length, centred.
inline constexpr double kDefaultConstrictionLengthFraction = 1.0 / 3.0;

struct CapillaryParameters {
  double length_um = 0.0;  // total length along x
  double inlet_diameter_um = 0.0;
  double outlet_diameter_um = 0.0;
  double throat_diameter_um = 0.0;               // the narrowest diameter, at the centre
  std::optional<double> constriction_length_um;  // default: length / 3
  std::optional<double> constriction_centre_um;  // x of the throat; default: length / 2
  std::string profile = "cosine";                // a name of narrowing_profiles()
};

// Paper §3.3, the validation case (geometry of Gallage et al. 2014): 31.2 um long, inlet and
// outlet diameter 10.2 um, throat "roughly" 6.75 um.
CapillaryParameters paper_validation_capillary();
// Paper §3.4, the three-morphology comparison: 42 um long, inlet and outlet 10 um, throat "about"
// 6.8 um.
CapillaryParameters paper_morphology_capillary();

// The one table of constriction profiles: narrowing(s) on s in [-1, 1], 1 at s = 0, 0 at |s| = 1.
struct NarrowingProfile {
  std::string_view name;
  double (*narrowing)(double s);
};
std::span<const NarrowingProfile> narrowing_profiles();

class CapillaryWall final : public AxisymmetricWall {
 public:
  // Fills in the defaults and throws rbcsim::InputError naming source.<parameter> for a
  // non-positive length, a throat not narrower than the inlet or the outlet, a constriction that
  // does not fit inside the tube, or an unknown profile.
  explicit CapillaryWall(const CapillaryParameters& parameters,
                         std::string_view source = "capillary");

  double lumen_radius_um(double x_um) const override;
  double largest_radius_um() const override;
  double length_um() const override { return parameters_.length_um; }

  // The parameters with every default filled in.
  const CapillaryParameters& parameters() const { return parameters_; }
  double constriction_start_um() const;
  double constriction_end_um() const;

 private:
  CapillaryParameters parameters_;
  double (*narrowing_)(double s) = nullptr;
};

}  // namespace rbcsim::geometry
