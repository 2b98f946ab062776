// The HDF5 writer on one process: rows land in their global places, in the declared types; the
// file appears complete or not at all; two writes of the same data are the same bytes, whenever
// they happen (no modification times). Across processes: tests/parallel/mpi.
#include "parallel/hdf5_file.hpp"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <thread>
#include <vector>

#include "common/errors.hpp"
#include "support/files.hpp"
#include "support/scratch_directory.hpp"

#ifdef RBCSIM_WITH_HDF5
#include <hdf5.h>
#endif

namespace rbcsim::parallel::hdf5_test {
namespace {

using Rows = Hdf5File::Rows;

#ifdef RBCSIM_WITH_HDF5

// Dataset `name` of `path` read back with the HDF5 library, as `memory_type`.
template <class T>
std::vector<T> read_dataset(const std::filesystem::path& path, const char* name, hid_t memory_type,
                            std::vector<hsize_t>& shape) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t dataset = H5Dopen2(file, name, H5P_DEFAULT);
  const hid_t space = H5Dget_space(dataset);
  shape.assign(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)), 0);
  H5Sget_simple_extent_dims(space, shape.data(), nullptr);
  std::vector<T> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  H5Dread(dataset, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Sclose(space);
  H5Dclose(dataset);
  H5Fclose(file);
  return values;
}

void write_example(const std::filesystem::path& path) {
  Hdf5File file(Communicator::self(), path);
  // Rows 0 and 1-3 as two ranges, as a process writes the vertices of two cells it owns.
  const std::array<std::size_t, 2> shape{4, 3};
  const std::array<Rows, 2> rows{Rows{0, 1}, Rows{1, 3}};
  const std::vector<double> values = {0, 1, 2, 10, 11, 12, 20, 21, 22, 30, 31, 32};
  file.write_rows("points_um", shape, rows, std::span<const double>(values));
  const std::array<std::size_t, 1> ids_shape{4};
  const std::array<Rows, 1> all{Rows{0, 4}};
  const std::vector<std::int32_t> ids = {7, -1, 2147483647, 0};
  file.write_rows("cell_id", ids_shape, all, std::span<const std::int32_t>(ids));
  const std::vector<std::uint8_t> mask = {0, 1, 2, 255};
  file.write_rows("solid_mask", ids_shape, all, std::span<const std::uint8_t>(mask));
  file.close();
}

TEST(Hdf5File, RowsLandInTheirGlobalPlacesInTheirTypes) {
  const rbcsim::testing::ScratchDirectory scratch;
  const auto path = scratch.path() / "a.h5";
  write_example(path);
  std::vector<hsize_t> shape;
  EXPECT_EQ(read_dataset<double>(path, "points_um", H5T_NATIVE_DOUBLE, shape),
            (std::vector<double>{0, 1, 2, 10, 11, 12, 20, 21, 22, 30, 31, 32}));
  EXPECT_EQ(shape, (std::vector<hsize_t>{4, 3}));
  EXPECT_EQ(read_dataset<std::int32_t>(path, "cell_id", H5T_NATIVE_INT32, shape),
            (std::vector<std::int32_t>{7, -1, 2147483647, 0}));
  EXPECT_EQ(read_dataset<std::uint8_t>(path, "solid_mask", H5T_NATIVE_UINT8, shape),
            (std::vector<std::uint8_t>{0, 1, 2, 255}));
}

// HDF5 stores each object's modification time unless told not to: two files a second apart
// would differ, and so would the same snapshot written on 1 and on 4 processes.
TEST(Hdf5File, TheSameDataAreTheSameBytesWhenWrittenLater) {
  const rbcsim::testing::ScratchDirectory scratch;
  write_example(scratch.path() / "first.h5");
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  write_example(scratch.path() / "second.h5");
  EXPECT_EQ(rbcsim::testing::read_text(scratch.path() / "first.h5"),
            rbcsim::testing::read_text(scratch.path() / "second.h5"));
}

TEST(Hdf5File, AFileNotClosedLeavesNothing) {
  const rbcsim::testing::ScratchDirectory scratch;
  const auto path = scratch.path() / "unfinished.h5";
  {
    Hdf5File file(Communicator::self(), path);
    const std::array<std::size_t, 1> shape{2};
    const std::array<Rows, 1> rows{Rows{0, 2}};
    const std::vector<double> values = {1.0, 2.0};
    file.write_rows("a", shape, rows, std::span<const double>(values));
  }
  EXPECT_TRUE(std::filesystem::is_empty(scratch.path()));
}

TEST(Hdf5File, RefusesValuesThatAreNotTheRowsNamed) {
  const rbcsim::testing::ScratchDirectory scratch;
  Hdf5File file(Communicator::self(), scratch.path() / "b.h5");
  const std::array<std::size_t, 2> shape{4, 3};
  const std::vector<double> five(5, 0.0);
  const std::vector<double> six(6, 0.0);
  const std::array<Rows, 1> two_rows{Rows{0, 2}};
  const std::array<Rows, 1> beyond{Rows{3, 2}};
  const std::array<Rows, 2> descending{Rows{2, 1}, Rows{0, 1}};
  EXPECT_THROW(file.write_rows("a", shape, two_rows, std::span<const double>(five)),
               std::invalid_argument);
  EXPECT_THROW(file.write_rows("b", shape, beyond, std::span<const double>(six)),
               std::invalid_argument);
  EXPECT_THROW(file.write_rows("c", shape, descending, std::span<const double>(six)),
               std::invalid_argument);
}

#else

TEST(Hdf5File, WithoutHdf5ItIsRefusedNamingTheOption) {
  EXPECT_FALSE(built_with_hdf5());
  const rbcsim::testing::ScratchDirectory scratch;
  try {
    Hdf5File file(Communicator::self(), scratch.path() / "a.h5");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("output.format"), std::string::npos);
  }
  EXPECT_TRUE(std::filesystem::is_empty(scratch.path()));
}

#endif

}  // namespace
}  // namespace rbcsim::parallel::hdf5_test
