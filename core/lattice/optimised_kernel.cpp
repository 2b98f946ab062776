#include "lattice/optimised_kernel.hpp"

#include "lattice/lees_edwards.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

// The bulk loop is compiled for the baseline x86-64 and for AVX2 and AVX-512 machines; the loader
// picks the best clone the CPU supports, so the binary stays portable (about 2.5x faster on an
// AVX-512 Xeon than the SSE2 baseline).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define RBCSIM_VECTOR_CLONES \
  __attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#else
#define RBCSIM_VECTOR_CLONES
#endif

// The bulk loop's arrays never overlap (one array per direction); telling the compiler lets it
// vectorise without run-time alias checks. GCC and clang spell the promise differently.
#if defined(__clang__)
#define RBCSIM_NO_LOOP_CARRIED_ALIASING _Pragma("clang loop vectorize(assume_safety)")
#else
#define RBCSIM_NO_LOOP_CARRIED_ALIASING _Pragma("GCC ivdep")
#endif

namespace rbcsim::lattice {
namespace {

struct TrtConstants {
  TrtConstants() = default;
  explicit TrtConstants(const RelaxationRates& rates)
      : omega_even(rates.even),
        omega_odd(rates.odd),
        source_even(1.0 - 0.5 * rates.even),
        source_odd(1.0 - 0.5 * rates.odd) {}
  double omega_even = 0.0;
  double omega_odd = 0.0;
  double source_even = 0.0;  // Guo prefactor of the even part of the forcing term, 1 - omega+/2
  double source_odd = 0.0;
};

// The constants of every viscosity class (collision.hpp) and each node's class, for the kernels
// with per-node rates; `classes` is null when every node relaxes at the step's uniform rates.
struct ClassConstants {
  explicit ClassConstants(const StepParameters& parameters)
      : classes(parameters.viscosity_classes) {
    if (classes == nullptr) return;
    for (int c = 0; c < kViscosityClasses; ++c) {
      constants[c] = TrtConstants(parameters.class_rates[c]);
    }
  }
  const ViscosityClass* classes;
  std::array<TrtConstants, kViscosityClasses> constants;
};

struct Moments {
  double density;
  double ux;
  double uy;
  double uz;
};

// Loads and stores of one population in either storage (fluid_kernel.hpp, Precision): a double
// as it is, a float as f - w with w the weight of the population's direction (a slot and its
// opposite share it). The kernels compute in double either way.
template <class Real>
struct Storage;
template <>
struct Storage<double> {
  static double load(double value, double) { return value; }
  static double store(double f, double) { return f; }
  static double* data(FluidArrays& arrays) { return arrays.populations.data(); }
};
template <>
struct Storage<float> {
  static double load(float value, double weight) { return static_cast<double>(value) + weight; }
  static float store(double f, double weight) { return static_cast<float>(f - weight); }
  static float* data(FluidArrays& arrays) { return arrays.single_populations.data(); }
};

// TRT relaxation of one pair of opposite populations, `along` c and `against` it, with
// cu = c.u, cf = c.F, base = 1 - u.u/(2 c_s^2), three_uf = u.F / c_s^2. Same operator as
// collide_node_reference, written for the pair at once. Without kForced the force is zero and its
// source terms, a third of the arithmetic, are left out (they would add exact zeros).
template <bool kForced>
[[gnu::always_inline]] inline void relax_pair(double& along, double& against, double weight,
                                              double cu, double cf, double density, double base,
                                              double three_uf, const TrtConstants& k) {
  const double equilibrium_even = weight * density * (base + 4.5 * cu * cu);
  const double equilibrium_odd = weight * density * 3.0 * cu;
  const double relaxation_even = k.omega_even * (0.5 * (along + against) - equilibrium_even);
  const double relaxation_odd = k.omega_odd * (0.5 * (along - against) - equilibrium_odd);
  double change_even = -relaxation_even;
  double change_odd = -relaxation_odd;
  if constexpr (kForced) {
    const double source_even = weight * (9.0 * cu * cf - three_uf);
    const double source_odd = weight * 3.0 * cf;
    change_even = k.source_even * source_even - relaxation_even;
    change_odd = k.source_odd * source_odd - relaxation_odd;
  }
  along += change_even + change_odd;
  against += change_even - change_odd;
}

// Collides one node in place, the 19 directions written out (pairs as in d3q19.hpp). Without
// kForced, (fx, fy, fz) must be zero and are not read.
template <bool kForced>
[[gnu::always_inline]] inline Moments collide_written_out(double (&f)[kDirections], double fx,
                                                          double fy, double fz,
                                                          const TrtConstants& k) {
  const double density = f[0] + f[1] + f[2] + f[3] + f[4] + f[5] + f[6] + f[7] + f[8] + f[9] +
                         f[10] + f[11] + f[12] + f[13] + f[14] + f[15] + f[16] + f[17] + f[18];
  const double jx = f[1] - f[2] + f[7] - f[8] + f[9] - f[10] + f[11] - f[12] + f[13] - f[14];
  const double jy = f[3] - f[4] + f[7] - f[8] - f[9] + f[10] + f[15] - f[16] + f[17] - f[18];
  const double jz = f[5] - f[6] + f[11] - f[12] - f[13] + f[14] + f[15] - f[16] - f[17] + f[18];
  const double inverse_density = 1.0 / density;
  double ux = jx * inverse_density;
  double uy = jy * inverse_density;
  double uz = jz * inverse_density;
  double three_uf = 0.0;
  if constexpr (kForced) {
    ux = (jx + 0.5 * fx) * inverse_density;
    uy = (jy + 0.5 * fy) * inverse_density;
    uz = (jz + 0.5 * fz) * inverse_density;
    three_uf = 3.0 * (ux * fx + uy * fy + uz * fz);
  }
  const double base = 1.0 - 1.5 * (ux * ux + uy * uy + uz * uz);

  const double relaxation_rest = k.omega_even * (f[0] - kWeightRest * density * base);
  if constexpr (kForced) {
    f[0] += k.source_even * (-kWeightRest * three_uf) - relaxation_rest;
  } else {
    f[0] -= relaxation_rest;
  }
  relax_pair<kForced>(f[1], f[2], kWeightFace, ux, fx, density, base, three_uf, k);
  relax_pair<kForced>(f[3], f[4], kWeightFace, uy, fy, density, base, three_uf, k);
  relax_pair<kForced>(f[5], f[6], kWeightFace, uz, fz, density, base, three_uf, k);
  relax_pair<kForced>(f[7], f[8], kWeightEdge, ux + uy, fx + fy, density, base, three_uf, k);
  relax_pair<kForced>(f[9], f[10], kWeightEdge, ux - uy, fx - fy, density, base, three_uf, k);
  relax_pair<kForced>(f[11], f[12], kWeightEdge, ux + uz, fx + fz, density, base, three_uf, k);
  relax_pair<kForced>(f[13], f[14], kWeightEdge, ux - uz, fx - fz, density, base, three_uf, k);
  relax_pair<kForced>(f[15], f[16], kWeightEdge, uy + uz, fy + fz, density, base, three_uf, k);
  relax_pair<kForced>(f[17], f[18], kWeightEdge, uy - uz, fy - fz, density, base, three_uf, k);
  return {density, ux, uy, uz};
}

// What a stretch of nodes is forced by: nothing (no body force, and no force field in its row),
// the uniform body force, or the body force plus the force field. Most of a single cell's lattice
// feels no force at all, and its collision then skips the forcing terms.
enum class Forcing { none, uniform, field };

// Collides `length` consecutive nodes starting at grid index `first`. Node k reads f_i from
// p[i][k] and writes f*_i to p[opp(i)][k]: with p[i] at slot i of the node itself this is the AA
// local step, with p[i] at slot opp(i) of the node x - c_i the streaming step. Every slot is read
// and written by one node only, so iterations are independent: `ivdep` says so to the vectoriser
// (GCC 12 does not vectorise this loop under `omp simd`, which privatises the array f into a simd
// array it cannot load from).
template <Forcing kForcing, class Real>
RBCSIM_VECTOR_CLONES void collide_run(Real* const (&p)[kDirections], std::size_t first,
                                      std::ptrdiff_t length, FluidArrays& arrays,
                                      const std::array<double, 3>& body_force,
                                      const TrtConstants& k) {
  using S = Storage<Real>;
  constexpr double w0 = kWeightRest;
  constexpr double wf = kWeightFace;
  constexpr double we = kWeightEdge;
  Real* const p0 = p[0];
  Real* const p1 = p[1];
  Real* const p2 = p[2];
  Real* const p3 = p[3];
  Real* const p4 = p[4];
  Real* const p5 = p[5];
  Real* const p6 = p[6];
  Real* const p7 = p[7];
  Real* const p8 = p[8];
  Real* const p9 = p[9];
  Real* const p10 = p[10];
  Real* const p11 = p[11];
  Real* const p12 = p[12];
  Real* const p13 = p[13];
  Real* const p14 = p[14];
  Real* const p15 = p[15];
  Real* const p16 = p[16];
  Real* const p17 = p[17];
  Real* const p18 = p[18];
  double* const density = arrays.density.data() + first;
  double* const ux = arrays.velocity[0].data() + first;
  double* const uy = arrays.velocity[1].data() + first;
  double* const uz = arrays.velocity[2].data() + first;
  const double* const force_x = arrays.force_density[0].data() + first;
  const double* const force_y = arrays.force_density[1].data() + first;
  const double* const force_z = arrays.force_density[2].data() + first;
  const double body_x = body_force[0];
  const double body_y = body_force[1];
  const double body_z = body_force[2];

  RBCSIM_NO_LOOP_CARRIED_ALIASING
  for (std::ptrdiff_t n = 0; n < length; ++n) {
    double f[kDirections] = {S::load(p0[n], w0),  S::load(p1[n], wf),  S::load(p2[n], wf),
                             S::load(p3[n], wf),  S::load(p4[n], wf),  S::load(p5[n], wf),
                             S::load(p6[n], wf),  S::load(p7[n], we),  S::load(p8[n], we),
                             S::load(p9[n], we),  S::load(p10[n], we), S::load(p11[n], we),
                             S::load(p12[n], we), S::load(p13[n], we), S::load(p14[n], we),
                             S::load(p15[n], we), S::load(p16[n], we), S::load(p17[n], we),
                             S::load(p18[n], we)};
    double fx = 0.0;
    double fy = 0.0;
    double fz = 0.0;
    if constexpr (kForcing != Forcing::none) {
      fx = body_x;
      fy = body_y;
      fz = body_z;
    }
    if constexpr (kForcing == Forcing::field) {
      fx += force_x[n];
      fy += force_y[n];
      fz += force_z[n];
    }
    const Moments moments = collide_written_out<kForcing != Forcing::none>(f, fx, fy, fz, k);
    density[n] = moments.density;
    ux[n] = moments.ux;
    uy[n] = moments.uy;
    uz[n] = moments.uz;
    p0[n] = S::store(f[0], w0);
    p2[n] = S::store(f[1], wf);
    p1[n] = S::store(f[2], wf);
    p4[n] = S::store(f[3], wf);
    p3[n] = S::store(f[4], wf);
    p6[n] = S::store(f[5], wf);
    p5[n] = S::store(f[6], wf);
    p8[n] = S::store(f[7], we);
    p7[n] = S::store(f[8], we);
    p10[n] = S::store(f[9], we);
    p9[n] = S::store(f[10], we);
    p12[n] = S::store(f[11], we);
    p11[n] = S::store(f[12], we);
    p14[n] = S::store(f[13], we);
    p13[n] = S::store(f[14], we);
    p16[n] = S::store(f[15], we);
    p15[n] = S::store(f[16], we);
    p18[n] = S::store(f[17], we);
    p17[n] = S::store(f[18], we);
  }
}

// collide_run with per-node rates: each maximal stretch of nodes of one viscosity class goes
// through the vectorised loop at that class's constants. The plasma and a cell's interior are long
// stretches; only the few nodes of a cell's rim change class from node to node. (Looking the
// constants up per node inside the loop kept it from vectorising: the 40x40x20 bench's fluid
// phase took 2.4x as long.) With kPerNodeRates false, plainly collide_run at `k`.
template <Forcing kForcing, bool kPerNodeRates, class Real>
void collide_run_at_rates(Real* const (&p)[kDirections], std::size_t first, std::ptrdiff_t length,
                          FluidArrays& arrays, const std::array<double, 3>& body_force,
                          const TrtConstants& k, const ClassConstants& node_rates) {
  if constexpr (!kPerNodeRates) {
    collide_run<kForcing>(p, first, length, arrays, body_force, k);
  } else {
    const ViscosityClass* const classes = node_rates.classes + first;
    std::ptrdiff_t begin = 0;
    while (begin < length) {
      std::ptrdiff_t end = begin + 1;
      while (end < length && classes[end] == classes[begin]) ++end;
      Real* stretch[kDirections];
      for (int i = 0; i < kDirections; ++i) stretch[i] = p[i] + begin;
      collide_run<kForcing>(stretch, first + begin, end - begin, arrays, body_force,
                            node_rates.constants[classes[begin]]);
      begin = end;
    }
  }
}

using LinkKind = OptimisedKernel::LinkKind;
using LinkedNode = OptimisedKernel::LinkedNode;
using WalledNode = OptimisedKernel::WalledNode;
using InterpolatedLink = OptimisedKernel::InterpolatedLink;
using Run = OptimisedKernel::Run;

// What the per-link path reads and writes besides the populations.
struct LinkBuffers {
  const double* ghost_in;
  double* ghost_out;
  const InterpolatedLink* interpolated_links;
  const double* wall_local_parts;
};

// Collides the gathered populations f of one node with its forcing and rates, and stores its
// density and velocity.
template <Forcing kForcing, bool kPerNodeRates>
Moments collide_one_node(double (&f)[kDirections], std::size_t node, FluidArrays& arrays,
                         const std::array<double, 3>& body_force, const TrtConstants& k,
                         const ClassConstants& node_rates) {
  std::array<double, 3> force = {0.0, 0.0, 0.0};
  if constexpr (kForcing != Forcing::none) force = body_force;
  if constexpr (kForcing == Forcing::field) {
    for (int axis = 0; axis < 3; ++axis) {
      force[axis] += arrays.force_density[axis][node];
    }
  }
  const TrtConstants& rates = kPerNodeRates ? node_rates.constants[node_rates.classes[node]] : k;
  const Moments moments =
      collide_written_out<kForcing != Forcing::none>(f, force[0], force[1], force[2], rates);
  arrays.density[node] = moments.density;
  arrays.velocity[0][node] = moments.ux;
  arrays.velocity[1][node] = moments.uy;
  arrays.velocity[2][node] = moments.uz;
  return moments;
}

// The streaming step of one node with boundary links: gather through each link, collide, scatter
// through each link (the write of f*_i goes through link opp(i), whose source is x + c_i).
template <Forcing kForcing, bool kPerNodeRates, class Real>
void collide_linked_node(const LinkedNode& linked, std::size_t stride, FluidArrays& arrays,
                         const LinkBuffers& buffers, const std::array<double, 3>& body_force,
                         const TrtConstants& k, const ClassConstants& node_rates) {
  using S = Storage<Real>;
  Real* const populations = S::data(arrays);
  const std::size_t node = linked.node;
  const double old_density = arrays.density[node];
  const std::array<double, 3> old_velocity = {arrays.velocity[0][node], arrays.velocity[1][node],
                                              arrays.velocity[2][node]};
  double f[kDirections];
  for (int i = 0; i < kDirections; ++i) {
    switch (static_cast<LinkKind>(linked.kind[i])) {
      case LinkKind::fluid:
        f[i] = S::load(populations[kOpposite[i] * stride + linked.source[i]], kWeights[i]);
        break;
      case LinkKind::wall:
        f[i] = bounce_back(S::load(populations[i * stride + node], kWeights[i]), old_density,
                           linked.value[i]);
        break;
      case LinkKind::pressure_outlet:
        f[i] = anti_bounce_back(i, S::load(populations[i * stride + node], kWeights[i]),
                                linked.value[i], old_velocity);
        break;
      case LinkKind::lees_edwards:
        f[i] = buffers.ghost_in[linked.source[i]];
        break;
      case LinkKind::interpolated_wall: {
        // Slot i of x + c_i holds f*_h(x + c_i) in the swapped layout; only x streams from it.
        const InterpolatedLink& link = buffers.interpolated_links[linked.source[i]];
        f[i] = buffers.wall_local_parts[linked.source[i]];
        if (link.weights.behind != 0.0) {
          f[i] += link.weights.behind * S::load(populations[i * stride + link.behind], kWeights[i]);
        }
        break;
      }
    }
  }
  const Moments moments =
      collide_one_node<kForcing, kPerNodeRates>(f, node, arrays, body_force, k, node_rates);
  const std::array<double, 3> velocity = {moments.ux, moments.uy, moments.uz};
  for (int i = 0; i < kDirections; ++i) {
    const int o = kOpposite[i];
    switch (static_cast<LinkKind>(linked.kind[o])) {
      case LinkKind::fluid:
        populations[i * stride + linked.source[o]] = S::store(f[i], kWeights[i]);
        break;
      case LinkKind::wall:
        populations[o * stride + node] =
            S::store(bounce_back(f[i], moments.density, linked.value[o]), kWeights[i]);
        break;
      case LinkKind::pressure_outlet:
        populations[o * stride + node] =
            S::store(anti_bounce_back(o, f[i], linked.value[o], velocity), kWeights[i]);
        break;
      case LinkKind::lees_edwards:
        buffers.ghost_out[linked.source[o]] = f[i];
        break;
      case LinkKind::interpolated_wall: {
        // The part behind follows in add_wall_parts_behind.
        const InterpolatedLink& link = buffers.interpolated_links[linked.source[o]];
        populations[o * stride + node] = S::store(
            wall_link_local_part(link.weights, f[i], f[o], moments.density, link.wall_coefficient),
            kWeights[i]);
        break;
      }
    }
  }
}

// How the nodes of one row are forced: the force field on the span where it may be non-zero
// (StepParameters::forced_spans; the whole row without them), and elsewhere the body force, if
// there is one.
struct RowForcing {
  ForcedSpan field;
  Forcing elsewhere;

  RowForcing(const StepParameters& parameters, std::int64_t row, int nx) {
    const auto& body = parameters.body_force;
    elsewhere =
        body[0] == 0.0 && body[1] == 0.0 && body[2] == 0.0 ? Forcing::none : Forcing::uniform;
    if (!parameters.force_field_active) return;
    field = parameters.forced_spans != nullptr ? parameters.forced_spans[row]
                                               : ForcedSpan{0, static_cast<std::uint32_t>(nx)};
  }
  Forcing at(int x) const {
    const auto u = static_cast<std::uint32_t>(x);
    return u >= field.begin && u < field.end ? Forcing::field : elsewhere;
  }
  // The nodes [x_begin, x_end) of the row in at most three pieces forced alike, in order: the
  // offset from x_begin, the length and the forcing of each.
  struct Piece {
    std::ptrdiff_t offset;
    std::ptrdiff_t length;
    Forcing forcing;
  };
  struct Pieces {
    std::array<Piece, 3> piece;
    int count = 0;
  };
  Pieces split(int x_begin, int x_end) const {
    const int lo = std::clamp(static_cast<int>(field.begin), x_begin, x_end);
    const int hi = std::clamp(static_cast<int>(field.end), lo, x_end);
    Pieces pieces;
    if (lo > x_begin) pieces.piece[pieces.count++] = {0, lo - x_begin, elsewhere};
    if (hi > lo) pieces.piece[pieces.count++] = {lo - x_begin, hi - lo, Forcing::field};
    if (x_end > hi) pieces.piece[pieces.count++] = {hi - x_begin, x_end - hi, elsewhere};
    return pieces;
  }
};

// The pointers p shifted by `offset` nodes.
template <class Real>
struct ShiftedPointers {
  Real* p[kDirections];
  ShiftedPointers(Real* const (&from)[kDirections], std::ptrdiff_t offset) {
    for (int i = 0; i < kDirections; ++i) p[i] = from[i] + offset;
  }
};

// The streaming step of a WalledNode: collide_linked_node without its cases (a resting half-way
// wall adds density x 0 to the bounced population).
template <Forcing kForcing, bool kPerNodeRates, class Real>
void collide_walled_node(const WalledNode& walled, std::size_t stride, FluidArrays& arrays,
                         const std::array<double, 3>& body_force, const TrtConstants& k,
                         const ClassConstants& node_rates) {
  using S = Storage<Real>;
  Real* const populations = S::data(arrays);
  const std::size_t node = walled.node;
  double f[kDirections];
  for (int i = 0; i < kDirections; ++i) {
    f[i] = S::load(populations[walled.read_slot[i] * stride + walled.read_node[i]], kWeights[i]);
  }
  collide_one_node<kForcing, kPerNodeRates>(f, node, arrays, body_force, k, node_rates);
  for (int i = 0; i < kDirections; ++i) {
    populations[walled.write_slot[i] * stride + walled.write_node[i]] = S::store(f[i], kWeights[i]);
  }
}

// The three ways of colliding (a run, a linked node, a walled node) as operations whose forcing is
// a template argument, and the one switch that picks it at run time.
template <bool kPerNodeRates>
struct CollideRun {
  template <Forcing kForcing, class... Args>
  static void at(Args&&... args) {
    collide_run_at_rates<kForcing, kPerNodeRates>(std::forward<Args>(args)...);
  }
};
template <bool kPerNodeRates, class Real>
struct CollideLinkedNode {
  template <Forcing kForcing, class... Args>
  static void at(Args&&... args) {
    collide_linked_node<kForcing, kPerNodeRates, Real>(std::forward<Args>(args)...);
  }
};
template <bool kPerNodeRates, class Real>
struct CollideWalledNode {
  template <Forcing kForcing, class... Args>
  static void at(Args&&... args) {
    collide_walled_node<kForcing, kPerNodeRates, Real>(std::forward<Args>(args)...);
  }
};

template <class Operation, class... Args>
void collide_forced(Forcing forcing, Args&&... args) {
  switch (forcing) {
    case Forcing::none:
      Operation::template at<Forcing::none>(std::forward<Args>(args)...);
      break;
    case Forcing::uniform:
      Operation::template at<Forcing::uniform>(std::forward<Args>(args)...);
      break;
    case Forcing::field:
      Operation::template at<Forcing::field>(std::forward<Args>(args)...);
      break;
  }
}

// The nodes [x_begin, x_end) of one row, whose populations the pointers p address from x_begin on
// (node index first), collided piece by piece as RowForcing splits them.
template <bool kPerNodeRates, class Real>
void collide_run_pieces(const RowForcing& forcing, Real* const (&p)[kDirections], std::size_t first,
                        int x_begin, int x_end, FluidArrays& arrays,
                        const std::array<double, 3>& body_force, const TrtConstants& k,
                        const ClassConstants& node_rates) {
  const auto pieces = forcing.split(x_begin, x_end);
  for (int n = 0; n < pieces.count; ++n) {
    const auto& piece = pieces.piece[n];
    const ShiftedPointers<Real> q(p, piece.offset);
    collide_forced<CollideRun<kPerNodeRates>>(piece.forcing, q.p, first + piece.offset,
                                              piece.length, arrays, body_force, k, node_rates);
  }
}

// `linked` as a WalledNode, if every link of it is plain fluid or a resting half-way wall and
// its node indices fit 32 bits.
std::optional<WalledNode> as_walled(const LinkedNode& linked, std::size_t node_count) {
  if (node_count > std::numeric_limits<std::uint32_t>::max()) return std::nullopt;
  WalledNode walled;
  walled.node = static_cast<std::uint32_t>(linked.node);
  for (int i = 0; i < kDirections; ++i) {
    const auto kind = static_cast<LinkKind>(linked.kind[i]);
    const bool resting_wall = kind == LinkKind::wall && linked.value[i] == 0.0;
    if (kind != LinkKind::fluid && !resting_wall) return std::nullopt;
    const int o = kOpposite[i];
    // Gather of f_i: from x - c_i, or bounced back at x (slot i holds f*_opp(i)(x)).
    walled.read_node[i] = static_cast<std::uint32_t>(resting_wall ? linked.node : linked.source[i]);
    walled.read_slot[i] = static_cast<std::uint8_t>(resting_wall ? i : o);
  }
  for (int i = 0; i < kDirections; ++i) {
    // Scatter of f*_i through link opp(i): to x + c_i, or bounced back into slot opp(i) of x (a
    // resting wall: the loop above returned for any other).
    const int o = kOpposite[i];
    const bool wall = static_cast<LinkKind>(linked.kind[o]) == LinkKind::wall;
    walled.write_node[i] = static_cast<std::uint32_t>(wall ? linked.node : linked.source[o]);
    walled.write_slot[i] = static_cast<std::uint8_t>(wall ? o : i);
  }
  return walled;
}

// Fills the wall link i of `linked` (x - c_i is a wall node): half-way links keep the plain path.
void link_wall(const LatticeSetup& setup, int i, std::size_t wall_node, LinkedNode& linked,
               std::vector<InterpolatedLink>& interpolated_links) {
  const double coefficient =
      wall_momentum_coefficient(i, setup.boundaries.wall_velocity(wall_node));
  const WallLinkWeights weights = wall_link_weights(setup, linked.node, i);
  if (weights == kHalfwayWeights) {
    linked.kind[i] = static_cast<std::uint8_t>(LinkKind::wall);
    linked.value[i] = coefficient;
    return;
  }
  linked.kind[i] = static_cast<std::uint8_t>(LinkKind::interpolated_wall);
  linked.source[i] = interpolated_links.size();
  interpolated_links.push_back({linked.node, i, weights, coefficient,
                                setup.grid.periodic_neighbour(linked.node, kVelocities[i])});
}

// Fills `linked` for a fluid node, appending its interpolated wall links; returns false when
// every link is plain periodic fluid.
bool link_node(const LatticeSetup& setup, std::size_t node, std::size_t plane_size,
               LinkedNode& linked, std::vector<InterpolatedLink>& interpolated_links) {
  const LatticeGrid& grid = setup.grid;
  const auto [x, y, z] = grid.coordinates(node);
  const std::size_t plane_position = x + static_cast<std::size_t>(grid.nx()) * z;
  bool needs_links = false;
  linked.node = node;
  for (int i = 0; i < kDirections; ++i) {
    const auto& c = kVelocities[i];
    const int source_y = y - c[1];
    linked.value[i] = 0.0;
    if (setup.lees_edwards_velocity && (source_y < 0 || source_y >= grid.ny())) {
      linked.kind[i] = static_cast<std::uint8_t>(LinkKind::lees_edwards);
      linked.source[i] = i * plane_size + plane_position;
      needs_links = true;
      continue;
    }
    const std::size_t source = grid.periodic_neighbour(node, {-c[0], -c[1], -c[2]});
    linked.source[i] = source;
    switch (setup.boundaries.kind(source)) {
      case NodeKind::fluid:
        linked.kind[i] = static_cast<std::uint8_t>(LinkKind::fluid);
        break;
      case NodeKind::wall:
        link_wall(setup, i, source, linked, interpolated_links);
        needs_links = true;
        break;
      case NodeKind::pressure_outlet:
        linked.kind[i] = static_cast<std::uint8_t>(LinkKind::pressure_outlet);
        linked.value[i] = setup.boundaries.outlet_density(source);
        needs_links = true;
        break;
    }
  }
  return needs_links;
}

// Appends the maximal runs of members along a row; with `split_at_wrap` a run never straddles
// x = 1 or x = nx - 1, so that its neighbours along x are one pointer offset away.
void append_runs(const std::vector<char>& member, bool split_at_wrap, std::vector<Run>& runs) {
  const int nx = static_cast<int>(member.size());
  int begin = -1;
  for (int x = 0; x <= nx; ++x) {
    const bool inside = x < nx && member[x] != 0;
    const bool split = split_at_wrap && (x == 1 || x == nx - 1);
    if (begin >= 0 && (!inside || split)) {
      runs.push_back({begin, x});
      begin = -1;
    }
    if (inside && begin < 0) {
      begin = x;
    }
  }
}

// Computes every population entering through a sliding plane at `arrival_time` and hands it to
// store(i, target node, x, z, value); post_collision(i, node) returns f*_i of a source node.
template <class PostCollision, class Store>
void for_each_lees_edwards_population(const LatticeSetup& setup, const FluidArrays& arrays,
                                      std::size_t arrival_time, PostCollision&& post_collision,
                                      Store&& store) {
  const LatticeGrid& grid = setup.grid;
  const double velocity_difference = *setup.lees_edwards_velocity;
  const auto planes = lees_edwards_planes(
      grid.ny(), lees_edwards_offset(velocity_difference, arrival_time, grid.nx()),
      velocity_difference);
#pragma omp parallel for schedule(static) if (grid.worth_threads())
  for (int z = 0; z < grid.nz(); ++z) {
    for (const auto& plane : planes) {
      for (int i = 1; i < kDirections; ++i) {
        if (kVelocities[i][1] != plane.entering_cy) {
          continue;
        }
        for (int x = 0; x < grid.nx(); ++x) {
          const double value = lees_edwards_population(
              grid, plane, i, x, z, arrays,
              [&](std::size_t source) { return post_collision(i, source); });
          store(i, grid.index(x, plane.target_y, z), x, z, value);
        }
      }
    }
  }
}

}  // namespace

OptimisedKernel::OptimisedKernel(const LatticeSetup& setup)
    : setup_(setup),
      plane_size_(static_cast<std::size_t>(setup.grid.nx()) * setup.grid.nz()),
      fluid_run_begin_{0},
      bulk_run_begin_{0},
      linked_begin_{0},
      walled_begin_{0} {
  const LatticeGrid& grid = setup.grid;
  std::vector<char> fluid(grid.nx());
  std::vector<char> bulk(grid.nx());
  LinkedNode linked;
  for (int z = 0; z < grid.nz(); ++z) {
    for (int y = 0; y < grid.ny(); ++y) {
      for (int x = 0; x < grid.nx(); ++x) {
        const std::size_t node = grid.index(x, y, z);
        fluid[x] = setup.boundaries.is_fluid(node);
        const bool has_links =
            fluid[x] && link_node(setup, node, plane_size_, linked, interpolated_links_);
        bulk[x] = fluid[x] && !has_links;
        // A bulk node on the periodic seam in x would be a run of one node (its neighbours along
        // x are not one pointer offset away), whose 19 pointers cost more than its collision: it
        // streams through fixed slots as a walled node instead.
        const bool on_seam = (x == 0 || x == grid.nx() - 1) && grid.nx() > 2;
        if (has_links || (bulk[x] && on_seam)) {
          if (const auto walled = as_walled(linked, grid.node_count())) {
            walled_nodes_.push_back(*walled);
            bulk[x] = false;
          } else if (has_links) {
            linked_nodes_.push_back(linked);
          }
        }
      }
      append_runs(fluid, false, fluid_runs_);
      append_runs(bulk, true, bulk_runs_);
      fluid_run_begin_.push_back(fluid_runs_.size());
      bulk_run_begin_.push_back(bulk_runs_.size());
      linked_begin_.push_back(linked_nodes_.size());
      walled_begin_.push_back(walled_nodes_.size());
    }
  }
  if (setup.lees_edwards_velocity) {
    ghost_in_.assign(kDirections * plane_size_, 0.0);
    ghost_out_.assign(kDirections * plane_size_, 0.0);
  }
  wall_local_parts_.assign(interpolated_links_.size(), 0.0);
}

void OptimisedKernel::step(FluidArrays& arrays, const StepParameters& parameters) {
  const bool per_node = parameters.viscosity_classes != nullptr;
  if (arrays.single()) {
    per_node ? step_with<true, float>(arrays, parameters)
             : step_with<false, float>(arrays, parameters);
  } else {
    per_node ? step_with<true, double>(arrays, parameters)
             : step_with<false, double>(arrays, parameters);
  }
}

template <bool kPerNodeRates, class Real>
void OptimisedKernel::step_with(FluidArrays& arrays, const StepParameters& parameters) {
  if (arrays.layout == PopulationLayout::natural) {
    local_step<kPerNodeRates, Real>(arrays, parameters);
  } else {
    streaming_step<kPerNodeRates, Real>(arrays, parameters);
  }
}

template <bool kPerNodeRates, class Real>
void OptimisedKernel::local_step(FluidArrays& arrays, const StepParameters& parameters) const {
  const LatticeGrid& grid = setup_.grid;
  const std::size_t stride = arrays.population_stride;
  const TrtConstants constants(parameters.rates);
  const ClassConstants node_rates(parameters);
  Real* const populations = Storage<Real>::data(arrays);
  const auto rows = static_cast<std::int64_t>(grid.row_count());
#pragma omp parallel for schedule(static) if (grid.worth_threads())
  for (std::int64_t row = 0; row < rows; ++row) {
    const std::size_t row_start = static_cast<std::size_t>(row) * grid.nx();
    const RowForcing forcing(parameters, row, grid.nx());
    for (std::size_t r = fluid_run_begin_[row]; r < fluid_run_begin_[row + 1]; ++r) {
      const Run run = fluid_runs_[r];
      const std::size_t first = row_start + run.x_begin;
      Real* p[kDirections];
      for (int i = 0; i < kDirections; ++i) {
        p[i] = populations + i * stride + first;
      }
      collide_run_pieces<kPerNodeRates>(forcing, p, first, run.x_begin, run.x_end, arrays,
                                        parameters.body_force, constants, node_rates);
    }
  }
  arrays.layout = PopulationLayout::swapped;
}

template <bool kPerNodeRates, class Real>
void OptimisedKernel::streaming_step(FluidArrays& arrays, const StepParameters& parameters) {
  const LatticeGrid& grid = setup_.grid;
  const std::size_t stride = arrays.population_stride;
  const TrtConstants constants(parameters.rates);
  const ClassConstants node_rates(parameters);
  Real* const populations = Storage<Real>::data(arrays);
  if (setup_.lees_edwards_velocity) {
    fill_lees_edwards_ghosts(arrays, parameters.time);
  }
  store_wall_local_parts(arrays);
  const LinkBuffers buffers{ghost_in_.data(), ghost_out_.data(), interpolated_links_.data(),
                            wall_local_parts_.data()};
  const auto rows = static_cast<std::int64_t>(grid.row_count());
#pragma omp parallel for schedule(static) if (grid.worth_threads())
  for (std::int64_t row = 0; row < rows; ++row) {
    const int y = static_cast<int>(row % grid.ny());
    const int z = static_cast<int>(row / grid.ny());
    const std::size_t row_start = static_cast<std::size_t>(row) * grid.nx();
    const RowForcing forcing(parameters, row, grid.nx());
    for (std::size_t r = bulk_run_begin_[row]; r < bulk_run_begin_[row + 1]; ++r) {
      const Run run = bulk_runs_[r];
      Real* p[kDirections];
      for (int i = 0; i < kDirections; ++i) {
        const auto& c = kVelocities[i];
        p[i] = populations + kOpposite[i] * stride +
               grid.index(LatticeGrid::wrap_by_one(run.x_begin - c[0], grid.nx()),
                          LatticeGrid::wrap_by_one(y - c[1], grid.ny()),
                          LatticeGrid::wrap_by_one(z - c[2], grid.nz()));
      }
      collide_run_pieces<kPerNodeRates>(forcing, p, row_start + run.x_begin, run.x_begin, run.x_end,
                                        arrays, parameters.body_force, constants, node_rates);
    }
    for (std::size_t l = linked_begin_[row]; l < linked_begin_[row + 1]; ++l) {
      const LinkedNode& linked = linked_nodes_[l];
      collide_forced<CollideLinkedNode<kPerNodeRates, Real>>(
          forcing.at(static_cast<int>(linked.node - row_start)), linked, stride, arrays, buffers,
          parameters.body_force, constants, node_rates);
    }
    for (std::size_t w = walled_begin_[row]; w < walled_begin_[row + 1]; ++w) {
      const WalledNode& walled = walled_nodes_[w];
      collide_forced<CollideWalledNode<kPerNodeRates, Real>>(
          forcing.at(static_cast<int>(walled.node - row_start)), walled, stride, arrays,
          parameters.body_force, constants, node_rates);
    }
  }
  if (setup_.lees_edwards_velocity) {
    empty_lees_edwards_ghosts(arrays, parameters.time + 1);
  }
  add_wall_parts_behind(arrays);
  arrays.layout = PopulationLayout::natural;
}

// Before a streaming step, in the swapped layout: slot i of x holds f*_h(x), slot h holds f*_i(x),
// and the density is that of the local step's collision.
void OptimisedKernel::store_wall_local_parts(const FluidArrays& arrays) {
  if (interpolated_links_.empty()) {
    return;  // no fork-join for nothing
  }
  const std::size_t stride = arrays.population_stride;
  const auto count = static_cast<std::int64_t>(interpolated_links_.size());
#pragma omp parallel for schedule(static) if (setup_.grid.worth_threads())
  for (std::int64_t l = 0; l < count; ++l) {
    const InterpolatedLink& link = interpolated_links_[l];
    const int i = link.direction;
    const int o = kOpposite[i];
    wall_local_parts_[l] = wall_link_local_part(
        link.weights, arrays.population(i, i * stride + link.node),
        arrays.population(o, o * stride + link.node), arrays.density[link.node],
        link.wall_coefficient);
  }
}

// After a streaming step, in the natural layout: slot h of x holds f*_h(x + c_i), streamed there
// by x + c_i (a plain fluid link whenever weights.behind is not zero).
void OptimisedKernel::add_wall_parts_behind(FluidArrays& arrays) const {
  if (interpolated_links_.empty()) {
    return;  // no fork-join for nothing
  }
  const std::size_t stride = arrays.population_stride;
  const auto count = static_cast<std::int64_t>(interpolated_links_.size());
#pragma omp parallel for schedule(static) if (setup_.grid.worth_threads())
  for (std::int64_t l = 0; l < count; ++l) {
    const InterpolatedLink& link = interpolated_links_[l];
    const int i = link.direction;
    const int o = kOpposite[i];
    if (link.weights.behind != 0.0) {
      const std::size_t slot = i * stride + link.node;
      arrays.set_population(i, slot,
                            arrays.population(i, slot) +
                                link.weights.behind * arrays.population(o, o * stride + link.node));
    }
  }
}

void OptimisedKernel::fill_lees_edwards_ghosts(const FluidArrays& arrays,
                                               std::size_t arrival_time) {
  const std::size_t stride = arrays.population_stride;
  const auto nx = static_cast<std::size_t>(setup_.grid.nx());
  for_each_lees_edwards_population(
      setup_, arrays, arrival_time,
      // After the local step, f*_i of a node sits in its slot opp(i).
      [&](int i, std::size_t source) {
        return arrays.population(kOpposite[i], kOpposite[i] * stride + source);
      },
      [&](int i, std::size_t, int x, int z, double value) {
        ghost_in_[i * plane_size_ + x + nx * z] = value;
      });
}

void OptimisedKernel::empty_lees_edwards_ghosts(FluidArrays& arrays,
                                                std::size_t arrival_time) const {
  const std::size_t stride = arrays.population_stride;
  const auto nx = static_cast<std::size_t>(setup_.grid.nx());
  const std::size_t layer = nx * setup_.grid.ny();
  for_each_lees_edwards_population(
      setup_, arrays, arrival_time,
      [&](int i, std::size_t source) {
        return ghost_out_[kOpposite[i] * plane_size_ + source % nx + nx * (source / layer)];
      },
      [&](int i, std::size_t target, int, int, double value) {
        arrays.set_population(i, i * stride + target, value);
      });
}

}  // namespace rbcsim::lattice
