#include "geometry/capillary_wall.hpp"
#include "common/registry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "common/errors.hpp"
#include "geometry/shape_parameters.hpp"

namespace rbcsim::geometry {
namespace {

double cosine_narrowing(double s) { return (1.0 + std::cos(std::numbers::pi * s)) / 2.0; }
double linear_narrowing(double s) { return 1.0 - std::abs(s); }

constexpr std::array kNarrowingProfiles{
    NarrowingProfile{"cosine", cosine_narrowing},
    NarrowingProfile{"linear", linear_narrowing},
};

void require_narrower(const CapillaryParameters& p, double side_diameter_um,
                      std::string_view side_key, std::string_view source) {
  if (p.throat_diameter_um >= side_diameter_um) {
    throw InputError(parameter_path(source, "throat_diameter_um"),
                     "must be smaller than " + std::string(side_key) + " (" +
                         std::to_string(p.throat_diameter_um) +
                         " >= " + std::to_string(side_diameter_um) + " um)");
  }
}

CapillaryParameters with_defaults(CapillaryParameters p, std::string_view source) {
  require_positive_length(p.length_um, source, "length_um");
  require_positive_length(p.inlet_diameter_um, source, "inlet_diameter_um");
  require_positive_length(p.outlet_diameter_um, source, "outlet_diameter_um");
  require_positive_length(p.throat_diameter_um, source, "throat_diameter_um");
  require_narrower(p, p.inlet_diameter_um, "inlet_diameter_um", source);
  require_narrower(p, p.outlet_diameter_um, "outlet_diameter_um", source);
  if (!p.constriction_length_um) {
    p.constriction_length_um = kDefaultConstrictionLengthFraction * p.length_um;
  }
  if (!p.constriction_centre_um) p.constriction_centre_um = p.length_um / 2.0;
  require_positive_length(*p.constriction_length_um, source, "constriction_length_um");
  if (*p.constriction_length_um > p.length_um) {
    throw InputError(parameter_path(source, "constriction_length_um"),
                     "must not exceed length_um (" + std::to_string(*p.constriction_length_um) +
                         " > " + std::to_string(p.length_um) + " um)");
  }
  const double half_um = *p.constriction_length_um / 2.0;
  const double centre_um = *p.constriction_centre_um;
  if (!std::isfinite(centre_um) || centre_um - half_um < 0.0 || centre_um + half_um > p.length_um) {
    throw InputError(parameter_path(source, "constriction_centre_um"),
                     "the constriction [" + std::to_string(centre_um - half_um) + ", " +
                         std::to_string(centre_um + half_um) +
                         "] um must lie inside the tube [0, " + std::to_string(p.length_um) +
                         "] um");
  }
  return p;
}

// A capillary whose inlet and outlet have the same diameter, with the default constriction.
CapillaryParameters equal_ends_capillary(double length_um, double diameter_um,
                                         double throat_diameter_um) {
  CapillaryParameters p;
  p.length_um = length_um;
  p.inlet_diameter_um = diameter_um;
  p.outlet_diameter_um = diameter_um;
  p.throat_diameter_um = throat_diameter_um;
  return p;
}

}  // namespace

CapillaryParameters paper_validation_capillary() { return equal_ends_capillary(31.2, 10.2, 6.75); }

CapillaryParameters paper_morphology_capillary() { return equal_ends_capillary(42.0, 10.0, 6.8); }

std::span<const NarrowingProfile> narrowing_profiles() { return kNarrowingProfiles; }

CapillaryWall::CapillaryWall(const CapillaryParameters& parameters, std::string_view source)
    : parameters_(with_defaults(parameters, source)),
      narrowing_(
          find_entry(narrowing_profiles(), parameters.profile, parameter_path(source, "profile"))
              .narrowing) {}

double CapillaryWall::constriction_start_um() const {
  return *parameters_.constriction_centre_um - *parameters_.constriction_length_um / 2.0;
}

double CapillaryWall::constriction_end_um() const {
  return *parameters_.constriction_centre_um + *parameters_.constriction_length_um / 2.0;
}

double CapillaryWall::lumen_radius_um(double x_um) const {
  const double s =
      (x_um - *parameters_.constriction_centre_um) / (*parameters_.constriction_length_um / 2.0);
  const double side_diameter_um =
      s < 0.0 ? parameters_.inlet_diameter_um : parameters_.outlet_diameter_um;
  if (std::abs(s) >= 1.0) return side_diameter_um / 2.0;
  const double narrowing_um = (side_diameter_um - parameters_.throat_diameter_um) * narrowing_(s);
  return (side_diameter_um - narrowing_um) / 2.0;
}

double CapillaryWall::largest_radius_um() const {
  return std::max(parameters_.inlet_diameter_um, parameters_.outlet_diameter_um) / 2.0;
}

}  // namespace rbcsim::geometry
