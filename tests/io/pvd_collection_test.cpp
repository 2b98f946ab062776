// The .pvd collection lists every data set with its time, refuses names that would break the XML,
// and reads back what it wrote (a resumed run continues its collections).
#include "io/pvd_collection.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "common/errors.hpp"
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

TEST(PvdCollection, ReadsBackEveryEntryItWrote) {
  const rbcsim::testing::ScratchDirectory scratch;
  // Times whose shortest text has an exponent, or no short form at all.
  const std::vector<rbcsim::io::PvdEntry> entries = {
      {0.0, "vtk/fluid_000000000.vti"}, {1.1e-06, "vtk/fluid_000000013.vti"}, {0.1 + 0.2, "b.vti"}};
  rbcsim::io::write_pvd_collection(scratch.path() / "fluid.pvd", entries);
  const auto read = rbcsim::io::read_pvd_collection(scratch.path() / "fluid.pvd");
  ASSERT_EQ(read.size(), entries.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    EXPECT_EQ(read[i].timestep, entries[i].timestep) << i;
    EXPECT_EQ(read[i].file, entries[i].file) << i;
  }
  rbcsim::io::write_pvd_collection(scratch.path() / "empty.pvd", {});
  EXPECT_TRUE(rbcsim::io::read_pvd_collection(scratch.path() / "empty.pvd").empty());
}

// Each message names the file.
TEST(PvdCollection, ReadingRefusesATruncatedCollectionOrABadTime) {
  const rbcsim::testing::ScratchDirectory scratch;
  const auto truncated = scratch.write("truncated.pvd",
                                       "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\">\n"
                                       "  <Collection>\n");
  EXPECT_THROW(
      {
        try {
          rbcsim::io::read_pvd_collection(truncated);
        } catch (const rbcsim::InputError& error) {
          EXPECT_NE(std::string(error.what()).find("truncated.pvd"), std::string::npos);
          throw;
        }
      },
      rbcsim::InputError);
  const auto bad_time =
      scratch.write("bad_time.pvd",
                    "<VTKFile type=\"Collection\">\n<Collection>\n"
                    "<DataSet timestep=\"1e-3x\" group=\"\" part=\"0\" file=\"a.vtp\"/>\n"
                    "</Collection>\n</VTKFile>\n");
  EXPECT_THROW(rbcsim::io::read_pvd_collection(bad_time), rbcsim::InputError);
}

}  // namespace
