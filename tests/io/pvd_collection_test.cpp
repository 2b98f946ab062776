// The .pvd collection lists every data set with its time, and refuses names that would break the
// XML.
#include "io/pvd_collection.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "support/run_rbcsim.hpp"
#include "support/scratch_directory.hpp"

namespace {

TEST(PvdCollection, ListsEachDataSetWithItsTime) {
  const rbcsim::testing::ScratchDirectory scratch;
  const std::vector<rbcsim::io::PvdEntry> entries = {{0.0, "vtk/cell0_000000000.vtp"},
                                                     {2.5e-4, "vtk/cell0_000000100.vtp"}};
  rbcsim::io::write_pvd_collection(scratch.path() / "cell0.pvd", entries);
  const auto text = rbcsim::testing::read_text(scratch.path() / "cell0.pvd");
  EXPECT_NE(text.find("<VTKFile type=\"Collection\""), std::string::npos);
  EXPECT_NE(text.find("<DataSet timestep=\"0\" group=\"\" part=\"0\" "
                      "file=\"vtk/cell0_000000000.vtp\"/>"),
            std::string::npos);
  EXPECT_NE(text.find("timestep=\"0.00025\""), std::string::npos);
}

TEST(PvdCollection, RefusesEmptyOrMarkupFileNames) {
  const rbcsim::testing::ScratchDirectory scratch;
  const std::vector<rbcsim::io::PvdEntry> markup = {{0.0, "a\"b.vtp"}};
  EXPECT_THROW(rbcsim::io::write_pvd_collection(scratch.path() / "x.pvd", markup),
               std::invalid_argument);
  const std::vector<rbcsim::io::PvdEntry> empty = {{0.0, ""}};
  EXPECT_THROW(rbcsim::io::write_pvd_collection(scratch.path() / "x.pvd", empty),
               std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(scratch.path() / "x.pvd"));
}

}  // namespace
