#include <railstab/setup/prepare_scene.hpp>

#include <railstab/model/equations_of_motion.hpp>
#include <railstab/curving/steady_curving.hpp>
#include <railstab/equilibrium/speed_continuation.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/scene_reading/scene_checker.hpp>
#include <railstab/setup/contact_tables.hpp>
#include <railstab/setup/model_error_context.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace railstab {

namespace {

std::string number_text(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

// --arc-length moves the reference point; every body's own track frame
// (reference + track_offset_m) must stay on the track. Said here, naming
// the flag: the scene check would blame bodies[i].track_offset_m, which the
// user did not change.
void check_reference_override(const SceneSpec& spec, double reference_m) {
  double length_m = 0.0;
  for (const TrackSegmentSpec& segment : spec.track.segments) length_m += segment.length_m;
  double lowest = 0.0, highest = 0.0;
  for (const BodySpec& body : spec.bodies) {
    lowest = std::min(lowest, body.track_offset_m);
    highest = std::max(highest, body.track_offset_m);
  }
  const double from = -lowest, to = length_m - highest;
  if (!(reference_m >= from && reference_m <= to))
    throw SceneError(spec.source_path + ": --arc-length: expected an arc length in [" +
                     number_text(from) + ", " + number_text(to) +
                     "] m (the track is " + number_text(length_m) +
                     " m long and the bodies' track_offset_m span [" + number_text(lowest) +
                     ", " + number_text(highest) + "] m), got " + number_text(reference_m));
}

// Irregular track is applied by the time-domain commands only: a steady
// state or a linearisation is of the design track, and running one on a
// scene that has irregularities would silently leave them out.
void refuse_irregular_track(const SceneSpec& spec) {
  if (spec.track.irregularities)
    throw SceneError(
        (spec.source_path.empty() ? std::string("<scene>") : spec.source_path) +
        ": track.irregularities: expected no irregularities for this command, got a "
        "[track.irregularities] section: irregular track is applied by the time-domain commands "
        "(simulate, verify, assess) and written by `railstab track`; this analysis is of the design "
        "track (docs/irregular_track.md): remove the section to run it");
}

}  // namespace

SceneSpec load_scene_with_overrides(const std::string& path, const SceneOverrides& overrides) {
  SceneSpec spec = load_scene_file(path, overrides.values);  // read and checked
  if (!overrides.apply_track_irregularities) refuse_irregular_track(spec);
  try {
    build_contact_tables(spec);
  } catch (const SceneError& e) {
    throw SceneError(std::string(e.what()) + settings_in_force(overrides.values));
  }
  // The run's own values replace the file's: only the checks they enter run
  // again (the scene is checked once).
  ReplacedSceneValues replaced;
  if (overrides.speed_m_per_s) {
    spec.speed_m_per_s = *overrides.speed_m_per_s;
    replaced.speed = true;
  }
  if (overrides.t_end_s) {
    spec.simulation.t_end_s = *overrides.t_end_s;
    replaced.t_end = true;
  }
  if (overrides.reference_arc_length_m) {
    check_reference_override(spec, *overrides.reference_arc_length_m);
    spec.reference_arc_length_m = *overrides.reference_arc_length_m;
    replaced.reference_arc_length = true;
  }
  validate_replaced_values(spec, replaced);
  apply_offset_settings(spec, overrides.offsets);
  return spec;
}

PreparedScene prepare_scene(const std::string& path, const SceneOverrides& overrides) {
  return prepare_scene(load_scene_with_overrides(path, overrides), overrides.apply_track_irregularities);
}

namespace {

// Where the steady state at V cannot be found from the nominal position
// (Newton and the pseudo-transient fallback fail, e.g. steady curving on
// real profiles at high cant deficiency), it is followed up in speed as a
// sweep does: from kRampStartSpeed in steps of kRampStep, each continued with
// halvings (equilibrium/speed_continuation.hpp). Defaults of critical-speed.
constexpr double kRampStartSpeed_m_per_s = 5.0;
constexpr double kRampStep_m_per_s = 2.5;

EquilibriumResult steady_state_by_speed_ramp(const Model& model, double V,
                                             const EquilibriumError& direct) {
  double v = kRampStartSpeed_m_per_s;
  EquilibriumResult eq;
  bool started = false;
  try {
    eq = solve_equilibrium(model, v, lowered_nominal_state(model, v));
    started = true;
    while (v < V) {
      const double next = std::min(V, v + kRampStep_m_per_s);
      eq = continue_equilibrium_in_speed(model, v, eq.state, next, EquilibriumOptions{});
      v = next;
    }
  } catch (const EquilibriumError& e) {
    const std::string ramp = std::string(direct.what()) +
                             "; following the steady state up in speed from " +
                             number_text(kRampStartSpeed_m_per_s) + " m/s stopped at " +
                             number_text(v) + " m/s: " + e.what();
    if (!started) throw EquilibriumError(ramp, direct.last_state, direct.worst_state);
    // Natural continuation stops at a fold of the branch (a wheelset's
    // contact moving onto its flange root): pseudo-arclength continuation
    // in speed from the last converged point follows the branch around it
    // (curving/steady_curving.hpp). Its error names the last converged
    // point, or says that the vehicle has no steady state physically
    // (flange climbing) beyond it.
    try {
      return continue_scene_steady_state(model, v, eq.state, V).equilibrium;
    } catch (const CurvingError& c) {
      // The state said with the error is the last converged one.
      const Eigen::VectorXd last =
          c.last_converged ? c.last_converged->equilibrium.state : direct.last_state;
      throw EquilibriumError(ramp + "; " + c.what(), last, "");
    }
  }
  return eq;
}

}  // namespace

PreparedScene prepare_scene(SceneSpec spec, bool apply_track_irregularities) {
  if (!apply_track_irregularities) refuse_irregular_track(spec);
  build_contact_tables(spec);  // into the spec: later models built from it share them
  Model model = build_model(spec);
  const double V = spec.speed_m_per_s;
  EquilibriumResult eq = with_model_context(model, {"steady state at t = 0", V}, [&] {
    try {
      return solve_equilibrium(model, V, lowered_nominal_state(model, V));
    } catch (const EquilibriumError& direct) {
      if (!(V > kRampStartSpeed_m_per_s)) throw;
      return steady_state_by_speed_ramp(model, V, direct);
    }
  });
  return PreparedScene{std::move(spec), std::move(model), V, std::move(eq)};
}

// A lateral (or yaw) offset given alone moves a wheelset on its coned
// wheels: one wheel climbs, the other drops, and with the equilibrium's
// height and roll kept, one wheel starts out of contact ("lost contact at
// t = 0"). So for each Hertz-contact wheelset whose offsets leave z and roll
// unset, z and roll are solved so its vertical and roll accelerations vanish
// with everything else held (a partial equilibrium); offsets the scene gives
// for z or roll are kept as given.
Eigen::VectorXd perturbed_initial_state(const PreparedScene& scene) {
  const Model& model = scene.model;
  const double V = scene.speed_m_per_s;
  const int n = model.n_coordinates;
  Eigen::VectorXd x = scene.equilibrium.state;
  for (int k = 0; k < n; ++k) {
    const auto [b, c] = model.coordinate_of_state[k];
    x(k) += scene.spec.bodies[b].initial_offset[c];
  }
  std::vector<int> settle;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    const BodySpec& spec = scene.spec.bodies[b];
    if (!body.wheelset()) continue;
    if (model.contacts[size_t(body.wheelset()->contact)].spec.normal != NormalForceKind::hertz)
      continue;
    const auto& o = spec.initial_offset;
    const bool moved = o[int(CoordinateIndex::y)] != 0.0 || o[int(CoordinateIndex::yaw)] != 0.0;
    const bool given = o[int(CoordinateIndex::z)] != 0.0 || o[int(CoordinateIndex::roll)] != 0.0;
    if (!moved || given) continue;
    for (CoordinateIndex c : {CoordinateIndex::z, CoordinateIndex::roll})
      if (body.state_index[int(c)] >= 0) settle.push_back(body.state_index[int(c)]);
  }
  if (!settle.empty()) {
    EquilibriumOptions options;
    options.only_positions = settle;
    x = with_model_context(
        model, {"consistent start (wheelset height and roll for the initial offsets)", V}, [&] {
          return solve_equilibrium(model, V, x, options).state;
        });
  }
  for (int k = 0; k < n; ++k) {
    const auto [b, c] = model.coordinate_of_state[k];
    x(n + k) += scene.spec.bodies[b].initial_rate[c];
  }
  // The integration starts here: an error at this state is said now, with
  // where it is, rather than from inside the integrator.
  with_model_context(model, {"initial state of the time integration", V, 0.0, &x},
                     [&] { return rhs(model, V, 0.0, x); });
  return x;
}

}  // namespace railstab
