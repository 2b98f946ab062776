// Cell shapes as minima of the bilayer-couple energy (bilayer_couple.hpp). The icosphere of the
// requested level is mapped onto the skeleton's stress-free reference, a near-spherical oblate
// spheroid of the membrane's area (as Lim, Wortis & Mukhopadhyay 2002 take it), and each trial
// follows a path from there (energy_paths below): a seeded random displacement, deflation in
// stages to the target reduced volume at the shape's relaxed area difference Delta a0, and a
// final FIRE minimisation, area and volume held throughout. The paths reach different local
// minima (a fluid-like membrane folds into a biconcave disc where a stiff one stays a convex
// oblate; a stiff one keeps a cup's lip clear of its wall where a fluid-like one folds it through),
// so every trial of every path is run and the lowest energy wins among the minima that do not pass
// through themselves (mesh/self_intersection.hpp). The winner is the stress-free reference of the
// six-force membrane of every later run (paper Sec. 2: the shapes of a shape-change minimisation).
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/registry.hpp"
#include "membrane/surface_energies.hpp"
#include "mesh/surface_map.hpp"
#include "mesh/triangle_mesh.hpp"
#include "shapes/bilayer_couple.hpp"

namespace rbcsim::shapes {

// A path from the reference to the shape: the skeleton's moduli during the deflation, relative to
// their values (then stiffened to them in geometric steps).
struct EnergyPath {
  std::string_view name;
  std::string_view description;
  bool soft_deflation;  // deflate at soft_skeleton_fraction of the moduli, then stiffen
  // Deflate at EnergyShapeSettings::continuation_start_area_difference (the discocyte's), then
  // walk Delta a0 to the shape's in steps of at most continuation_step: the shape changes through
  // the sequence's own minima instead of the full drive acting on the near-spherical reference.
  bool area_difference_continuation;
};
const Registry<EnergyPath>& energy_paths();

// The relaxed area differences and reduced volumes the model reaches: measured at 2562
// vertices (docs/validation.md): beyond Delta a0 = 14 the minimisation does not converge, below
// -6 the cup closes on itself; v was scanned only down to 0.5. Outside, InputError.
inline constexpr double kReachableAreaDifference[2] = {-6.0, 14.0};
inline constexpr double kLowestReachableReducedVolume = 0.5;

struct EnergyShapeSettings {
  double area_um2 = 134.09;       // the membrane area (Evans-Fung's discocyte: area is conserved)
  double reduced_volume = 0.642;  // v = 6 sqrt(pi) V / A^1.5 (Lim et al. 2002)
  double relaxed_area_difference = 1.0;  // Delta a0 = DeltaA0 / (8 pi D R_A) of the shape
  // The config key diagnostics name for relaxed_area_difference (the shape's own).
  std::string relaxed_area_difference_key = "mesh.energy.relaxed_area_difference";
  double bending_modulus_J = 2e-19;                        // kappa (Lim et al. 2002)
  double nonlocal_bending_ratio = 2.0 / std::numbers::pi;  // alpha = kappa_bar / kappa
  membrane::SkeletonParameters skeleton;                   // mu, K_alpha, a3, a4, b1, b2
  // The skeleton's stress-free shape: an oblate spheroid of this reduced volume and the
  // membrane's area.
  double skeleton_reference_reduced_volume = 0.96;

  std::vector<std::string> paths = {"soft", "stiff"};  // names of energy_paths()
  double soft_skeleton_fraction = 0.01;  // the soft path's deflation moduli, of the full
  int volume_stages = 10;                // equal steps from the reference's volume to the target
  int stiffening_stages = 4;             // geometric steps from soft to full moduli
  // The continuation path's start and largest step in Delta a0 (EnergyPath).
  double continuation_start_area_difference = 1.0;
  double continuation_step = 1.0;
  std::size_t stage_iterations = 3000;   // FIRE iterations per stage, at most
  // A stage ends when no vertex's force exceeds this: the path needs no precise intermediate
  // minima, only the final state does (force_tolerance_pN).
  double stage_force_tolerance_pN = 1e-5;

  int trials = 1;                       // seeded starts per path; the lowest energy wins
  std::uint64_t seed = 1;               // of the first trial; trial k uses seed + k
  double perturbation_um = 0.02;        // amplitude of the seeded displacement at every stage
  double force_tolerance_pN = 1e-7;     // converged: every vertex's projected force below this
  std::size_t max_iterations = 300000;  // of the final minimisation

  // The minimum's vertices slid over its own surface to even out its triangles
  // (redistribute_on_surface): the minimisation moves vertices tangentially to lower the
  // skeleton's shear energy about its reference, leaving angles of 36-92 deg on a discocyte,
  // and that in-plane strain is lost once the shape is the stress-free mesh of a flow run,
  // where such triangles fail first. Kept only when it makes the smallest angle larger (on a
  // shape whose features the triangles do not resolve, an echinocyte's single-vertex spikes or a
  // 162-vertex cup's lip, the smoothing cuts them off and makes the triangles worse). 0 sweeps
  // ships the minimum itself.
  mesh::RelaxationSettings redistribution{.iterations = 200, .step_fraction = 0.8};
};

struct EnergyShapeTrial {
  std::string path;
  std::uint64_t seed = 0;
  BilayerCoupleEnergies energies;
  std::size_t iterations = 0;  // all stages
  bool converged = false;
  double max_force_pN = 0.0;
  std::size_t self_intersections = 0;  // intersecting triangle pairs of its minimum
  std::optional<std::string> failure;  // why the trial has no minimum (a RuntimeFailure's text)
  double seconds = 0.0;
  // A minimum that can win: converged, and not passing through itself.
  bool valid() const { return !failure && converged && self_intersections == 0; }
};

// What redistributing the minimum's vertices over its surface changed.
struct Redistribution {
  int sweeps = 0;
  // Whether the shape is the redistributed minimum (its smallest angle grew) or the minimum as
  // found, and why.
  bool kept = false;
  std::string outcome;
  // Restoring the area and volume moves the vertices off the minimum's (piecewise-flat) surface,
  // along its normals, by at most this.
  double largest_restoring_move_um = 0.0;
  double min_angle_before_deg = 0.0;
  double max_angle_before_deg = 0.0;
  double min_angle_deg = 0.0;
  double max_angle_deg = 0.0;
};

struct EnergyShape {
  // The winning trial's minimum with its vertices redistributed over its surface, centred,
  // principal axes on x, y, z, and its coordinates rounded to single precision as its STL file
  // stores them, so that a shape read back from its file is the shape generated (the stress-free
  // reference of every run is the same either way).
  mesh::TriangleMesh mesh;
  // The minimum itself, in the same frame (its energies are the shape's).
  mesh::TriangleMesh minimum;
  Redistribution redistribution;
  mesh::TriangleMesh skeleton_reference;
  BilayerCoupleEnergies energies;
  double reduced_area_difference = 0.0;  // Delta a of the minimum (realised, not relaxed)
  std::vector<EnergyShapeTrial> trials;
  std::size_t best_trial = 0;
};

// One state of a path: what the model holds while FIRE minimises.
struct EnergyStage {
  double volume_um3;
  double skeleton_fraction;        // of the skeleton's moduli
  double relaxed_area_difference;  // Delta a0
  std::size_t iterations;          // at most
  double force_tolerance_pN;
};

// The stages `path` takes from the reference of volume `start_volume_um3` to the shape: the
// deflation, the soft path's stiffening, the continuation's walk in Delta a0, the final
// minimisation.
std::vector<EnergyStage> energy_stages(const EnergyPath& path, const EnergyShapeSettings& settings,
                                       double start_volume_um3);

// Progress: trial index, stage (volume_stages + 1 is the final minimisation), FIRE's state.
using EnergyShapeProgress =
    std::function<void(int trial, int stage, const minimise::FireResult& so_far)>;

// Throws InputError naming the mesh.energy key for settings the model cannot take (a reduced
// volume outside (0, reference's), a non-positive modulus, an unknown path), RuntimeFailure when
// no trial gives a valid minimum (naming each trial's residual or failure).
EnergyShape minimise_shape(int subdivisions, const EnergyShapeSettings& settings,
                           const EnergyShapeProgress& progress = {});

// The model the settings describe, holding `area_um2` and `volume_um3` (kappa converted to pN um).
BilayerCoupleParameters bilayer_couple_parameters(const EnergyShapeSettings& settings,
                                                  double area_um2, double volume_um3);

// The settings as JSON, member names as in the config's mesh.energy.* keys (without the shape's
// own relaxed_area_difference.<shape> suffix): what a shipped shape was generated with.
nlohmann::ordered_json to_json(const EnergyShapeSettings& settings);

// `shape`'s vertices slid over its own surface (mesh::piecewise_linear_map on the unit icosphere of
// `subdivisions`, whose connectivity it must have) by `relaxation`, then moved by one uniform
// offset along the vertex normals to the shape's reduced volume and scaled to its area: returned
// when its smallest angle is larger than the shape's, else `shape` itself (also when an offset of
// a quarter of an edge does not restore the reduced volume: the smoothing cut off a feature the
// triangles cannot follow). `record` says which and why.
mesh::TriangleMesh redistribute_on_surface(const mesh::TriangleMesh& shape, int subdivisions,
                                           const mesh::RelaxationSettings& relaxation,
                                           Redistribution& record);

// The skeleton's reference at a level: unit_icosphere(subdivisions) scaled along z to an oblate
// spheroid of `reduced_volume` (of the mesh itself, by bisection on the axis ratio), then to
// `area_um2`.
mesh::TriangleMesh oblate_spheroid(int subdivisions, double reduced_volume, double area_um2);

}  // namespace rbcsim::shapes
