#pragma once
// Model checks a user wants before trusting a run: what the scene amounts
// to physically (total mass, axle loads, the static deflection of every
// spring under its preload, the natural frequencies at rest) and warnings
// for the usual input mistakes. Every limit is a named parameter of
// ModelCheckLimits with its unit and the reason for its default.
//
// Nothing here changes the model: a warning is advice, the run goes on.
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/model/model.hpp>
#include <railstab/scene/scene_spec.hpp>

#include <string>
#include <vector>

namespace railstab {

// Limits of the warnings. A railway engineer's ranges, wide enough that the
// vehicles of cases/ (thesis bogie and vehicle, textbook models) raise none.
struct ModelCheckLimits {
  // A wheelset is placed along the track by its track_offset_m (its track
  // frame, where its contact is evaluated); position_m.x beyond this puts it
  // ahead of or behind its own contact.
  double wheelset_position_x_max_m = 0.01;
  // spring_damper_3d and bump_stop act on the relative displacement of two
  // points that coincide at rest in a usual model (an axle box and its seat);
  // end points further apart than this at the nominal configuration mostly
  // mean a point given in the wrong body's frame (primary springs: < 0.1 m
  // apart in practice; 0.5 m leaves room for modelled spring heights).
  double spring_end_separation_max_m = 0.5;
  // Static deflection preload / stiffness of a spring beyond this (coil and
  // air springs: 0.02-0.3 m) means a stiffness 10x too soft or a preload on
  // the wrong axis.
  double static_deflection_max_m = 0.5;
  // Body masses by role (role from the topology: a wheelset; a rigid body
  // joined by an element to a wheelset is a bogie frame; a rigid body joined
  // to a bogie frame only is a car body (or bolster); any other rigid body).
  double wheelset_mass_min_kg = 500.0, wheelset_mass_max_kg = 3000.0;
  double bogie_frame_mass_min_kg = 1000.0, bogie_frame_mass_max_kg = 10000.0;
  double car_body_mass_min_kg = 5000.0, car_body_mass_max_kg = 100000.0;
  double other_body_mass_min_kg = 10.0, other_body_mass_max_kg = 100000.0;
  // Radius of gyration sqrt(J / m) of any body about any axis: outside this
  // the inertia is in another unit (t m^2, g m^2) or belongs to another body.
  double radius_of_gyration_min_m = 0.05, radius_of_gyration_max_m = 30.0;
  // Axle load (sum of the wheel loads normal to the track plane): 20 kN is
  // below an empty light wagon or a bogie alone (the thesis bogie: 29.5 kN),
  // 350 kN is the heaviest heavy-haul axle load in service (~35 t).
  double axle_load_min_N = 20e3, axle_load_max_N = 350e3;
  // 2 half_contact_distance_m against track.rail_contact_distance_m.
  double contact_distance_mismatch_max_m = 0.005;
  // Lengths that look like millimetres: positions in a body's track frame and
  // element points (a vehicle is below 30 m long and placed along the track
  // by track_offset_m), track offsets (a train of 20 coaches is ~500 m), and
  // wheel geometry (half contact distance, rolling radius).
  double body_position_max_m = 50.0;
  double element_point_max_m = 50.0;
  double track_offset_max_m = 1000.0;
  double wheel_geometry_max_m = 5.0;
  // A longitudinal coordinate is unheld when the stiffness matrix has an
  // eigenvalue omega^2 below (2 pi f)^2 with f this, whose eigenvector is
  // mostly (> half) longitudinal coordinates.
  double unheld_frequency_max_hz = 0.05;

  // --- plausibility of the run's conditions (docs/commands.md, "Plausibility
  // checks": each rule with its reason) ---------------------------------------
  // A damper c in series with k_s acts as the damper below its corner
  // frequency f_c = k_s / (2 pi c) and as the spring above it: its effective
  // damping is c / (1 + (f / f_c)^2). The modes that matter for stability
  // (body modes to hunting) lie in [series_damper_band_min_hz,
  // series_damper_band_max_hz]. f_c below the band's low end by the factor
  // below (10: the damper keeps < 1 % of c in the band) is a damper that does
  // nothing: k_s in MN/m given as N/m. f_c above the high end by the factor
  // above (100) is a series spring that is rigid for every modelled motion
  // (k_s in N/mm given as N/m, or a stiffness meant elsewhere); it adds only
  // a time constant c / k_s far shorter than any mode.
  double series_damper_band_min_hz = 0.5, series_damper_band_max_hz = 20.0;
  double series_damper_corner_factor_below = 10.0;
  double series_damper_corner_factor_above = 100.0;
  // Cant deficiency I = D V^2 |kappa| / g - cant_outer (and excess E = -I),
  // D = track.rail_contact_distance_m: EN 13803-1's maximum limits for plain
  // line, conventional (non-tilting) passenger vehicles: I 150 mm, E 110 mm.
  // Tilting trains run at up to 300 mm deficiency: raise the limit for them.
  double cant_deficiency_max_m = 0.150;
  double cant_excess_max_m = 0.110;
  // A cant below this (m) counts as none (no direction to check).
  double cant_direction_min_m = 0.001;
  // Larger over smaller wheel load of an axle in the steady state. The
  // quasi-static load transfer of a car body on its suspension is
  // dQ/Q0 = 2 h a_q / (g D) (h = 1.8 m, a_q = 0.98 m/s^2 at the 150 mm
  // deficiency limit, D = 1.5 m: 0.24, a ratio of 1.6); with the car body's
  // roll on soft air springs and the creep forces the coach of
  // cases/coach_curve.toml reaches 2.17 at 159 mm (R = 1000 m, 37 m/s).
  // 2.5 (dQ/Q0 = 0.43) leaves every admissible curving state below it;
  // EN 14363's wheel-unloading limit dQ/Q0 = 0.6 (ratio 4) includes a track
  // twist on top.
  double wheel_load_ratio_max = 2.5;
};

struct ModelCheckOptions {
  ModelCheckLimits limits;
  // Natural frequencies at rest: eigen-analysis of the model linearised about
  // its equilibrium at this small speed (the creep forces, ~ 1/V, then hold
  // the wheels on the rails laterally as friction holds a standing vehicle;
  // the suspension modes remain, with their damping). Off: one equilibrium
  // and linearisation less.
  bool natural_frequencies = true;
  double natural_frequency_speed_m_per_s = 0.5;
  // Listed band. Below: the kinematic (hunting) modes, whose frequency V / L
  // goes with the speed (wavelength L > 5 m: below 0.1 Hz at 0.5 m/s), not
  // a property of the vehicle at rest. Above: the wheel-rail contact modes.
  double natural_frequency_min_hz = 0.1;
  double natural_frequency_max_hz = 30.0;
};

struct ModelWarning {
  // Stable identifiers (tests and scripts match them):
  //   wheelset_placed_by_position, spring_ends_apart, static_deflection_large,
  //   body_mass_out_of_range, inertia_out_of_range, axle_load_out_of_range,
  //   longitudinal_unheld, contact_distance_mismatch, unit_looks_wrong,
  //   series_damper_corner_below_band, series_damper_corner_above_band,
  //   cant_on_inner_rail, cant_deficiency_beyond_limit, cant_excess_beyond_limit,
  //   wheel_loads_unbalanced, lateral_shift_beyond_flange_clearance
  std::string kind;
  std::string subject;  // body, element, contact or key it is about
  std::string message;  // what is wrong, the value, the expected range, the key
};

struct SpringDeflection {
  std::string element, type;
  std::string axis;          // "x", "y", "z", "roll", "line", "twist"
  std::string unit;          // "m" or "rad"
  double preload = 0.0;      // N or N m
  double stiffness = 0.0;    // N/m or N m/rad (at the nominal configuration)
  double deflection = 0.0;   // preload / stiffness, m or rad
};

struct BodyCheck {
  std::string name, role;  // role: wheelset, bogie frame, car body, rigid body
  double mass_kg = 0.0;
};

struct AxleLoad {
  std::string wheelset;
  double left_N = 0.0, right_N = 0.0;  // normal to the track plane
  double total_N = 0.0;
};

struct NaturalFrequency {
  double frequency_hz = 0.0;
  double damping_ratio = 0.0;
  std::string name;
};

struct ModelCheckReport {
  std::string scene;
  double speed_m_per_s = 0.0;  // of the equilibrium the axle loads are taken at
  double gravity_m_per_s2 = 9.81;
  std::vector<BodyCheck> bodies;
  double total_mass_kg = 0.0;
  std::vector<AxleLoad> axle_loads;
  double axle_load_sum_N = 0.0;
  std::vector<SpringDeflection> static_deflections;
  // Natural frequencies (empty when not asked for or when the analysis
  // failed: then natural_frequency_note says why).
  double natural_frequency_speed_m_per_s = 0.0;
  double natural_frequency_min_hz = 0.0, natural_frequency_max_hz = 0.0;  // listed band
  std::vector<NaturalFrequency> natural_frequencies;
  std::string natural_frequency_note;
  std::vector<ModelWarning> warnings;
  // Errors: what prevented a check (no equilibrium); the command fails.
  std::vector<std::string> errors;

  bool has_warning(const std::string& kind) const;
};

// All checks, with the equilibrium at `speed_m_per_s` (axle loads, the
// unheld-coordinate test on the linearisation about it).
ModelCheckReport check_model(const SceneSpec& spec, const Model& model, double speed_m_per_s,
                             const EquilibriumResult& equilibrium,
                             const ModelCheckOptions& options = {});

// The checks that need no equilibrium (masses, geometry, units, spring
// deflections), for a scene whose equilibrium could not be found; `error`
// (why not) is recorded in the report's errors.
ModelCheckReport check_model_without_equilibrium(const SceneSpec& spec, const Model& model,
                                                 const std::string& error,
                                                 const ModelCheckOptions& options = {});

// A steady state of a sweep over speeds (a grid point of the critical-speed
// search): the speed and the state at it.
struct SpeedSteadyState {
  double speed_m_per_s = 0.0;
  const Eigen::VectorXd* state = nullptr;  // null: no steady state (only the cant is checked)
};

// The checks whose verdict depends on the speed, at every speed of a sweep
// (issue 24: check_model evaluates them at one speed only): cant deficiency
// and excess (at every speed given), the wheel-load balance and a flangeless
// wheelset's steady shift beyond its flange clearance (at the speeds with a
// steady state). One warning per kind and subject: the speeds where the limit
// is exceeded (the first and last, and how many of the speeds checked) and
// the message at the worst speed of the range for that check (the highest for
// deficiency, load balance and shift, which grow with the speed in a curve;
// the lowest for excess). Same kinds and subjects as check_model's.
std::vector<ModelWarning> check_speed_range(const Model& model,
                                            const std::vector<SpeedSteadyState>& speeds,
                                            const ModelCheckLimits& limits = {});

// A scene from scratch, as `railstab check` runs it: the model built
// (build_model; its exceptions propagate: nothing to check without a model),
// the equilibrium at the scene's speed solved; when that fails, the checks
// without it, the failure an error of the report.
ModelCheckReport check_scene(const SceneSpec& spec, const ModelCheckOptions& options = {});

}  // namespace railstab
