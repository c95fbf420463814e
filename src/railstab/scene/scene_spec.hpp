#pragma once
// The scene as data: what a scene file says, in SI units, before any model is
// built. The scene reader (scene_reading/load_scene.hpp) fills it and checks
// it; the set-up step (setup/) builds the profile contact tables; the model
// (model/model.hpp) is assembled from it. Nothing here computes physics.
// The parts that the layers below use too are described beside the code that
// uses them: a wheel-rail contact (ContactSpec, contact/contact_spec.hpp) and
// the track (TrackSpec, track/track_spec.hpp); a force element is the model's
// element type (elements/element.hpp).
//
// Frames and conventions (stated once, used everywhere):
// - W: fixed (global) frame, z up, gravity along -z.
// - T: track frame of a body, origin on the track centreline at the body's own
//   arc length s(t) = reference_arc_length + track_offset + V t; x along the
//   track, y to the left, z up out of the track plane (A = Az Ay Ax).
// - Body coordinates (6, relative to T): x, y, z of the centre of mass, then
//   roll (about x), pitch (about y), yaw (about z), composed as B = Bz Bx By.
//   A wheelset's pitch is its spin angle; its attachment points live in the
//   non-spinning intermediate frame I = Bz Bx.
// - Curvature > 0 turns left (+y). Cant > 0 raises the right rail, i.e. the
//   normal cant of a left-hand curve; the track roll angle is -asin(cant / D).
#include <railstab/contact/contact_spec.hpp>
#include <railstab/core/coordinates.hpp>
#include <railstab/elements/element.hpp>
#include <railstab/scene/integrator_kind.hpp>
#include <railstab/track/track_spec.hpp>

#include <Eigen/Dense>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace railstab {

// --- Bodies ------------------------------------------------------------------------
// A point fixed in a rigid body where `simulate` reports accelerations
// ([[bodies.measure_points]]; docs/ride_quantities.md), e.g. the bogie frame
// above the leading wheelset, where EN 14363 places its accelerometer.
struct MeasurePointSpec {
  std::string name;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  // from the CM, body axes (x fwd, y left, z up)
};

struct BodySpec {
  std::string name;
  bool is_wheelset = false;
  double mass_kg = 0.0;
  Eigen::Vector3d inertia_kg_m2 = Eigen::Vector3d::Zero();  // principal Jx, Jy, Jz
  double track_offset_m = 0.0;  // arc length of its track frame minus the reference
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  // nominal CM in its track frame
  std::array<bool, 6> free = {true, true, true, true, true, true};
  std::array<double, 6> initial_offset = {0, 0, 0, 0, 0, 0};  // m and rad, added to nominal
  std::array<double, 6> initial_rate = {0, 0, 0, 0, 0, 0};    // m/s and rad/s
  std::string contact;  // wheelsets: name of a ContactSpec
  std::vector<MeasurePointSpec> measure_points;  // rigid bodies only
};

// --- Force elements -------------------------------------------------------------------
// An element as the scene gives it is the model's element type itself
// (elements/element.hpp) with body names; the builder resolves the names and
// sets what is measured from the nominal configuration.
using ElementSpec = ElementTpl<double>;

// --- Analyses ---------------------------------------------------------------------------
enum class PreloadMode {
  balance_gravity_at_nominal,  // ERRATA 13: suspension preloads solved so the
                               // nominal position is the static equilibrium
  none                         // free lengths at the nominal position: the vehicle sags
};

// Defaults from the work-precision study of the thesis vehicle (README,
// "Error against run time"): ARKODE's L-stable SDIRK of order 4 at rtol 1e-3
// is the cheapest run below 1e-5 m position error (lateral error ~1e-7 m).
// On a contact table (profile contact) the defaults are those of
// profile_contact_simulation_defaults() instead.
struct SimulationSpec {
  double t_end_s = 10.0;
  double output_interval_s = 0.01;
  IntegratorKind integrator = IntegratorKind::arkode_dirk;
  int integrator_order = 0;  // 0: the method's default (see IntegrationOptions::order)
  double relative_tolerance = 1e-3;
  double absolute_tolerance = 1e-6;  // m, rad, m/s, rad/s alike
};

// The defaults of a scene with a contact table (geometry "profiles" or
// "table"), each key that [simulation] does not give: CVODE Adams at rtol
// 1e-4, atol 1e-8. In flange hunting every integrator resolves the nearly
// undamped wheel-rail contact modes (~200 Hz), so the cost is the work per
// step: Adams takes ~1.3 right-hand sides per step where the SDIRK takes
// ~13. Measured against rtol 1e-8 references (docs/time_domain.md,
// "Profile contact"; analysis/bench_flange_hunting.cpp): 3-4 times cheaper
// than the SDIRK at 1e-3/1e-6 and 1.5-3 times more accurate, on the thesis
// vehicle (100 m/s), the thesis bogie (45 m/s) and the coach (120 m/s).
inline SimulationSpec profile_contact_simulation_defaults() {
  SimulationSpec spec;
  spec.integrator = IntegratorKind::cvode_adams;
  spec.relative_tolerance = 1e-4;
  spec.absolute_tolerance = 1e-8;
  return spec;
}

// Limits the ride and assessment quantities are judged against
// ([assessment]; docs/ride_quantities.md).
struct AssessmentSpec {
  // alpha of Prud'homme's limit (Sum Y)_lim = alpha (10 kN + P0 / 3) on the
  // track shift force of a wheelset, P0 its static axle load in kN: 1.0 for
  // locomotives and passenger vehicles, 0.85 for freight wagons (EN 14363).
  double prudhomme_factor = 1.0;
  // EN 14363's flange-climbing limit on the 2 m mean of Y/Q (curves of
  // R >= 250 m).
  double y_over_q_limit = 0.8;
  // Running stability (railstab assess; docs/assessment.md): the rms of the
  // band-passed Sum Y and bogie frame lateral acceleration over windows of
  // stability_window_m stepped by stability_window_step_m, the band
  // f0 +- stability_band_half_width_Hz around the instability frequency f0,
  // a Butterworth band-pass whose prototype order is stability_filter_order
  // (the order EN 14363 prescribes is not public to us: a parameter).
  double stability_window_m = 100.0;
  double stability_window_step_m = 10.0;
  double stability_band_half_width_Hz = 2.0;
  int stability_filter_order = 4;
};

struct SceneSpec {
  std::string name;
  std::string source_path;  // file it was read from, for messages
  // SHA-256 of the file's bytes as read (before any --set), for reports;
  // empty for a scene from text or built in code.
  std::string source_sha256;
  double speed_m_per_s = 0.0;
  double gravity_m_per_s2 = 9.81;
  double reference_arc_length_m = 0.0;
  TrackSpec track;
  std::vector<ContactSpec> contacts;
  std::vector<BodySpec> bodies;
  std::vector<ElementSpec> elements;
  PreloadMode preload = PreloadMode::balance_gravity_at_nominal;
  SimulationSpec simulation;
  AssessmentSpec assessment;
};

}  // namespace railstab
