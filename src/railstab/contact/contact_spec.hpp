#pragma once
// A wheel-rail contact as a scene describes it ([contacts.<name>]): the
// geometry, the normal and tangential force models, the creep law and the
// materials, in SI units. The scene (scene/scene_spec.hpp) holds one per
// named contact; the model holds it in its ModelContact (model_contact.hpp).
#include <railstab/contact/creep/creep_law.hpp>
#include <railstab/contact_geometry/profile_source.hpp>
#include <railstab/core/name_table.hpp>

#include <memory>
#include <string>
#include <string_view>

namespace railstab {

enum class ContactGeometryKind {
  knife_edge_cone,  // thesis 5.2-5.7: conical wheel on a wire rail
  linear_conicity,  // textbook: r = r0 +/- lambda y, normal along the track normal
  profiles,         // measured or design wheel and rail profiles (contact tables)
  table             // a precomputed contact table read from a file (contact_table_file.hpp)
};
// `geometry` in scene files and reports.
inline constexpr NameTable<ContactGeometryKind, 4> kContactGeometryNames = {{
    {"knife_edge_cone", ContactGeometryKind::knife_edge_cone},
    {"linear_conicity", ContactGeometryKind::linear_conicity},
    {"profiles", ContactGeometryKind::profiles},
    {"table", ContactGeometryKind::table}}};
constexpr std::string_view contact_geometry_name(ContactGeometryKind kind) {
  return name_in(kContactGeometryNames, kind);
}
// The geometries evaluated through a contact table (ProfileContactGeometry:
// built from profiles, or read from a file); the same model code, branch for
// branch, serves both.
constexpr bool uses_contact_table(ContactGeometryKind kind) {
  return kind == ContactGeometryKind::profiles || kind == ContactGeometryKind::table;
}

// geometry = "table": the file's format (`contact_table_format`).
enum class ContactTableFormat {
  railstab,  // written by `railstab contact-geometry` (<stem>_contact_table.csv)
  rsgeo      // DYTSI's RSGEO rigid-contact table over the wheelset's lateral shift
};
inline constexpr NameTable<ContactTableFormat, 2> kContactTableFormatNames = {{
    {"railstab", ContactTableFormat::railstab}, {"rsgeo", ContactTableFormat::rsgeo}}};

enum class NormalForceKind { hertz, prescribed };
// `normal` in scene files and reports.
inline constexpr NameTable<NormalForceKind, 2> kNormalForceNames = {{
    {"hertz", NormalForceKind::hertz}, {"prescribed", NormalForceKind::prescribed}}};
constexpr std::string_view normal_force_name(NormalForceKind kind) {
  return name_in(kNormalForceNames, kind);
}

enum class TangentialForceKind {
  kalker_hertz,  // Kalker linear, coefficients from the Hertz ellipse and table B.1
  constant,      // given f11, f22, f23, f33
  none
};
// `tangential` in scene files.
inline constexpr NameTable<TangentialForceKind, 3> kTangentialForceNames = {{
    {"kalker_hertz", TangentialForceKind::kalker_hertz},
    {"constant", TangentialForceKind::constant},
    {"none", TangentialForceKind::none}}};

// geometry = "profiles" (or "table"): the placed pair and its contact table,
// built (or read) once by the set-up step (setup/contact_tables.hpp,
// contact_geometry/profile_contact_geometry.hpp) and shared, immutable, by
// every model built from the scene.
struct ProfileContactGeometry;

// Default contact damping of a scene's Hertz contact: the vertical damping of
// one rail pad, 7.5e4 N s/m (Zhai, Wang & Lin, "Modelling and experiment of
// railway ballast vibrations", J. Sound Vib. 270 (2004) 673-683, track
// parameters). The track is rigid in this model, so the damper under each
// wheel stands for the dissipation of the rail support beneath it; on the
// thesis vehicle it damps the ~160 Hz wheelset contact modes to a damping
// ratio of ~0.05 (docs/model.md, section 13).
inline constexpr double kDefaultNormalDamping_N_s_per_m = 7.5e4;

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
  // A scene's default is kDefaultNormalDamping_N_s_per_m for Hertz contact
  // (the thesis has none: its cases say 0, and their wheel-rail vertical
  // modes are then damped only through the creep forces and can go unstable
  // in curves). Lift-off events are then located where the (unclipped)
  // normal force crosses zero, which can be before the penetration does.
  // Hertz normal force only.
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
  // until the set-up step has built (geometry = table: read) it, and for the
  // flangeless geometries.
  ProfileSourceSpec profile_source;
  // geometry = table: the file (resolved against the scene's folder) and its
  // format; an RSGEO table is resampled on profile_source.table's grid.
  std::string contact_table_path;
  ContactTableFormat contact_table_format = ContactTableFormat::railstab;
  std::shared_ptr<const ProfileContactGeometry> profile_geometry;
};

}  // namespace railstab
