#include "report/reference_data.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "config/embedded_share.hpp"
#include "io/csv_table.hpp"

namespace rbcsim::report {
namespace {

constexpr std::string_view kMillsFile = "reference/mills2004_stretch.csv";
constexpr std::string_view kPriesFile = "reference/pries_tube_flow.csv";
constexpr std::string_view kCellFreeLayerFile = "reference/cell_free_layer.csv";

io::CsvTable embedded_table(std::string_view file) {
  const auto text = config::find_embedded_share_file(file);
  // The build embeds share/reference; a binary without it is a build error, not bad input.
  if (!text) throw std::logic_error("share/" + std::string(file) + " is not embedded");
  return io::CsvTable::parse(*text, "share/" + std::string(file));
}

StretchReference read_mills2004() {
  const auto table = embedded_table(kMillsFile);
  return {table.numbers("force_pN"), table.numbers("axial_um"), table.numbers("axial_err_um"),
          table.numbers("transverse_um"), table.numbers("transverse_err_um")};
}

std::vector<TubeFlowReferenceRow> read_pries_table() {
  const auto table = embedded_table(kPriesFile);
  const auto diameter = table.numbers("diameter_um");
  const auto hematocrit = table.numbers("discharge_hematocrit");
  const auto viscosity = table.numbers("relative_apparent_viscosity");
  const auto ratio = table.numbers("tube_to_discharge_hematocrit_ratio");
  std::vector<TubeFlowReferenceRow> rows;
  for (std::size_t i = 0; i < diameter.size(); ++i) {
    rows.push_back({diameter[i], hematocrit[i], viscosity[i], ratio[i]});
  }
  return rows;
}

std::vector<CellFreeLayerReference> read_cell_free_layer() {
  const auto table = embedded_table(kCellFreeLayerFile);
  const auto source = table.strings("source");
  const auto diameter = table.numbers("diameter_um");
  const auto hematocrit = table.numbers("hematocrit");
  const auto kind = table.strings("hematocrit_kind");
  const auto layer = table.numbers("cfl_um");
  const auto uncertainty = table.numbers("cfl_uncertainty_um");
  const auto status = table.strings("status");
  std::vector<CellFreeLayerReference> rows;
  for (std::size_t i = 0; i < diameter.size(); ++i) {
    rows.push_back(
        {source[i], diameter[i], hematocrit[i], kind[i], layer[i], uncertainty[i], status[i]});
  }
  return rows;
}

}  // namespace

const StretchReference& mills2004_stretch() {
  static const StretchReference reference = read_mills2004();
  return reference;
}

double pries1992_relative_apparent_viscosity(double diameter_um, double discharge_hematocrit) {
  const double d = diameter_um;
  // Pries et al. 1992: the viscosity at H_D = 0.45, and the shape C(D) of its hematocrit law.
  const double at_045 =
      220.0 * std::exp(-1.3 * d) + 3.2 - 2.44 * std::exp(-0.06 * std::pow(d, 0.645));
  const double large_tube = 1.0 / (1.0 + 1e-11 * std::pow(d, 12.0));
  const double shape = (0.8 + std::exp(-0.075 * d)) * (large_tube - 1.0) + large_tube;
  return 1.0 + (at_045 - 1.0) * (std::pow(1.0 - discharge_hematocrit, shape) - 1.0) /
                   (std::pow(1.0 - 0.45, shape) - 1.0);
}

double pries1992_large_tube_relative_viscosity(double hematocrit) {
  return pries1992_relative_apparent_viscosity(std::numeric_limits<double>::infinity(), hematocrit);
}

double pries1990_tube_to_discharge_hematocrit(double diameter_um, double discharge_hematocrit) {
  const double d = diameter_um;
  return discharge_hematocrit + (1.0 - discharge_hematocrit) *
                                    (1.0 + 1.7 * std::exp(-0.415 * d) - 0.6 * std::exp(-0.011 * d));
}

const std::vector<TubeFlowReferenceRow>& pries_tube_flow_table() {
  static const auto rows = read_pries_table();
  return rows;
}

const std::vector<CellFreeLayerReference>& cell_free_layer_reference() {
  static const auto rows = read_cell_free_layer();
  return rows;
}

}  // namespace rbcsim::report
