// SIGKILL leaves a program no chance to clean up, so what a killed run leaves must already be
// whole (docs/architecture.md): every file is written to a temporary sibling
// (".<name>.tmp<random>") and renamed, so a file with its final name is always complete. The
// mechanism's own test (AtomicFile.KilledMidWrite..., tests/io) kills a process inside a write;
// this one kills the whole command while it writes a membrane and a fluid snapshot every step, and
// checks every file it left under its final name, so an output written around io/atomic_file fails
// it whenever the kill lands inside that write.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/files.hpp"
#include "support/run_rbcsim.hpp"
#include "support/scratch_directory.hpp"
#include "support/xml_document.hpp"

namespace {

namespace fs = std::filesystem;

bool is_temporary(const fs::path& file) { return file.filename().string().starts_with("."); }

// Empty if `file` is complete for its kind, else what is wrong with it.
std::string defect_of(const fs::path& file) {
  const auto extension = file.extension().string();
  const auto text = rbcsim::testing::read_text(file);
  if (extension == ".vtp" || extension == ".vti" || extension == ".pvd") {
    return rbcsim::testing::parse_xml(text).error;
  }
  if (extension == ".json") {
    return nlohmann::json::accept(text) ? "" : "not valid JSON";
  }
  if (extension == ".csv") {
    return !text.empty() && text.back() == '\n' ? "" : "does not end with a complete line";
  }
  return "";
}

TEST(KilledRun, EveryFileWithItsFinalNameIsComplete) {
  const rbcsim::testing::ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  // The coarse capillary of capillary_case_test.cpp (dx = 1 um, the 162-vertex cell).
  const std::string arguments =
      "capillary --quiet --threads 1 --set mesh.subdivisions=2 --set mesh.method=parametric --set "
      "lattice.spacing_um=1"
      " --set capillary.throat_diameter_um=9 --set capillary.inlet_velocity_m_per_s=0.014"
      " --set capillary.fluid_tolerance=1e-5 --set output.membrane_interval_s=1e-12"
      " --set output.fluid_interval_s=1e-12 --output '" +
      run_dir.string() + "'";
  // Killed once the coupled run has written its first snapshots (the initial state).
  EXPECT_EQ(rbcsim::testing::run_rbcsim_signalled_once(run_dir / "vtk" / "fluid_000000001.vti",
                                                       arguments, "KILL"),
            128 + 9);
  std::size_t complete_files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(run_dir)) {
    if (!entry.is_regular_file() || is_temporary(entry.path())) continue;
    EXPECT_EQ(defect_of(entry.path()), "") << entry.path();
    ++complete_files;
  }
  // config.json and at least two steps of snapshots were checked.
  EXPECT_GE(complete_files, 5u);
}

}  // namespace
