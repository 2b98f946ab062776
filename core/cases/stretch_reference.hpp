// Comparison of a stretch curve with measured data: Mills, Qie, Dao, Lim, Suresh (2004), Fig. 8
// (share/reference/mills2004_stretch.csv: mean diameters and the ends of their error bars).
//
// At every reference force inside the simulated force range the simulated diameters are taken at
// that force (linearly interpolated between the two simulated forces around it when it was not
// simulated; never extrapolated). Reported: the RMS deviation from the reference means, and how
// many reference forces have the simulated value inside the error bar [low, high] as digitised
// (the bars are not centred on the means, so the digitised ends are used, not mean +- err).
// Only converged points enter.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "cases/stretch_case.hpp"
#include "io/csv_table.hpp"

namespace rbcsim::cases {

struct MeasuredDiameter {
  double mean_um = 0.0;
  double bar_low_um = 0.0;
  double bar_high_um = 0.0;
  bool contains(double value_um) const { return bar_low_um <= value_um && value_um <= bar_high_um; }
  // (value - mean)^2 over the square of the bar's half on value's side: under 1 exactly when
  // value is inside the bar (the bars are not centred on the means).
  double misfit(double value_um) const {
    if (value_um == mean_um) return 0.0;  // also where a bar ends at its mean
    const double half_bar_um = value_um < mean_um ? mean_um - bar_low_um : bar_high_um - mean_um;
    const double deviation = (value_um - mean_um) / half_bar_um;
    return deviation * deviation;
  }
};

struct StretchReferencePoint {
  double force_pN = 0.0;
  MeasuredDiameter axial;
  MeasuredDiameter transverse;
};

// From a table with the columns force_pN, axial_um, axial_bar_low_um, axial_bar_high_um,
// transverse_um, transverse_bar_low_um, transverse_bar_high_um (InputError otherwise).
std::vector<StretchReferencePoint> stretch_reference_from(const io::CsvTable& table);

struct StretchComparison {
  std::size_t point_count = 0;         // reference forces compared
  std::optional<double> rms_axial_um;  // empty when point_count is 0
  std::optional<double> rms_transverse_um;
  std::size_t inside_error_bars = 0;  // forces with both diameters inside their bars
  std::size_t axial_inside_error_bar = 0;
  std::size_t transverse_inside_error_bar = 0;
  // Sum of MeasuredDiameter::misfit over the forces compared and both diameters: a chi-square
  // with the error bars as standard deviations, what the calibrate stretch fit minimises.
  double misfit = 0.0;
};

StretchComparison compare_with_reference(std::span<const StretchPoint> simulated,
                                         std::span<const StretchReferencePoint> reference);

}  // namespace rbcsim::cases
