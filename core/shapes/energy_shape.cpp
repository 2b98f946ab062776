#include "shapes/energy_shape.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <random>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "mesh/geometry.hpp"
#include "mesh/icosphere.hpp"
#include "mesh/inspection.hpp"
#include "mesh/self_intersection.hpp"
#include "mesh/topology.hpp"
#include "mesh/transform.hpp"

namespace rbcsim::shapes {
namespace {

constexpr double kPicoNewtonMicrometrePerJoule = 1e18;
constexpr int kBisectionSteps = 80;

double mesh_reduced_volume(const mesh::TriangleMesh& mesh) {
  return mesh::reduced_volume(mesh::surface_area_um2(mesh), mesh::enclosed_volume_um3(mesh));
}

void check_settings(const EnergyShapeSettings& settings) {
  if (settings.paths.empty()) throw InputError("mesh.energy.paths", "needs at least one path");
  for (const auto& path : settings.paths) energy_paths().find(path, "mesh.energy.paths");
  auto require_positive = [](double value, const char* key) {
    if (!(value > 0.0)) {
      throw InputError(key, "must be > 0, got " + format_number(value));
    }
  };
  require_positive(settings.area_um2, "mesh.energy.membrane_area_um2");
  require_positive(settings.bending_modulus_J, "mesh.energy.bending_modulus_J");
  require_positive(settings.skeleton.shear_modulus_pN_per_um, "mesh.energy.shear_modulus_uN_per_m");
  require_positive(settings.skeleton.area_modulus_pN_per_um, "mesh.energy.area_modulus_uN_per_m");
  if (!(settings.reduced_volume >= kLowestReachableReducedVolume &&
        settings.reduced_volume <= settings.skeleton_reference_reduced_volume)) {
    throw InputError("mesh.energy.reduced_volume",
                     "must lie in [" + format_number(kLowestReachableReducedVolume) + ", " +
                         format_number(settings.skeleton_reference_reduced_volume) +
                         "]: the lowest reached, and the skeleton reference's "
                         "(mesh.energy.skeleton_reference_reduced_volume) the shape is deflated "
                         "from; got " +
                         format_number(settings.reduced_volume));
  }
  const auto [lowest, highest] = kReachableAreaDifference;
  if (!(settings.relaxed_area_difference >= lowest &&
        settings.relaxed_area_difference <= highest)) {
    throw InputError(settings.relaxed_area_difference_key,
                     format_number(settings.relaxed_area_difference) +
                         " is outside the range the model reaches, " + format_number(lowest) +
                         " to " + format_number(highest) +
                         " (beyond, the minimisation does not converge or the cup closes)");
  }
}

// Seeded displacement of every vertex by up to `amplitude_um` per axis: breaks the spheroid's
// symmetry, so that the minimum found does not depend on the icosphere's own.
void perturb(std::span<Vec3> positions_um, std::uint64_t seed, double amplitude_um) {
  std::mt19937_64 generator(seed);
  std::uniform_real_distribution<double> draw(-amplitude_um, amplitude_um);
  for (auto& position : positions_um) position += random_vec3(draw, generator);
}

double volume_for(double reduced_volume, double area_um2) {
  return reduced_volume * std::pow(area_um2, 1.5) / (6.0 * std::sqrt(std::numbers::pi));
}

// Area-weighted outward normal of every vertex, unit length.
std::vector<Vec3> vertex_normals(const mesh::TriangleMesh& shape) {
  std::vector<Vec3> normals(shape.vertex_count(), Vec3::Zero());
  for (const auto& triangle : shape.triangles) {
    const Vec3 area_vector = mesh::triangle_area_vector(shape.positions_um, triangle);
    for (auto v : triangle) normals[v] += area_vector;
  }
  for (auto& normal : normals) normal.normalize();
  return normals;
}

// Moves every vertex by the same distance along its normal so that the mesh has the `target`
// reduced volume, searched by bisection within about a quarter of the mean edge either way (v is
// monotonic in so small an offset; it rises with it on a discocyte and falls on a spiculated
// body). False, and the mesh unchanged, when the target lies beyond.
bool offset_to_reduced_volume(mesh::TriangleMesh& shape, double target) {
  const auto start = shape.positions_um;
  const auto normals = vertex_normals(shape);
  const double reach = 0.25 * std::sqrt(mesh::surface_area_um2(shape) /
                                       static_cast<double>(shape.triangle_count()));
  auto place = [&](double offset) {
    for (std::size_t v = 0; v < start.size(); ++v) {
      shape.positions_um[v] = start[v] + offset * normals[v];
    }
    return mesh_reduced_volume(shape);
  };
  double low = -reach;
  double high = reach;
  const double at_low = place(low);
  const double at_high = place(high);
  if ((at_low - target) * (at_high - target) > 0.0) {
    shape.positions_um = start;
    return false;
  }
  for (int step = 0; step < kBisectionSteps; ++step) {
    const double middle = 0.5 * (low + high);
    ((place(middle) < target) == (at_high > at_low) ? low : high) = middle;
  }
  place(0.5 * (low + high));
  return true;
}

membrane::SkeletonParameters scaled(membrane::SkeletonParameters skeleton, double fraction) {
  skeleton.shear_modulus_pN_per_um *= fraction;
  skeleton.area_modulus_pN_per_um *= fraction;
  return skeleton;
}

struct TrialOutcome {
  EnergyShapeTrial trial;
  std::vector<Vec3> positions_um;
};

// Follows `path` from the reference with `seed`. A RuntimeFailure on the way (a constraint that
// cannot be restored at FIRE's smallest step) ends the trial with its text, not the shape.
TrialOutcome run_trial(const EnergyPath& path, std::uint64_t seed, int trial_index,
                       const mesh::TriangleMesh& reference, const mesh::MeshTopology& topology,
                       const EnergyShapeSettings& settings, const EnergyShapeProgress& progress) {
  const auto started = std::chrono::steady_clock::now();
  const double start_volume = mesh::enclosed_volume_um3(reference);
  BilayerCoupleModel model(
      reference.triangles, topology,
      membrane::capture_skeleton_reference(reference.positions_um, reference.triangles),
      bilayer_couple_parameters(settings, settings.area_um2, start_volume));
  TrialOutcome outcome;
  outcome.trial.path = std::string(path.name);
  outcome.trial.seed = seed;
  outcome.positions_um = reference.positions_um;
  const auto stages = energy_stages(path, settings, start_volume);
  try {
    minimise::FireResult last;
    for (std::size_t index = 0; index < stages.size(); ++index) {
      const auto& stage = stages[index];
      model.set_volume_um3(stage.volume_um3);
      model.set_skeleton(scaled(settings.skeleton, stage.skeleton_fraction));
      model.set_relaxed_curvature_sum_um(
          membrane::curvature_sum_for(stage.relaxed_area_difference, settings.area_um2));
      // A fresh seeded kick at every stage: a state that the path's last change made a saddle
      // holds no component along the unstable mode after the previous minimisation, and FIRE
      // would stop on it.
      perturb(outcome.positions_um, seed * 7919 + index, settings.perturbation_um);
      model.restore(outcome.positions_um);
      minimise::FireSettings fire;
      fire.force_tolerance = stage.force_tolerance_pN;
      fire.max_iterations = stage.iterations;
      fire.stiffness_update_interval = 1000;
      if (progress) {
        fire.on_iteration = [&](const minimise::FireResult& so_far) {
          if (so_far.iterations % 200 == 0) progress(trial_index, static_cast<int>(index), so_far);
          return true;
        };
      }
      last = minimise::minimise_fire(model, outcome.positions_um, fire);
      outcome.trial.iterations += last.iterations;
    }
    outcome.trial.converged = last.converged;
    outcome.trial.max_force_pN = last.max_force;
    outcome.trial.energies = model.evaluate(outcome.positions_um, {});
    outcome.trial.self_intersections =
        mesh::self_intersections({outcome.positions_um, reference.triangles}).size();
  } catch (const RuntimeFailure& failure) {
    outcome.trial.failure = failure.what();
  }
  outcome.trial.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return outcome;
}

std::string trial_summary(const EnergyShapeTrial& trial, const EnergyShapeSettings& settings) {
  std::string text = trial.path + " path, seed " + std::to_string(trial.seed) + ": ";
  if (trial.failure) return text + *trial.failure;
  if (!trial.converged) {
    return text + "did not converge in " + std::to_string(settings.max_iterations) +
           " iterations (mesh.energy.max_iterations): the largest vertex force is " +
           format_significant(trial.max_force_pN) + " pN against " +
           format_number(settings.force_tolerance_pN) + " pN (mesh.energy.force_tolerance_pN)";
  }
  return text + "its minimum passes through itself (" + std::to_string(trial.self_intersections) +
         " intersecting triangle pairs)";
}

}  // namespace

std::vector<EnergyStage> energy_stages(const EnergyPath& path, const EnergyShapeSettings& settings,
                                       double start_volume_um3) {
  std::vector<EnergyStage> stages;
  const double target_volume = volume_for(settings.reduced_volume, settings.area_um2);
  const double soft = path.soft_deflation ? settings.soft_skeleton_fraction : 1.0;
  const double target_a0 = settings.relaxed_area_difference;
  const double start_a0 =
      path.area_difference_continuation ? settings.continuation_start_area_difference : target_a0;
  auto stage = [&](double volume, double fraction, double a0) {
    return EnergyStage{volume, fraction, a0, settings.stage_iterations,
                       settings.stage_force_tolerance_pN};
  };
  for (int k = 1; k <= settings.volume_stages; ++k) {
    const double f = static_cast<double>(k) / settings.volume_stages;
    stages.push_back(
        stage(start_volume_um3 + f * (target_volume - start_volume_um3), soft, start_a0));
  }
  if (path.soft_deflation) {
    for (int k = 1; k <= settings.stiffening_stages; ++k) {
      const double f = static_cast<double>(k) / settings.stiffening_stages;
      stages.push_back(stage(target_volume, std::pow(soft, 1.0 - f), start_a0));
    }
  }
  const int steps =
      static_cast<int>(std::ceil(std::abs(target_a0 - start_a0) / settings.continuation_step));
  for (int k = 1; k < steps; ++k) {
    const double f = static_cast<double>(k) / steps;
    stages.push_back(stage(target_volume, 1.0, start_a0 + f * (target_a0 - start_a0)));
  }
  stages.push_back(
      {target_volume, 1.0, target_a0, settings.max_iterations, settings.force_tolerance_pN});
  return stages;
}

const Registry<EnergyPath>& energy_paths() {
  static const Registry<EnergyPath> paths(
      "energy path",
      {{"soft",
        "deflated with the skeleton's moduli at mesh.energy.soft_skeleton_fraction, then stiffened "
        "(the nearly fluid membrane Lim et al. relax their reference with)",
        true, false},
       {"stiff", "deflated with the full skeleton", false, false},
       {"continuation",
        "deflated with the full skeleton at mesh.energy.continuation_start_area_difference, "
        "then Delta a0 walked to the shape's in steps of at most mesh.energy.continuation_step",
        false, true}});
  return paths;
}

BilayerCoupleParameters bilayer_couple_parameters(const EnergyShapeSettings& settings,
                                                  double area_um2, double volume_um3) {
  BilayerCoupleParameters parameters;
  const double kappa_pN_um = settings.bending_modulus_J * kPicoNewtonMicrometrePerJoule;
  parameters.bending.bending_modulus_pN_um = kappa_pN_um;
  parameters.area_difference.bending_modulus_pN_um = kappa_pN_um;
  parameters.area_difference.nonlocal_ratio = settings.nonlocal_bending_ratio;
  parameters.area_difference.relaxed_curvature_sum_um =
      membrane::curvature_sum_for(settings.relaxed_area_difference, settings.area_um2);
  parameters.skeleton = settings.skeleton;
  parameters.area_um2 = area_um2;
  parameters.volume_um3 = volume_um3;
  return parameters;
}

nlohmann::ordered_json to_json(const EnergyShapeSettings& settings) {
  const auto& skeleton = settings.skeleton;
  nlohmann::ordered_json json = {
      {"membrane_area_um2", settings.area_um2},
      {"reduced_volume", settings.reduced_volume},
      {"relaxed_area_difference", settings.relaxed_area_difference},
      {"bending_modulus_J", settings.bending_modulus_J},
      {"nonlocal_bending_ratio", settings.nonlocal_bending_ratio},
      {"shear_modulus_uN_per_m", skeleton.shear_modulus_pN_per_um},
      {"area_modulus_uN_per_m", skeleton.area_modulus_pN_per_um},
      {"skeleton_a3", skeleton.a3},
      {"skeleton_a4", skeleton.a4},
      {"skeleton_b1", skeleton.b1},
      {"skeleton_b2", skeleton.b2},
      {"skeleton_reference_reduced_volume", settings.skeleton_reference_reduced_volume},
      {"paths", settings.paths},
      {"soft_skeleton_fraction", settings.soft_skeleton_fraction},
      {"volume_stages", settings.volume_stages},
      {"stiffening_stages", settings.stiffening_stages},
      {"stage_iterations", settings.stage_iterations},
      {"stage_force_tolerance_pN", settings.stage_force_tolerance_pN},
      {"trials", settings.trials},
      {"seed", settings.seed},
      {"perturbation_um", settings.perturbation_um},
      {"force_tolerance_pN", settings.force_tolerance_pN},
      {"max_iterations", settings.max_iterations},
      {"redistribution_sweeps", settings.redistribution.iterations},
      {"redistribution_step", settings.redistribution.step_fraction},
  };
  // Only where a path uses them, so that the settings of shapes made without them (the shipped
  // meshes' manifest entries) stay what they were.
  const bool continued = std::ranges::any_of(settings.paths, [](const std::string& name) {
    return energy_paths().find(name, "mesh.energy.paths").area_difference_continuation;
  });
  if (continued) {
    json["continuation_start_area_difference"] = settings.continuation_start_area_difference;
    json["continuation_step"] = settings.continuation_step;
  }
  return json;
}

mesh::TriangleMesh oblate_spheroid(int subdivisions, double reduced_volume, double area_um2) {
  const auto sphere = mesh::unit_icosphere(subdivisions);
  auto squash = [&](double axis_ratio) {
    auto spheroid = sphere;
    for (auto& position : spheroid.positions_um) position.z() *= axis_ratio;
    return spheroid;
  };
  // v grows with the axis ratio c / a up to the (polyhedral) sphere's.
  double low = 1e-3;
  double high = 1.0;
  if (reduced_volume >= mesh_reduced_volume(sphere)) {
    throw InputError("mesh.energy.skeleton_reference_reduced_volume",
                     "must be below the level-" + std::to_string(subdivisions) +
                         " icosphere's own reduced volume " +
                         format_number(mesh_reduced_volume(sphere)) + ", got " +
                         format_number(reduced_volume));
  }
  for (int step = 0; step < kBisectionSteps; ++step) {
    const double middle = 0.5 * (low + high);
    (mesh_reduced_volume(squash(middle)) < reduced_volume ? low : high) = middle;
  }
  auto spheroid = squash(0.5 * (low + high));
  mesh::scale_to_area(spheroid, area_um2);
  return spheroid;
}

mesh::TriangleMesh redistribute_on_surface(const mesh::TriangleMesh& shape, int subdivisions,
                                           const mesh::RelaxationSettings& relaxation,
                                           Redistribution& record) {
  const auto before = mesh::inspect_mesh(shape);
  record = {};
  record.sweeps = relaxation.iterations;
  record.min_angle_before_deg = record.min_angle_deg = before.min_angle_deg;
  record.max_angle_before_deg = record.max_angle_deg = before.max_angle_deg;
  if (relaxation.iterations == 0) {
    record.outcome = "not asked for";
    return shape;
  }
  const auto sphere = mesh::unit_icosphere(subdivisions);
  const auto surface = mesh::piecewise_linear_map(sphere, shape);
  auto result = mesh::map_mesh(surface, mesh::relax_parameter_mesh(surface, sphere, relaxation));
  // Vertices inside the minimum's flat triangles cut its corners: a little area and volume is
  // lost. Given back by one uniform offset along the vertex normals (to the reduced volume) and
  // one uniform scale (to the area), which change the triangles' angles least: restoring along
  // the constraints' gradients would move the sharpest features (a cup's lip) most.
  const auto on_surface = result.positions_um;
  if (!offset_to_reduced_volume(result, mesh::reduced_volume(before.area_um2, before.volume_um3))) {
    record.outcome = "not kept: the smoothing cut off features (the reduced volume is not "
                     "restored by a uniform offset of a quarter of an edge)";
    return shape;
  }
  mesh::scale_to_area(result, before.area_um2);
  const auto after = mesh::inspect_mesh(result);
  if (!(after.min_angle_deg > before.min_angle_deg)) {
    record.outcome = "not kept: the smallest angle would fall from " +
                     format_number(before.min_angle_deg) + " to " +
                     format_number(after.min_angle_deg) + " deg";
    return shape;
  }
  record.kept = true;
  record.outcome = "kept";
  record.min_angle_deg = after.min_angle_deg;
  record.max_angle_deg = after.max_angle_deg;
  for (std::size_t v = 0; v < on_surface.size(); ++v) {
    record.largest_restoring_move_um = std::max(record.largest_restoring_move_um,
                                                (result.positions_um[v] - on_surface[v]).norm());
  }
  return result;
}

EnergyShape minimise_shape(int subdivisions, const EnergyShapeSettings& settings,
                           const EnergyShapeProgress& progress) {
  check_settings(settings);
  EnergyShape shape;
  shape.skeleton_reference =
      oblate_spheroid(subdivisions, settings.skeleton_reference_reduced_volume, settings.area_um2);
  const auto topology = mesh::MeshTopology::build(shape.skeleton_reference);
  std::vector<Vec3> best_positions;
  std::optional<std::size_t> best;
  int trial_index = 0;
  for (const auto& path_name : settings.paths) {
    const auto& path = energy_paths().find(path_name, "mesh.energy.paths");
    for (int k = 0; k < settings.trials; ++k) {
      auto outcome = run_trial(path, settings.seed + static_cast<std::uint64_t>(k), trial_index++,
                               shape.skeleton_reference, topology, settings, progress);
      shape.trials.push_back(outcome.trial);
      if (!outcome.trial.valid()) continue;
      if (!best ||
          outcome.trial.energies.total_pN_um() < shape.trials[*best].energies.total_pN_um()) {
        best = shape.trials.size() - 1;
        best_positions = std::move(outcome.positions_um);
      }
    }
  }
  if (!best) {
    std::string reasons;
    for (const auto& trial : shape.trials) {
      reasons += (reasons.empty() ? "" : "; ") + trial_summary(trial, settings);
    }
    throw RuntimeFailure("the shape minimisation found no valid minimum: " + reasons);
  }
  shape.best_trial = *best;
  shape.minimum.triangles = shape.skeleton_reference.triangles;
  shape.minimum.positions_um = std::move(best_positions);
  shape.energies = shape.trials[shape.best_trial].energies;
  shape.reduced_area_difference = membrane::reduced_area_difference(
      mesh::curvature_sums(shape.minimum.positions_um, topology).signed_um,
      mesh::surface_area_um2(shape.minimum));
  mesh::translate_centroid_to_origin(shape.minimum);
  mesh::align_principal_axes(shape.minimum);
  shape.mesh = redistribute_on_surface(shape.minimum, subdivisions, settings.redistribution,
                                       shape.redistribution);
  mesh::round_to_single_precision(shape.minimum);
  mesh::round_to_single_precision(shape.mesh);
  return shape;
}

}  // namespace rbcsim::shapes
