#include "parallel/communicator.hpp"

#include "common/errors.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <limits>
#include <string>
#include <thread>
#include <utility>

#ifdef RBCSIM_WITH_MPI
#include <mpi.h>
#endif

namespace rbcsim::parallel {

namespace {
bool session_active = false;
}  // namespace

#ifdef RBCSIM_WITH_MPI
namespace {
MPI_Comm failure_comm = MPI_COMM_NULL;  // MPI_COMM_WORLD's duplicate for failure agreement
}  // namespace
#endif

bool built_with_mpi() {
#ifdef RBCSIM_WITH_MPI
  return true;
#else
  return false;
#endif
}

bool launched_by_mpi() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(variable) != nullptr) return true;
  }
  return false;
}

int launcher_process_count() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    if (const char* value = std::getenv(variable)) {
      const int count = std::atoi(value);
      return count > 0 ? count : 1;
    }
  }
  return 1;
}

#ifdef RBCSIM_WITH_MPI

struct Communicator::Handle {
  MPI_Comm comm;
};

namespace {
// MPI counts and displacements are ints: a message of more values is refused, not wrapped.
int mpi_count(std::size_t values, const char* what) {
  if (values > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw RuntimeFailure(std::string("mpi: ") + what + " of " + std::to_string(values) +
                         " values exceeds MPI's int counts (2^31 - 1)");
  }
  return static_cast<int>(values);
}

void check_mpi(int code, const char* what) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw RuntimeFailure(std::string("mpi: ") + what + " failed: " + std::string(text, length));
}
}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
  if (!launched_by_mpi()) return;
  // Errors come back as codes (check_mpi turns them into RuntimeFailure), not as MPI's abort.
  // Funneled: OpenMP threads compute, only the main thread calls MPI.
  int provided = 0;
  check_mpi(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  check_mpi(MPI_Comm_dup(MPI_COMM_WORLD, &failure_comm), "MPI_Comm_dup");
  session_active = true;
}

MpiSession::~MpiSession() {
  if (!session_active) return;
  MPI_Comm_free(&failure_comm);
  MPI_Finalize();
  session_active = false;
}

Communicator Communicator::world() {
  if (!session_active) return Communicator(nullptr, 0, 1);
  int rank = 0;
  int size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return Communicator(std::make_shared<const Handle>(Handle{MPI_COMM_WORLD}), rank, size);
}

Communicator Communicator::self() { return Communicator(nullptr, 0, 1); }

bool every_process_fails_together(double timeout_s) {
  if (!session_active) return true;
  MPI_Request request = MPI_REQUEST_NULL;
  if (MPI_Ibarrier(failure_comm, &request) != MPI_SUCCESS) return false;
  const double start = MPI_Wtime();
  int done = 0;
  while (MPI_Test(&request, &done, MPI_STATUS_IGNORE) == MPI_SUCCESS && done == 0) {
    if (MPI_Wtime() - start > timeout_s) return false;  // the barrier is left pending: aborting
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return done != 0;
}

void Communicator::send_receive(std::span<const double> send, int destination,
                                std::span<double> receive, int source, int tag) const {
  if (!handle_) {
    if (send.size() != receive.size()) {
      throw RuntimeFailure("mpi: a process sent itself " + std::to_string(send.size()) +
                           " values for " + std::to_string(receive.size()));
    }
    std::copy(send.begin(), send.end(), receive.begin());
    return;
  }
  MPI_Status status;
  check_mpi(
      MPI_Sendrecv(send.data(), mpi_count(send.size(), "a halo message"), MPI_DOUBLE, destination,
                   tag, receive.data(), mpi_count(receive.size(), "a halo message"), MPI_DOUBLE,
                   source, tag, handle_->comm, &status),
      "MPI_Sendrecv");
  int received = 0;
  MPI_Get_count(&status, MPI_DOUBLE, &received);
  if (static_cast<std::size_t>(received) != receive.size()) {
    throw RuntimeFailure("mpi: rank " + std::to_string(rank_) + " received " +
                         std::to_string(received) + " values from rank " + std::to_string(source) +
                         ", expected " + std::to_string(receive.size()));
  }
}

std::vector<double> Communicator::gather_to_root(std::span<const double> values) const {
  if (!handle_) return {values.begin(), values.end()};
  const int count = mpi_count(values.size(), "a gather");
  std::vector<int> counts(is_root() ? size_ : 0);
  check_mpi(MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, handle_->comm),
            "MPI_Gather");
  std::vector<int> offsets(counts.size(), 0);
  std::vector<double> gathered;
  if (is_root()) {
    std::size_t total = 0;
    for (int r = 0; r < size_; ++r) {
      offsets[r] = mpi_count(total, "a gather");
      total += static_cast<std::size_t>(counts[r]);
    }
    mpi_count(total, "a gather");
    gathered.resize(total);
  }
  check_mpi(MPI_Gatherv(values.data(), count, MPI_DOUBLE, gathered.data(), counts.data(),
                        offsets.data(), MPI_DOUBLE, 0, handle_->comm),
            "MPI_Gatherv");
  return gathered;
}

std::vector<double> Communicator::gather_to_all(std::span<const double> values) const {
  if (!handle_) return {values.begin(), values.end()};
  const int count = mpi_count(values.size(), "a gather");
  std::vector<int> counts(static_cast<std::size_t>(size_));
  check_mpi(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, handle_->comm),
            "MPI_Allgather");
  std::vector<int> offsets(counts.size(), 0);
  std::size_t total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    offsets[r] = mpi_count(total, "a gather");
    total += static_cast<std::size_t>(counts[r]);
  }
  mpi_count(total, "a gather");
  std::vector<double> gathered(total);
  check_mpi(MPI_Allgatherv(values.data(), count, MPI_DOUBLE, gathered.data(), counts.data(),
                           offsets.data(), MPI_DOUBLE, handle_->comm),
            "MPI_Allgatherv");
  return gathered;
}

std::vector<double> Communicator::scatter_from_root(
    const std::vector<std::vector<double>>& per_rank, std::size_t count) const {
  if (!handle_) {
    if (per_rank.size() != 1 || per_rank[0].size() != count) {
      throw RuntimeFailure("mpi: a process scattered to itself values of the wrong count");
    }
    return per_rank[0];
  }
  std::vector<int> counts;
  std::vector<int> offsets;
  std::vector<double> flat;
  if (is_root()) {
    if (per_rank.size() != static_cast<std::size_t>(size_)) {
      throw RuntimeFailure("mpi: a scatter needs one slice per process");
    }
    for (const auto& slice : per_rank) {
      offsets.push_back(mpi_count(flat.size(), "a scatter"));
      counts.push_back(mpi_count(slice.size(), "a scatter"));
      flat.insert(flat.end(), slice.begin(), slice.end());
    }
  }
  std::vector<double> mine(count);
  int my_count = 0;
  check_mpi(MPI_Scatter(counts.data(), 1, MPI_INT, &my_count, 1, MPI_INT, 0, handle_->comm),
            "MPI_Scatter");
  if (static_cast<std::size_t>(my_count) != count) {
    throw RuntimeFailure("mpi: rank " + std::to_string(rank_) + " was sent " +
                         std::to_string(my_count) + " values, expected " + std::to_string(count));
  }
  check_mpi(MPI_Scatterv(flat.data(), counts.data(), offsets.data(), MPI_DOUBLE, mine.data(),
                         my_count, MPI_DOUBLE, 0, handle_->comm),
            "MPI_Scatterv");
  return mine;
}

Communicator Communicator::split(int colour) const {
  if (!handle_) return *this;
  MPI_Comm part;
  check_mpi(MPI_Comm_split(handle_->comm, colour, rank_, &part), "MPI_Comm_split");
  int rank = 0;
  int size = 1;
  MPI_Comm_rank(part, &rank);
  MPI_Comm_size(part, &size);
  MPI_Comm_set_errhandler(part, MPI_ERRORS_RETURN);
  // Freed with the last copy, before MPI_Finalize as long as the communicator does not outlive
  // the session.
  auto handle = std::shared_ptr<const Handle>(new Handle{part}, [](const Handle* owned) {
    MPI_Comm comm = owned->comm;
    if (session_active) MPI_Comm_free(&comm);
    delete owned;
  });
  return Communicator(std::move(handle), rank, size);
}

void Communicator::broadcast_from_root(std::span<double> values) const {
  if (!handle_) return;
  check_mpi(MPI_Bcast(values.data(), mpi_count(values.size(), "a broadcast"), MPI_DOUBLE, 0,
                      handle_->comm),
            "MPI_Bcast");
}

bool Communicator::any(bool local) const {
  if (!handle_) return local;
  int value = local ? 1 : 0;
  int result = 0;
  check_mpi(MPI_Allreduce(&value, &result, 1, MPI_INT, MPI_LOR, handle_->comm), "MPI_Allreduce");
  return result != 0;
}

double Communicator::max(double local) const {
  if (!handle_) return local;
  double result = local;
  check_mpi(MPI_Allreduce(&local, &result, 1, MPI_DOUBLE, MPI_MAX, handle_->comm), "MPI_Allreduce");
  return result;
}

void Communicator::barrier() const {
  if (handle_) check_mpi(MPI_Barrier(handle_->comm), "MPI_Barrier");
}

void Communicator::abort(int exit_code) const {
  if (handle_) MPI_Abort(handle_->comm, exit_code);
  std::exit(exit_code);
}

#else  // one process, no MPI

struct Communicator::Handle {};

MpiSession::MpiSession(int& /*argc*/, char**& /*argv*/) {}
MpiSession::~MpiSession() = default;

Communicator Communicator::world() { return Communicator(nullptr, 0, 1); }
Communicator Communicator::self() { return Communicator(nullptr, 0, 1); }

void Communicator::send_receive(std::span<const double> send, int /*destination*/,
                                std::span<double> receive, int /*source*/, int /*tag*/) const {
  if (send.size() != receive.size()) {
    throw RuntimeFailure("mpi: a process sent itself " + std::to_string(send.size()) +
                         " values for " + std::to_string(receive.size()));
  }
  std::copy(send.begin(), send.end(), receive.begin());
}

std::vector<double> Communicator::gather_to_root(std::span<const double> values) const {
  return {values.begin(), values.end()};
}
std::vector<double> Communicator::gather_to_all(std::span<const double> values) const {
  return {values.begin(), values.end()};
}
std::vector<double> Communicator::scatter_from_root(
    const std::vector<std::vector<double>>& per_rank, std::size_t count) const {
  if (per_rank.size() != 1 || per_rank[0].size() != count) {
    throw RuntimeFailure("mpi: a process scattered to itself values of the wrong count");
  }
  return per_rank[0];
}
bool every_process_fails_together(double /*timeout_s*/) { return true; }
Communicator Communicator::split(int /*colour*/) const { return *this; }
void Communicator::broadcast_from_root(std::span<double> /*values*/) const {}
bool Communicator::any(bool local) const { return local; }
double Communicator::max(double local) const { return local; }
void Communicator::barrier() const {}
void Communicator::abort(int exit_code) const { std::exit(exit_code); }

#endif

bool MpiSession::active() { return session_active; }

const void* Communicator::mpi_comm() const {
#ifdef RBCSIM_WITH_MPI
  if (handle_) return &handle_->comm;
#endif
  return nullptr;
}

Communicator::Communicator(std::shared_ptr<const Handle> handle, int rank, int size)
    : handle_(std::move(handle)), rank_(rank), size_(size) {}

}  // namespace rbcsim::parallel
