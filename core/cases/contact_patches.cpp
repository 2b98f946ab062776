#include "cases/contact_patches.hpp"

#include <algorithm>
#include <array>
#include <iterator>
#include <numeric>

#include "common/errors.hpp"
#include "common/registry.hpp"

namespace rbcsim::cases {
namespace {

// Vertex indices ordered by decreasing sign * x, ties by index.
std::vector<std::int32_t> ordered_towards_end(std::span<const Vec3> positions_um, double sign) {
  std::vector<std::int32_t> order(positions_um.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) {
    return sign * positions_um[a].x() > sign * positions_um[b].x();
  });
  return order;
}

std::vector<std::int32_t> within_contact_diameter(std::span<const Vec3> positions_um,
                                                  const ContactSettings& settings, double sign) {
  const auto order = ordered_towards_end(positions_um, sign);
  const Vec3 tip = positions_um[order.front()];
  const double radius_um = settings.diameter_um / 2;
  std::vector<std::int32_t> patch;
  for (const auto vertex : order) {
    if ((positions_um[vertex] - tip).norm() <= radius_um) patch.push_back(vertex);
  }
  std::sort(patch.begin(), patch.end());
  return patch;
}

std::vector<std::int32_t> extreme_vertices(std::span<const Vec3> positions_um,
                                           const ContactSettings& settings, double sign) {
  auto order = ordered_towards_end(positions_um, sign);
  const auto count =
      std::min(static_cast<std::size_t>(std::max(settings.extreme_vertex_count, 0)), order.size());
  order.resize(count);
  std::sort(order.begin(), order.end());
  return order;
}

struct ContactRule {
  std::string_view name;
  std::string_view option_path;  // the option that sets the patch size, for diagnostics
  std::vector<std::int32_t> (*select)(std::span<const Vec3>, const ContactSettings&, double sign);
};

constexpr std::array<ContactRule, 2> kContactRules{{
    {"contact-diameter", "stretch.contact.diameter_um", within_contact_diameter},
    {"extreme-vertices", "stretch.contact.extreme_vertex_count", extreme_vertices},
}};

bool share_a_vertex(const std::vector<std::int32_t>& a, const std::vector<std::int32_t>& b) {
  std::vector<std::int32_t> common;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
  return !common.empty();
}

}  // namespace

std::vector<std::string> contact_rule_names() { return entry_names(kContactRules); }

ContactPatches select_contact_patches(std::span<const Vec3> positions_um,
                                      const ContactSettings& settings) {
  const auto& rule = find_entry(kContactRules, settings.rule, "stretch.contact.rule");
  ContactPatches patches{rule.select(positions_um, settings, +1.0),
                         rule.select(positions_um, settings, -1.0)};
  if (patches.positive_end.empty() || patches.negative_end.empty()) {
    throw InputError(std::string(rule.option_path), "a contact patch holds no vertex");
  }
  if (share_a_vertex(patches.positive_end, patches.negative_end)) {
    throw InputError(std::string(rule.option_path),
                     "the two contact patches overlap: too large for this cell");
  }
  return patches;
}

std::vector<std::vector<std::int32_t>> rigid_contact_groups(const ContactPatches& patches,
                                                            const ContactSettings& settings) {
  if (!settings.rigid) return {};
  return {patches.positive_end, patches.negative_end};
}

std::vector<Vec3> tweezer_forces_pN(std::size_t vertex_count, const ContactPatches& patches,
                                    double force_pN) {
  std::vector<Vec3> forces(vertex_count, Vec3::Zero());
  const auto spread = [&forces](const std::vector<std::int32_t>& patch, double total_pN) {
    const Vec3 share(total_pN / static_cast<double>(patch.size()), 0.0, 0.0);
    for (const auto vertex : patch) forces[vertex] += share;
  };
  spread(patches.positive_end, force_pN);
  spread(patches.negative_end, -force_pN);
  return forces;
}

}  // namespace rbcsim::cases
