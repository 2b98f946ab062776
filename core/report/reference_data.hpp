// Measured data the report plots runs against, compiled into the binary from share/reference
// (see core/config/CMakeLists.txt), so a report needs no file beside the runs.
#pragma once

#include <string>
#include <vector>

namespace rbcsim::report {

// Mills, Qie, Dao, Lim, Suresh (2004), Fig. 8: optical-tweezers stretching of healthy cells,
// digitised (share/reference/mills2004_stretch.csv keeps the provenance). Errors are the
// half-lengths of the error bars.
struct StretchReference {
  std::vector<double> force_pN;
  std::vector<double> axial_um;
  std::vector<double> axial_error_um;
  std::vector<double> transverse_um;
  std::vector<double> transverse_error_um;
};

const StretchReference& mills2004_stretch();

// Straight-tube blood flow in vitro (share/reference/pries_tube_flow.csv keeps the provenance and
// the caveats): the fit of Pries, Neuhaus, Gaehtgens (1992, Am J Physiol 263:H1770) of the
// apparent viscosity relative to plasma, eta_rel(D, H_D), and the Fahraeus ratio H_T/H_D of
// Pries, Secomb, Gaehtgens, Gross (1990, Circ Res 67:826), both against the tube diameter D (um)
// and the discharge hematocrit H_D (fraction).
double pries1992_relative_apparent_viscosity(double diameter_um, double discharge_hematocrit);
double pries1990_tube_to_discharge_hematocrit(double diameter_um, double discharge_hematocrit);
// The same fit's limit in a tube much wider than a cell (D -> infinity: eta_rel at 0.45 = 3.2,
// exponent C = -0.8): the high-shear viscosity of bulk blood relative to plasma at hematocrit H,
// the scale against which a sheared suspension's relative viscosity is set.
double pries1992_large_tube_relative_viscosity(double hematocrit);
// rbcsim's own goal for a suspension against these fits: within 15 % (the suspensions issue).
inline constexpr double kPriesAgreement = 0.15;
// The verdict on rbcsim / fit - 1 against that goal.
inline const char* pries_verdict(double relative_difference) {
  return relative_difference <= kPriesAgreement && relative_difference >= -kPriesAgreement
             ? "within 15 %"
             : "differs by more than 15 %";
}

// The rows of share/reference/pries_tube_flow.csv (computed there from the same fits), so the
// formulas above can be checked against an implementation of their own.
struct TubeFlowReferenceRow {
  double diameter_um;
  double discharge_hematocrit;
  double relative_apparent_viscosity;
  double tube_to_discharge_hematocrit;
};
const std::vector<TubeFlowReferenceRow>& pries_tube_flow_table();

// Cell-free layer thickness next to the wall (share/reference/cell_free_layer.csv): in-vivo
// values (READ_TEXT) and simulation values (RECALLED, a check of scale, not a bound).
struct CellFreeLayerReference {
  std::string source;
  double diameter_um;
  double hematocrit;
  std::string hematocrit_kind;  // "systemic", "tube" or "discharge"
  double cell_free_layer_um;
  double uncertainty_um;
  std::string status;  // "READ_TEXT" or "RECALLED"
};
const std::vector<CellFreeLayerReference>& cell_free_layer_reference();

}  // namespace rbcsim::report
