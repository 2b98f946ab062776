// Ctrl-C (docs/architecture.md): the time loops stop at the next iteration once the interrupt flag
// is set, the stretch keeps the points it reached, and `rbcsim stretch` killed with SIGINT exits
// 130 with a result.json of status "interrupted" and no half-written file.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "cases/fire_relaxation.hpp"
#include "cases/stretch_case.hpp"
#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "io/csv_table.hpp"
#include "membrane/membrane_model.hpp"
#include "membrane/relaxation.hpp"
#include "mesh/cell_shapes.hpp"
#include "support/interrupt_scope.hpp"
#include "support/run_rbcsim.hpp"
#include "support/run_result.hpp"
#include "support/scratch_directory.hpp"

namespace {

namespace fs = std::filesystem;
using rbcsim::testing::read_text;
using rbcsim::testing::ScratchDirectory;

using rbcsim::testing::InterruptScope;

rbcsim::cases::StretchCell coarse_cell() {
  return rbcsim::cases::prepare_stretch_cell(
      rbcsim::mesh::generate_cell("discocyte", 2, rbcsim::mesh::CellShapeParameters{}), {});
}

TEST(Interrupt, BothRelaxationsStopAtTheirNextIteration) {
  const InterruptScope scope;
  const auto cell = coarse_cell();
  const rbcsim::membrane::MembraneModel model(cell.mesh, rbcsim::membrane::MembraneParameters{});
  auto positions_um = cell.mesh.positions_um;
  const rbcsim::membrane::RelaxationSettings settings;
  rbcsim::request_interrupt(SIGTERM);
  EXPECT_THROW(rbcsim::cases::relax_membrane_fire(model, positions_um, {}, settings),
               rbcsim::Interrupted);
  EXPECT_THROW(rbcsim::membrane::relax_membrane(model, positions_um, {}, settings),
               rbcsim::Interrupted);
  EXPECT_EQ(positions_um, cell.mesh.positions_um);  // not a single step taken
}

TEST(Interrupt, StretchKeepsThePointsReachedBeforeIt) {
  const InterruptScope scope;
  const auto cell = coarse_cell();
  const rbcsim::membrane::MembraneModel model(cell.mesh, rbcsim::membrane::MembraneParameters{});
  rbcsim::cases::StretchSettings settings;
  settings.forces_pN = {0.0, 10.0, 20.0};
  // The signal arrives while the first point is being written.
  const auto run = rbcsim::cases::run_stretch(
      model, cell, settings, [](const auto&) { rbcsim::request_interrupt(SIGINT); });
  EXPECT_TRUE(run.interrupted);
  EXPECT_FALSE(run.ok());
  ASSERT_EQ(run.points.size(), 1u);
  EXPECT_TRUE(run.points[0].converged);
  EXPECT_EQ(run.failure, "F = 10 pN: interrupted by SIGINT");
}

// Starts rbcsim with `arguments` (no shell), stdout and stderr into `scratch`.
pid_t start_rbcsim(const std::vector<std::string>& arguments, const fs::path& scratch) {
  const pid_t child = fork();
  if (child == 0) {
    const int out = open((scratch / "stdout.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open((scratch / "stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(out, STDOUT_FILENO);
    dup2(err, STDERR_FILENO);
    std::vector<char*> argv{const_cast<char*>(RBCSIM_BINARY)};
    for (const auto& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    execv(RBCSIM_BINARY, argv.data());
    _exit(127);
  }
  return child;
}

bool wait_for_file(const fs::path& file, std::chrono::seconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (!fs::exists(file)) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

// Every file of the run directory is complete: JSON parses, CSV reads, VTK files are closed, and
// no temporary file is left.
void expect_every_file_complete(const fs::path& run_dir) {
  for (const auto& entry : fs::recursive_directory_iterator(run_dir)) {
    if (!entry.is_regular_file()) continue;
    const auto& file = entry.path();
    const auto extension = file.extension().string();
    const auto text = read_text(file);
    if (extension == ".json") {
      EXPECT_TRUE(nlohmann::json::accept(text)) << file;
    } else if (extension == ".csv") {
      EXPECT_NO_THROW({ [[maybe_unused]] const auto table = rbcsim::io::read_csv_file(file); })
          << file;
    } else if (extension == ".vtp" || extension == ".pvd") {
      EXPECT_NE(text.find("</VTKFile>"), std::string::npos) << file;
    } else {
      ADD_FAILURE() << "unexpected file (a temporary one left behind?) " << file;
    }
  }
}

TEST(Interrupt, SigintWritesTheResultsSoFarAndExits130) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  // 401 forces on a 642-vertex cell take half a minute: the signal comes long before the end.
  const pid_t child = start_rbcsim({"stretch", "--set", "mesh.subdivisions=3", "--forces",
                                    "0:400:1", "--threads", "1", "--output", run_dir.string()},
                                   scratch.path());
  ASSERT_TRUE(wait_for_file(run_dir / "shapes/stretch_000.vtp", std::chrono::seconds(60)));
  kill(child, SIGINT);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), rbcsim::kExitInterrupted);
  const auto err = read_text(scratch.path() / "stderr.txt");
  EXPECT_EQ(err.rfind("rbcsim: stopped: stretch: F = ", 0), 0u) << err;
  EXPECT_NE(err.find("interrupted by SIGINT\n"), std::string::npos) << err;

  const auto result = nlohmann::json::parse(read_text(run_dir / "result.json"));
  EXPECT_EQ(result["status"], "interrupted");
  EXPECT_NE(result["failure"].get<std::string>().find("interrupted by SIGINT"), std::string::npos);
  EXPECT_GE(result["stretch"]["points"].size(), 1u);
  EXPECT_EQ(rbcsim::testing::result_schema_problems(result), std::vector<std::string>{});
  expect_every_file_complete(run_dir);
}

}  // namespace
