#include "parallel/hdf5_file.hpp"

#include "common/errors.hpp"

#include <stdexcept>
#include <system_error>
#include <utility>

#ifdef RBCSIM_WITH_HDF5
#include <hdf5.h>
#include <mpi.h>
#endif

namespace rbcsim::parallel {

bool built_with_hdf5() {
#ifdef RBCSIM_WITH_HDF5
  return true;
#else
  return false;
#endif
}

namespace {

std::filesystem::path partial_path(const std::filesystem::path& path) {
  auto partial = path;
  partial += ".partial";
  return partial;
}

// Checks that `rows` lie in the shape, ascending and disjoint, and that `values` are theirs.
void check_rows(std::span<const std::size_t> shape, std::span<const Hdf5File::Rows> rows,
                std::size_t values, const std::string& name) {
  if (shape.empty()) throw std::invalid_argument("Hdf5File: dataset " + name + " without a shape");
  std::size_t per_row = 1;
  for (std::size_t d = 1; d < shape.size(); ++d) per_row *= shape[d];
  std::size_t next = 0;
  std::size_t total = 0;
  for (const auto& range : rows) {
    if (range.first < next || range.first + range.count > shape[0]) {
      throw std::invalid_argument("Hdf5File: rows " + std::to_string(range.first) + " to " +
                                  std::to_string(range.first + range.count) + " of dataset " +
                                  name + " overlap, descend or lie beyond its " +
                                  std::to_string(shape[0]));
    }
    next = range.first + range.count;
    total += range.count;
  }
  if (total * per_row != values) {
    throw std::invalid_argument("Hdf5File: " + std::to_string(values) + " values of dataset " +
                                name + " for " + std::to_string(total) + " rows of " +
                                std::to_string(per_row));
  }
}

}  // namespace

#ifdef RBCSIM_WITH_HDF5

namespace {

// An HDF5 identifier closed with its scope.
class Id {
 public:
  Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Id() {
    if (id_ >= 0) close_(id_);
  }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  hid_t get() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void check(herr_t status, const char* what, const std::filesystem::path& file) {
  if (status < 0) {
    throw RuntimeFailure("hdf5: " + std::string(what) + " failed for " + file.string());
  }
}
hid_t checked(hid_t id, const char* what, const std::filesystem::path& file) {
  check(id < 0 ? -1 : 0, what, file);
  return id;
}

const MPI_Comm* comm_of(const Communicator& communicator) {
  return static_cast<const MPI_Comm*>(communicator.mpi_comm());
}

}  // namespace

Hdf5File::Hdf5File(Communicator communicator, std::filesystem::path path)
    : communicator_(std::move(communicator)),
      path_(std::move(path)),
      partial_(partial_path(path_)) {
  // Errors come back as status codes and become exceptions here, not HDF5's printed stacks.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  Id access(checked(H5Pcreate(H5P_FILE_ACCESS), "a file access list", path_), H5Pclose);
  if (const MPI_Comm* comm = comm_of(communicator_)) {
    check(H5Pset_fapl_mpio(access.get(), *comm, MPI_INFO_NULL), "MPI-IO access", path_);
  }
  Id creation(checked(H5Pcreate(H5P_FILE_CREATE), "a file creation list", path_), H5Pclose);
  check(H5Pset_obj_track_times(creation.get(), false), "untimed root group", path_);
  file_ = checked(H5Fcreate(partial_.c_str(), H5F_ACC_TRUNC, creation.get(), access.get()),
                  "creating the file", partial_);
}

Hdf5File::~Hdf5File() {
  if (file_ < 0) return;
  H5Fclose(file_);
  if (communicator_.is_root()) {
    std::error_code ignored;
    std::filesystem::remove(partial_, ignored);
  }
}

void Hdf5File::write(const std::string& name, std::span<const std::size_t> shape,
                     std::span<const Rows> rows, const void* values, std::size_t count,
                     Element element) {
  // Every process throws, or none: one process leaving the collective calls below would leave the
  // others waiting in them.
  std::string problem;
  try {
    check_rows(shape, rows, count, name);
  } catch (const std::invalid_argument& error) {
    problem = error.what();
  }
  if (communicator_.any(!problem.empty())) {
    throw std::invalid_argument(problem.empty() ? "Hdf5File: another process's rows of dataset " +
                                                      name + " are not whole rows of its shape"
                                                : problem);
  }
  std::vector<hsize_t> dimensions(shape.begin(), shape.end());
  const auto rank = static_cast<int>(dimensions.size());
  Id file_space(checked(H5Screate_simple(rank, dimensions.data(), nullptr), "a dataspace", path_),
                H5Sclose);
  // Untimed, allocated at creation and never filled: the bytes are the data's alone, on any
  // process count.
  Id creation(checked(H5Pcreate(H5P_DATASET_CREATE), "a dataset creation list", path_), H5Pclose);
  check(H5Pset_obj_track_times(creation.get(), false), "untimed datasets", path_);
  check(H5Pset_alloc_time(creation.get(), H5D_ALLOC_TIME_EARLY), "early allocation", path_);
  check(H5Pset_fill_time(creation.get(), H5D_FILL_TIME_NEVER), "no fill", path_);
  const hid_t file_type = element == Element::float64 ? H5T_IEEE_F64LE
                          : element == Element::int32 ? H5T_STD_I32LE
                                                      : H5T_STD_U8LE;
  const hid_t memory_type = element == Element::float64 ? H5T_NATIVE_DOUBLE
                            : element == Element::int32 ? H5T_NATIVE_INT32
                                                        : H5T_NATIVE_UINT8;
  Id dataset(checked(H5Dcreate2(file_, name.c_str(), file_type, file_space.get(), H5P_DEFAULT,
                                creation.get(), H5P_DEFAULT),
                     ("creating dataset " + name).c_str(), path_),
             H5Dclose);
  const hsize_t memory_count = count > 0 ? count : 1;
  Id memory_space(checked(H5Screate_simple(1, &memory_count, nullptr), "a dataspace", path_),
                  H5Sclose);
  check(H5Sselect_none(file_space.get()), "selecting rows", path_);
  if (count == 0) check(H5Sselect_none(memory_space.get()), "selecting no rows", path_);
  std::vector<hsize_t> start(dimensions.size(), 0);
  std::vector<hsize_t> extent = dimensions;
  for (const auto& range : rows) {
    if (range.count == 0) continue;
    start[0] = range.first;
    extent[0] = range.count;
    check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_OR, start.data(), nullptr, extent.data(),
                              nullptr),
          "selecting rows", path_);
  }
  Id transfer(checked(H5Pcreate(H5P_DATASET_XFER), "a transfer list", path_), H5Pclose);
  if (comm_of(communicator_) != nullptr) {
    check(H5Pset_dxpl_mpio(transfer.get(), H5FD_MPIO_COLLECTIVE), "collective writes", path_);
  }
  const herr_t written = H5Dwrite(dataset.get(), memory_type, memory_space.get(), file_space.get(),
                                  transfer.get(), values);
  if (communicator_.any(written < 0)) {
    throw RuntimeFailure("hdf5: writing dataset " + name + " failed for " + partial_.string() +
                         (written < 0 ? "" : " (on another process)"));
  }
}

void Hdf5File::close() {
  if (file_ < 0) return;
  const hid_t file = file_;
  file_ = -1;
  // Agreed (any()) after the close, so that every process's part is in the file, and after the
  // rename, so that the file is there for whoever reads it next; a failure throws everywhere.
  if (communicator_.any(H5Fclose(file) < 0)) {
    std::error_code ignored;
    if (communicator_.is_root()) std::filesystem::remove(partial_, ignored);
    throw RuntimeFailure("hdf5: closing " + partial_.string() + " failed");
  }
  std::error_code renamed;
  if (communicator_.is_root()) std::filesystem::rename(partial_, path_, renamed);
  if (communicator_.any(static_cast<bool>(renamed))) {
    throw RuntimeFailure("hdf5: renaming " + partial_.string() + " to " + path_.string() +
                         " failed" + (renamed ? ": " + renamed.message() : ""));
  }
}

#else  // without HDF5

Hdf5File::Hdf5File(Communicator communicator, std::filesystem::path path)
    : communicator_(std::move(communicator)),
      path_(std::move(path)),
      partial_(partial_path(path_)) {
  throw InputError("output.format",
                   "hdf5: this rbcsim was built without HDF5 (cmake -DRBCSIM_HDF5=ON, with "
                   "libhdf5-openmpi-dev; scripts/setup.sh does)");
}
Hdf5File::~Hdf5File() = default;
void Hdf5File::write(const std::string& name, std::span<const std::size_t> shape,
                     std::span<const Rows> rows, const void* /*values*/, std::size_t count,
                     Element /*element*/) {
  check_rows(shape, rows, count, name);
}
void Hdf5File::close() {}

#endif

void Hdf5File::write_rows(const std::string& name, std::span<const std::size_t> shape,
                          std::span<const Rows> rows, std::span<const double> values) {
  write(name, shape, rows, values.data(), values.size(), Element::float64);
}
void Hdf5File::write_rows(const std::string& name, std::span<const std::size_t> shape,
                          std::span<const Rows> rows, std::span<const std::int32_t> values) {
  write(name, shape, rows, values.data(), values.size(), Element::int32);
}
void Hdf5File::write_rows(const std::string& name, std::span<const std::size_t> shape,
                          std::span<const Rows> rows, std::span<const std::uint8_t> values) {
  write(name, shape, rows, values.data(), values.size(), Element::uint8);
}

}  // namespace rbcsim::parallel
