// The element passes of the optimised kernel (step 1 in optimised_kernel.cpp): one vectorised
// loop over a block of edges and one over a block of triangles, each writing only its elements'
// entries of OptimisedScratch and its block's partial sums. Internal to the membrane module.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "membrane/force_law.hpp"
#include "membrane/optimised_scratch.hpp"
#include "mesh/topology.hpp"

namespace rbcsim::membrane::optimised {

// Elements per block of the partial sums: a constant, so the sums do not depend on the thread
// count; small enough that two threads share the blocks of a 642-vertex cell evenly.
constexpr std::size_t kBlockSize = 64;
inline std::size_t block_count(std::size_t elements) {
  return (elements + kBlockSize - 1) / kBlockSize;
}

// The built-in terms, in registry order (force_term_table.cpp).
enum Term : std::size_t {
  kLink,
  kBend,
  kArea,
  kVolume,
  kAreaDifference,
  kTotalCurvature,
  kTotalArea,
  kHelfrich,
  kLocalArea,
  kTermCount
};
constexpr std::array<std::string_view, kTermCount> kTermNames = {
    "link",       "bend",     "area",      "volume", "area_difference", "total_curvature",
    "total_area", "helfrich", "local_area"};

// A term's force law and scales. An element's force coefficient is force_scale slope(d) (what
// it multiplies is said where it is used); its energy is energy_scale (times a per-element
// factor for link and area) energy(d).
struct ScaledLaw {
  ForceLaw law;
  double force_scale;
  double energy_scale;
  double coefficient(double deviation) const { return force_scale * law.slope(deviation); }
};

struct FusedConstants {
  std::array<bool, kTermCount> enabled;
  bool angle_terms;  // bend, area_difference or total_curvature: hinge patterns are needed
  std::array<double, kTermCount> tau;
  ScaledLaw link;             // b of an edge: the link force on each end
  ScaledLaw bend;             // a of an edge
  ScaledLaw area;             // corner force: -coefficient (3 / P0) n x (opposite edge)
  ScaledLaw volume;           // c_v = -coefficient
  ScaledLaw area_difference;  // c_ad = coefficient
  ScaledLaw total_curvature;  // c_tc = coefficient
  // total_area: c_A = -K d times each corner's dA/dx (harmonic, no law); K in pN/um.
  double total_area_modulus_pN_per_um;
  // local_area: -K d_t times each corner's dA_t/dx (harmonic); K in pN/um.
  double local_area_modulus_pN_per_um;
  // helfrich: kappa, pN um (helfrich_term.cpp).
  double helfrich_modulus_pN_um;
  // total_area, local_area or helfrich: the corners' area gradients are needed.
  bool area_gradients;
};

// Per-element reference data, structure of arrays (inverses: multiplications in the passes).
struct HingeStencils {
  std::vector<std::array<std::int32_t, 4>> vertices;  // vertex0, vertex1, wing0, wing1
  std::vector<double> reference_lengths_um;
  std::vector<double> inverse_reference_lengths_per_um;
  std::vector<double> reference_angles_rad;
};
struct CornerStencils {
  // Corners a, b, c, padded with a copy of a: GCC 12 vectorises loads of a group of four indices,
  // not of three.
  std::vector<std::array<std::int32_t, 4>> corners;
  std::vector<double> reference_areas_um2;
  std::vector<double> inverse_reference_areas_per_um2;
  std::vector<double> area_forces_per_um;  // 3 / P0 (area_term.cpp)
};

// Step 1: one pass over block `block` of the edges (or triangles); positions_xyz is x, y, z per
// vertex.
using EdgeBlockPass = void (*)(const FusedConstants& constants, const HingeStencils& hinges,
                               std::size_t block, const double* positions_xyz,
                               OptimisedScratch& scratch);
void measure_triangle_block(const FusedConstants& constants, const CornerStencils& corners,
                            std::size_t block, const double* positions_xyz,
                            OptimisedScratch& scratch);

// Step 1b, after step 1 and only with helfrich: each vertex of block `block` gathers Juelicher's
// M_v and A_v from the lengths, angles and areas step 1 measured (surface_energies.hpp) and writes
// its Helfrich loads and energy, H0_v from `reference_mean_curvatures_per_um`.
void measure_vertex_block(const FusedConstants& constants, const mesh::MeshTopology& topology,
                          std::span<const double> reference_mean_curvatures_per_um,
                          std::size_t block, OptimisedScratch& scratch);

// The weight of each term in a force: 1 for link, bend and area (their coefficients are in the
// scratch already), the cell coefficients c_v, c_ad, c_tc, c_A for the cell terms, 1 for helfrich
// and local_area when enabled; 0 for a term left out.
using SlotWeights = std::array<double, kTermCount>;

// Step 3a: the force of every slot of block `block` of the edges (or triangles) for `weights`,
// into OptimisedScratch::slot_forces_pN. The stencils give the elements' vertices (helfrich).
void weigh_edge_block(const SlotWeights& weights, const HingeStencils& hinges, std::size_t block,
                      OptimisedScratch& scratch);
void weigh_triangle_block(const SlotWeights& weights, const CornerStencils& corners,
                          std::size_t block, OptimisedScratch& scratch);

// One distribution of the angle terms as the optimised kernel needs it, by the names of
// hinge.cpp's table: its edge pass and the scales of a (bend) and c (cell terms) from k kBT / L0.
struct FusedDistribution {
  std::string_view name;
  EdgeBlockPass measure_edge_block;
  double (*bend_scale)(double force_scale_pN, double length_scale_um);
  double (*cell_scale)(double force_scale_pN);
};
std::span<const FusedDistribution> fused_distribution_table();
// The gradient form's bending stiffness K_b, the energy scale of both distributions.
double gradient_bend_scale(double force_scale_pN, double length_scale_um);

}  // namespace rbcsim::membrane::optimised
