// One HDF5 file written together by the processes of a communicator: parallel HDF5 over MPI-IO
// when the communicator spans several processes, HDF5's plain POSIX driver on one. Each dataset
// has a global layout (its rows: lattice planes, or vertices cell after cell) and every process
// writes its own rows into it, so that a snapshot is never gathered onto one process.
//
// The file's bytes do not depend on the process count: the same datasets are created in the same
// order, contiguous, their space allocated at creation with no fill pass, and without the
// modification times HDF5 otherwise stores in each object header. Like every output of rbcsim the
// file appears complete or not at all (io/atomic_file.hpp): it is written as <path>.partial and
// renamed when closed.
//
// A failure on one process (rows that do not fit, a write, the close) throws on every process, so
// that none is left waiting in a collective call.
//
// Built with RBCSIM_HDF5 (Debian's libhdf5-openmpi-dev); without it the constructor throws
// rbcsim::InputError and built_with_hdf5() says so, for the option that asks for it to refuse
// early.
#pragma once

#include "parallel/communicator.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace rbcsim::parallel {

bool built_with_hdf5();

class Hdf5File {
 public:
  // Collective: creates <path>.partial (truncating one left by a killed run). The directory must
  // exist. Throws rbcsim::InputError without HDF5, rbcsim::RuntimeFailure naming the file if HDF5
  // refuses.
  Hdf5File(Communicator communicator, std::filesystem::path path);
  // Closes and removes an unfinished file (a throw between creation and close()).
  ~Hdf5File();
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;

  // Rows [first, first + count) of a dataset.
  struct Rows {
    std::size_t first = 0;
    std::size_t count = 0;
  };
  // Collective: the dataset `name` of `shape` (row-major; shape[0] rows), of which this process
  // writes the rows `rows` (disjoint, ascending; none: an empty list) from `values`, those rows
  // one after the other. Every process passes the same name and shape. Throws
  // std::invalid_argument if the values are not those rows' or a row lies outside the shape.
  void write_rows(const std::string& name, std::span<const std::size_t> shape,
                  std::span<const Rows> rows, std::span<const double> values);
  void write_rows(const std::string& name, std::span<const std::size_t> shape,
                  std::span<const Rows> rows, std::span<const std::int32_t> values);
  void write_rows(const std::string& name, std::span<const std::size_t> shape,
                  std::span<const Rows> rows, std::span<const std::uint8_t> values);

  // Collective: closes the file and renames it to `path`.
  void close();

 private:
  enum class Element { float64, int32, uint8 };
  void write(const std::string& name, std::span<const std::size_t> shape,
             std::span<const Rows> rows, const void* values, std::size_t count, Element element);

  Communicator communicator_;
  std::filesystem::path path_;
  std::filesystem::path partial_;
  std::int64_t file_ = -1;  // the HDF5 file (hid_t); -1: closed
};

}  // namespace rbcsim::parallel
