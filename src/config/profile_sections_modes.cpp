// Each estimator mode's own profile section (docs/estimators.md): `point` (with the shape of
// profiles before mode sections), `bernoulli`, `group` and `extended`.
#include <algorithm>
#include <iterator>
#include <string>

#include "profile_sections.hpp"

namespace skytrack::config::detail {
namespace {

// The point tracker's sections, under `point`. A profile of the shape before mode sections has
// them at the top level: read from there, the same keys (config/README.md, "Profiles of the
// earlier shape"); a profile may not have both.
void read_point(YamlSection& root, ErrorList& errors, TrackingProfile& p) {
  constexpr const char* kSections[] = {"initiation", "track_life", "branching"};
  if (p.mode != TrackingMode::kPoint) {
    for (const char* key : {"point", "initiation", "track_life", "branching"}) {
      if (!root.has(key)) continue;
      root.section(key);
      root.error(key, "applies to mode: point only (this profile's mode is " +
                          std::string(to_string(p.mode)) + ")");
    }
    return;
  }
  if (!root.has("point")) {
    p.point.initiation = read_initiation(root.section("initiation"));
    p.point.track_life = read_track_life(root.section("track_life"));
    p.point.branching = read_branching(root.section("branching"), errors, p);
    return;
  }
  for (const char* key : kSections) {
    if (root.has(key)) {
      root.error(key, "belongs under point: (point." + std::string(key) +
                          "), and this profile has a point section");
    }
  }
  YamlSection point = root.section("point");
  p.point.initiation = read_initiation(point.section("initiation"));
  p.point.track_life = read_track_life(point.section("track_life"));
  p.point.branching = read_branching(point.section("branching"), errors, p);
  point.finish();
}

/// The Bernoulli filter's models are the profile's motion models: constant velocity and
/// coordinated turns at a known rate, their transition matrix per scan and a newborn
/// target's model probabilities the common ones.
void copy_bernoulli_models(YamlSection& root, TrackingProfile& p) {
  bernoulli::BernoulliSpec& b = p.bernoulli;
  const auto n = static_cast<int>(p.motion_models.size());
  if (n > bernoulli::kMaxModels) {
    root.error("motion_models",
               "mode bernoulli takes at most " + std::to_string(bernoulli::kMaxModels) + " models");
    return;
  }
  const auto square = [n](const auto& rows) {
    return static_cast<int>(rows.size()) == n &&
           std::all_of(rows.begin(), rows.end(),
                       [n](const auto& row) { return static_cast<int>(row.size()) == n; });
  };
  // A wrong-sized matrix or list was reported by check_imm.
  if (!square(p.mode_transition) || static_cast<int>(p.initial_mode_probabilities.size()) != n) {
    return;
  }
  for (int i = 0; i < n; ++i) {
    const MotionModelSpec& m = p.motion_models[static_cast<std::size_t>(i)];
    if (m.type != MotionModelType::kConstantVelocity &&
        m.type != MotionModelType::kCoordinatedTurn) {
      root.error("motion_models",
                 "mode bernoulli takes constant_velocity and coordinated_turn "
                 "models; '" +
                     m.name + "' is " + std::string(to_string(m.type)));
      return;
    }
    b.models[static_cast<std::size_t>(i)].turn_rate =
        m.type == MotionModelType::kCoordinatedTurn ? m.turn_rate : 0.0;
    b.models[static_cast<std::size_t>(i)].accel_sigma = m.accel_sigma;
    b.birth_model_probabilities[static_cast<std::size_t>(i)] =
        p.initial_mode_probabilities[static_cast<std::size_t>(i)];
    for (int j = 0; j < n; ++j) {
      b.transition[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          p.mode_transition[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    }
  }
  b.model_count = n;
  b.detection_probability = p.association.detection_probability;
}

void read_bernoulli(YamlSection s, YamlSection& root, TrackingProfile& p) {
  bernoulli::BernoulliSpec& b = p.bernoulli;
  copy_bernoulli_models(root, p);
  std::vector<double> particles;
  s.numbers("particles", particles, {}, Range{1.0, 1e6});
  if (!particles.empty()) {
    if (static_cast<int>(particles.size()) != b.model_count) {
      s.error("particles", "expected one count per motion model (" + std::to_string(b.model_count) +
                               "), got " + std::to_string(particles.size()));
    }
    for (std::size_t i = 0; i < particles.size() && i < b.models.size(); ++i) {
      b.models[i].particles = static_cast<int>(particles[i]);
    }
  }
  s.number("survival_probability", b.survival_probability, Range::open_probability());
  s.number("birth_probability", b.birth_probability, Range::open_probability());
  s.number("clutter_intensity", b.clutter_intensity, Range{1e-12, 1e3});
  s.number("existence_threshold", b.existence_threshold, kOpenUnit);
  read_enum(s, "birth", b.birth_proposal,
            {bernoulli::BirthProposal::kPlotPairs, bernoulli::BirthProposal::kVelocityPrior});
  s.integer("birth_particles", b.birth_particles, Range{1.0, 1e6});
  std::vector<double> velocity(b.birth_velocity.begin(), b.birth_velocity.end());
  s.numbers("birth_velocity", velocity, {2}, Range{-kMaxSpeed, kMaxSpeed});
  if (velocity.size() == 2) b.birth_velocity = {velocity[0], velocity[1]};
  s.number("birth_velocity_sigma", b.birth_velocity_sigma, Range{1e-3, kMaxSpeed});
  s.number("max_birth_speed", b.max_birth_speed, Range{1e-3, kMaxSpeed});
  s.number("gate_distance_squared", b.gate_distance_squared, Range{1.0, 1e4});
  std::int64_t seed = static_cast<std::int64_t>(b.seed);
  s.integer("seed", seed, Range::non_negative());
  b.seed = static_cast<std::uint64_t>(seed);
  s.finish();
}

void read_group(YamlSection s, TrackingProfile& p) {
  group::GroupSpec& g = p.group;
  g.preprocessing = p.clutter_rejection;
  read_enum(s, "motion", g.motion,
            {group::GroupMotion::kConstantVelocity, group::GroupMotion::kCoordinatedTurn});
  s.number("turn_rate", g.turn_rate, Range{-1.0, 1.0});
  s.integer("boxes_per_group", g.boxes_per_group, Range{1.0, 1e5});
  s.number("position_width", g.position_width, Range{1e-3, 1e6});
  s.number("velocity_width", g.velocity_width, Range{1e-3, kMaxSpeed});
  s.number("jitter", g.jitter, Range::probability());
  s.number("measurement_box_padding", g.measurement_box_padding, Range{0.0, 1e6});
  s.integer("births_per_box", g.births_per_box, Range{0.0, 1e4});
  s.integer("births_per_estimate", g.births_per_estimate, Range{0.0, 1e4});
  s.number("birth_mass_per_box", g.birth_mass_per_box, Range::open_probability());
  s.number("birth_speed", g.birth_speed, Range{0.0, kMaxSpeed});
  s.number("survival_probability", g.survival_probability, Range::open_probability());
  s.number("detection_probability", g.detection_probability, Range{0.0, 1.0, true, false});
  s.number("clutter_rate", g.clutter_rate, Range{0.0, 1e6});
  s.number("surveillance_area", g.surveillance_area, Range{1.0, 1e14});
  read_enum(s, "labels", g.labels, {group::LabelModel::kDouble, group::LabelModel::kSingle});
  s.number("extraction_threshold", g.extraction_threshold, kOpenUnit);
  s.integer("max_missed", g.max_missed, Range{0.0, 1000.0});
  s.boolean("exclusive_cells", g.exclusive_cells);
  s.number("shape_smoothing", g.shape_smoothing, Range{0.0, 1.0, true, false});
  s.number("measurement_sigma", g.measurement_sigma, Range{0.0, 1e6});
  s.number("member_detection_probability", g.member_detection_probability,
           Range{0.0, 1.0, true, false});
  s.number("readmit_distance", g.readmit_distance, Range{0.0, 1e6});
  std::int64_t seed = static_cast<std::int64_t>(g.seed);
  s.integer("seed", seed, Range::non_negative());
  g.seed = static_cast<std::uint64_t>(seed);
  s.finish();
}

void read_extended(YamlSection s, TrackingProfile& p) {
  extended::ExtendedSpec& e = p.extended;
  read_enum(s, "estimator", e.kind,
            {extended::EstimatorKind::kSmf, extended::EstimatorKind::kRandomMatrix,
             extended::EstimatorKind::kMemEkf});
  YamlSection motion = s.section("motion");
  motion.number("time_constant", e.motion.time_constant, Range{1e-3, 1e6});
  motion.number("accel_noise", e.motion.accel_noise, Range{0.0, kMaxAccel});
  motion.number("manoeuvre_accel", e.motion.manoeuvre_accel, Range{0.0, kMaxAccel});
  motion.number("straight_duration", e.motion.straight_duration, Range{1e-3, 1e6});
  motion.number("manoeuvre_duration", e.motion.manoeuvre_duration, Range{1e-3, 1e6});
  motion.finish();
  YamlSection smf = s.section("smf");
  smf.number("scattering", e.smf.scattering, Range{1e-3, 10.0});
  smf.number("bound_sigmas", e.smf.bound_sigmas, Range{0.1, 10.0});
  smf.integer("boundary_points", e.smf.boundary_points, Range{4.0, 1024.0});
  smf.number("extent_gain", e.smf.extent_gain, Range{0.0, 1.0, true, false});
  smf.number("min_axis", e.smf.min_axis, Range{1e-3, 1e5});
  smf.number("outlier_margin", e.smf.outlier_margin, Range{0.0, 100.0});
  smf.number("outlier_min_axis", e.smf.outlier_min_axis, Range{0.0, 1e5});
  smf.finish();
  YamlSection rm = s.section("random_matrix");
  rm.number("scattering", e.random_matrix.scattering, Range{1e-3, 10.0});
  rm.number("extent_time_constant", e.random_matrix.extent_time_constant, Range{1e-3, 1e7});
  rm.number("initial_dof", e.random_matrix.initial_dof, Range{2.0, 1e6, true, false});
  rm.finish();
  YamlSection mem = s.section("mem_ekf");
  mem.number("scattering", e.mem_ekf.scattering, Range{1e-3, 10.0});
  mem.number("orientation_noise", e.mem_ekf.orientation_noise, Range{0.0, 10.0});
  mem.number("axis_noise", e.mem_ekf.axis_noise, Range{0.0, 1e8});
  mem.number("initial_orientation_var", e.mem_ekf.initial_orientation_var, Range{1e-6, 10.0});
  mem.number("initial_axis_var", e.mem_ekf.initial_axis_var, Range{1e-3, 1e10});
  mem.number("spread_bound_sigmas", e.mem_ekf.spread_bound_sigmas, Range{0.0, 10.0});
  mem.number("min_axis", e.mem_ekf.min_axis, Range{1e-3, 1e5});
  mem.finish();
  s.number("partition_distance", e.partition_distance, Range{1e-3, 1e6});
  s.number("gate", e.gate, Range{1e-3, 1e4});
  s.number("plot_gate", e.plot_gate, Range{1e-3, 1e4});
  s.integer("min_partition_plots", e.min_partition_plots, Range{1.0, 1e4});
  s.integer("confirm_hits", e.confirm_hits, Range{1.0, 1000.0});
  s.integer("tentative_max_misses", e.tentative_max_misses, Range{1.0, 1000.0});
  s.integer("delete_misses", e.delete_misses, Range{1.0, 1000.0});
  YamlSection existence = s.section("existence");
  extended::ExistenceSpec& x = e.existence;
  existence.boolean("enabled", x.enabled);
  existence.number("detection_probability", x.detection_probability, Range::open_probability());
  existence.number("expected_plots", x.expected_plots, Range{1e-3, 1e6});
  existence.number("clutter_density", x.clutter_density, Range{1e-15, 1.0});
  existence.number("survival", x.survival, Range::open_probability());
  existence.number("birth", x.birth, Range{0.0, 1.0, true, true});
  existence.number("delete_below", x.delete_below, Range{0.0, 1.0, true, true});
  existence.finish();
  s.number("initial_speed_sigma", e.initial_speed_sigma, Range{1e-3, kMaxSpeed});
  s.number("initial_accel_sigma", e.initial_accel_sigma, Range{1e-3, kMaxAccel});
  s.number("initial_extent_axis", e.initial_extent_axis, Range{1e-3, 1e5});
  s.boolean("coast_constant_velocity", e.coast_constant_velocity);
  s.boolean("clutter_scan_test", e.clutter_scan_test);
  s.boolean("one_object_split_test", e.one_object_split_test);
  s.finish();
}

/// A mode's own section: read when it is the profile's mode, refused otherwise.
template <class Read>
void mode_section(YamlSection& root, TrackingProfile& p, TrackingMode mode, const Read& read) {
  const std::string key(to_string(mode));
  if (p.mode == mode) {
    if (p.dimension == 3) root.error("dimension", "mode " + key + " tracks in 2-D (2 or auto)");
    read(root.section(key));
  } else if (root.has(key)) {
    root.section(key);
    root.error(key, "applies to mode: " + key + " only (this profile's mode is " +
                        std::string(to_string(p.mode)) + ")");
  }
}

}  // namespace

void read_mode_sections(YamlSection& root, ErrorList& errors, TrackingProfile& p) {
  read_point(root, errors, p);
  mode_section(root, p, TrackingMode::kBernoulli,
               [&](YamlSection s) { read_bernoulli(s, root, p); });
  mode_section(root, p, TrackingMode::kGroup, [&](YamlSection s) { read_group(s, p); });
  mode_section(root, p, TrackingMode::kExtended, [&](YamlSection s) { read_extended(s, p); });
}

}  // namespace skytrack::config::detail
