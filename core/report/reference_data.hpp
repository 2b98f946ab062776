// Measured data the report plots runs against, compiled into the binary from share/reference
// (see core/config/CMakeLists.txt), so a report needs no file beside the runs.
#pragma once

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

}  // namespace rbcsim::report
