#include "report/reference_data.hpp"

#include <stdexcept>
#include <string>

#include "config/embedded_share.hpp"
#include "io/csv_table.hpp"

namespace rbcsim::report {
namespace {

constexpr std::string_view kMillsFile = "reference/mills2004_stretch.csv";

StretchReference read_mills2004() {
  const auto text = config::find_embedded_share_file(kMillsFile);
  // The build embeds share/reference; a binary without it is a build error, not bad input.
  if (!text) throw std::logic_error("share/" + std::string(kMillsFile) + " is not embedded");
  const auto table = io::CsvTable::parse(*text, "share/" + std::string(kMillsFile));
  return {table.numbers("force_pN"), table.numbers("axial_um"), table.numbers("axial_err_um"),
          table.numbers("transverse_um"), table.numbers("transverse_err_um")};
}

}  // namespace

const StretchReference& mills2004_stretch() {
  static const StretchReference reference = read_mills2004();
  return reference;
}

}  // namespace rbcsim::report
