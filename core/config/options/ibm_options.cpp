#include <string>
#include <vector>

#include "config/options/option_areas.hpp"
#include "coupling/coupled_simulation.hpp"
#include "ibm/delta_kernels.hpp"
#include "ibm/point_advance.hpp"

namespace rbcsim::config {
namespace {

// The choices are the names of the IBM module's tables, the defaults the coupled loop's: one source
// of truth each.
const coupling::CouplingParameters kIbmDefaults{};

template <typename Table>
std::vector<std::string> names_of(const Table& table) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.emplace_back(entry.name);
  return names;
}

}  // namespace

void add_ibm_options(OptionTable& table) {
  table.add_choice("ibm.kernel", names_of(ibm::delta_kernels()), kIbmDefaults.kernel,
                   "Immersed-boundary kernel: phi2 (trilinear, HemoCell's default), phi3, phi4 "
                   "(Peskin).");
  table.add_choice("ibm.point_advance", names_of(ibm::point_advance_schemes()),
                   kIbmDefaults.point_advance,
                   "How vertices follow the interpolated velocity: euler (x += u dt, HemoCell's "
                   "scheme) or ab2 (second-order Adams-Bashforth).");
}

}  // namespace rbcsim::config
