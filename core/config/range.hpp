// Lists of values on the command line (--rates, --forces; docs/commands/README.md). The text is one
// or more comma-separated items, each
//   a number                "500"
//   start:stop:step         "0:2000:250"  -> 0, 250, ..., 2000 (stop included when it lands on a
//                                            step; a negative step counts down)
//   start:stop/count        "0:200/5"     -> 0, 50, 100, 150, 200 (count >= 2, evenly spaced)
//   start:stop              like start:stop/default_count (the caller's choice of resolution)
// Values keep the order written. Errors throw InputError(source, ...) quoting the item.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace rbcsim::config {

// The most values one range may expand to: more is a typo, not a sweep.
inline constexpr std::size_t kMaximumRangeValues = 100000;

std::vector<double> parse_range(std::string_view text, std::string_view source,
                                std::size_t default_count);

}  // namespace rbcsim::config
