#pragma once
// The scene as data: what a scene file says, in SI units, before any model is
// built. The scene reader (scene_reading/load_scene.hpp) fills it and checks
// it; the set-up step (setup/) builds the profile contact tables; the model
// (model/model.hpp) is assembled from it. Nothing here computes physics.
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
#include <railstab/contact/creep/creep_law_concept.hpp>
#include <railstab/contact/creep/linear_kalker_creep.hpp>
#include <railstab/contact/creep/polach_creep.hpp>
#include <railstab/contact/creep/shen_hedrick_elkins_creep.hpp>
#include <railstab/core/coordinates.hpp>
#include <railstab/contact_geometry/contact_table_options.hpp>
#include <railstab/elements/element.hpp>
#include <railstab/profiles/profile_pair.hpp>
#include <railstab/scene/track_spec.hpp>
#include <railstab/scene/integrator_kind.hpp>

#include <Eigen/Dense>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace railstab {

// --- Wheel-rail contact ---------------------------------------------------------
enum class ContactGeometryKind {
  knife_edge_cone,  // thesis 5.2-5.7: conical wheel on a wire rail
  linear_conicity,  // textbook: r = r0 +/- lambda y, normal along the track normal
  profiles          // measured or design wheel and rail profiles (contact tables)
};

// geometry = "profiles": where the profiles come from and how they are
// placed (profiles/profile_pair.hpp; the pair's nominal rolling radius is the
// contact's nominal_rolling_radius_m), and the grid of the contact table
// (contact_geometry/contact_tables.hpp).
struct ProfileSourceSpec {
  std::string wheel_profile_path, rail_profile_path;  // resolved against the scene's folder
  LengthUnit wheel_unit = LengthUnit::millimetre, rail_unit = LengthUnit::millimetre;
  ProfilePairParameters placement;
  ContactTableOptions table;
};
// The placed pair and its contact table, built once by the set-up step
// (setup/contact_tables.hpp, contact_geometry/profile_contact_geometry.hpp)
// and shared, immutable, by every model built from the scene.
struct ProfileContactGeometry;
enum class NormalForceKind { hertz, prescribed };
enum class TangentialForceKind {
  kalker_hertz,  // Kalker linear, coefficients from the Hertz ellipse and table B.1
  constant,      // given f11, f22, f23, f33
  none
};

// The creep law: the tangential forces from the creepages and Kalker's
// linear coefficients (contact/creep/): one type per law, one variant.
template <class S>
using CreepLawTpl = std::variant<LinearKalkerCreep<S>, ShenHedrickElkinsCreep<S>, PolachCreep<S>>;
using CreepLawSpec = CreepLawTpl<double>;
static_assert(assert_creep_laws(std::type_identity<CreepLawTpl<double>>{}));

struct ContactSpec {
  std::string name;
  ContactGeometryKind geometry = ContactGeometryKind::knife_edge_cone;
  double cone_angle_rad = 0.1;            // knife_edge_cone: gamma
  double conicity = 0.1;                  // linear_conicity: lambda
  double half_contact_distance_m = 0.75;  // e0
  double nominal_rolling_radius_m = 0.45; // r0
  NormalForceKind normal = NormalForceKind::hertz;
  double prescribed_wheel_load_N = 0.0;   // normal = prescribed
  double rail_head_transverse_radius_m = 0.30;  // ERRATA 8
  // Viscous damping of the Hertz contact along its normal (rail pad, track
  // bed, material damping lumped), in parallel with the Hertz spring while
  // the wheel is in contact; the normal force never pulls (clipped at 0).
  // The thesis has none (default 0): its wheel-rail vertical modes are then
  // damped only through the creep forces and can go unstable in curves.
  // Lift-off events are then located where the (unclipped) normal force
  // crosses zero, which can be before the penetration does. Hertz normal
  // force only.
  double normal_damping_N_s_per_m = 0.0;
  // Validity limit of the flangeless contact models: a wheelset whose lateral
  // shift exceeds it would be in flange contact, which is not modelled, so the
  // time integration stops there (choice: a typical nominal flange clearance).
  double flange_clearance_m = 0.0075;
  double wheel_young_modulus_Pa = 2.1e11;
  double wheel_poisson_ratio = 0.25;
  double rail_young_modulus_Pa = 2.1e11;
  double rail_poisson_ratio = 0.25;
  TangentialForceKind tangential = TangentialForceKind::kalker_hertz;
  bool spin_creepage = true;
  double f11_N = 0.0;     // constant: longitudinal
  double f22_N = 0.0;     // constant: lateral
  double f23_N_m = 0.0;   // constant: lateral/spin
  double f33_N_m2 = 0.0;  // constant: spin
  // `creep_law`: linear_kalker (default, the thesis: no saturation),
  // shen_hedrick_elkins or polach (saturate at mu N; keys in
  // scene_reading/creep_law_reader.hpp).
  CreepLawSpec creep_law = LinearKalkerCreep<double>{};
  // geometry = profiles: the files and options as read; the geometry is null
  // until the set-up step has built it (and for other geometries).
  ProfileSourceSpec profile_source;
  std::shared_ptr<const ProfileContactGeometry> profile_geometry;
};

// --- Bodies ------------------------------------------------------------------------
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
struct SimulationSpec {
  double t_end_s = 10.0;
  double output_interval_s = 0.01;
  IntegratorKind integrator = IntegratorKind::arkode_dirk;
  int integrator_order = 0;  // 0: the method's default (see IntegrationOptions::order)
  double relative_tolerance = 1e-3;
  double absolute_tolerance = 1e-6;  // m, rad, m/s, rad/s alike
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
};

}  // namespace railstab
