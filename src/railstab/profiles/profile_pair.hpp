#pragma once
// A wheel profile and a rail profile placed in the track by the named
// parameters (defaults: the Manchester Contact Benchmark set-up, new S1002 on
// UIC60 1:40, standard gauge).
//
// Placement, for the LEFT side (the right side is the mirror image y_T -> -y_T):
//   rail:  the rail profile is first inclined by rail_inclination_rad about its
//          origin, head towards the track centre:
//            (y, z) -> (y cos(b) - z sin(b), y sin(b) + z cos(b)),
//          (use 0 for a profile that is already canted, as the benchmark UIC60
//          file). Its highest point is the top of rail, z_T = 0. The gauge
//          point is the innermost point of the profile at
//          gauge_measuring_height_m below that top; it lies at y_T = gauge/2:
//            y_T = rail_offset_y_m + y_rail,  z_T = z_rail - rail_top_z_m,
//            rail_offset_y_m = track_gauge_m / 2 - gauge_point_y.
//   wheel: the wheelset's axle frame I (origin at the wheelset centre, y_I
//          along the axle to the left, z_I up when not rolled) holds the
//          left wheel profile with its origin (the tape circle at the nominal
//          rolling radius) at
//            y_I = wheel_offset_y_m = flange_back_distance_m / 2
//                                     + tape_circle_from_flange_back_m,
//            z_I = -nominal_rolling_radius_m,
//          so a wheel profile point (u, z_w) is at
//            (y_I, z_I) = (wheel_offset_y_m + u, -r0 + z_w).
//   Because the plane x = 0 of a non-yawed wheelset contains the axle, the
//   wheel's cross-section in that plane is exactly the profile curve moved
//   rigidly with the axle (roll included): see contact_geometry/.
#include <railstab/profiles/cubic_spline.hpp>
#include <railstab/profiles/profile.hpp>

#include <optional>

namespace railstab {

struct ProfilePairParameters {
  double track_gauge_m = 1.435;
  double gauge_measuring_height_m = 0.014;   // below the top of rail
  double flange_back_distance_m = 1.360;
  double nominal_rolling_radius_m = 0.460;
  double rail_inclination_rad = 0.0;         // 0: rail given canted (benchmark UIC60 file)
  double tape_circle_from_flange_back_m = 0.070;  // EN 13715 (S1002 and relatives)
  // The gauge point's y in the rail profile frame (after the inclination);
  // empty: searched at gauge_measuring_height_m below the top of rail.
  std::optional<double> rail_gauge_point_y_m;
};

struct ProfilePair {
  Profile wheel;                 // profile frame
  Profile rail;                  // profile frame, inclination applied
  CubicSpline wheel_z;           // z_w(u), wheel profile frame
  CubicSpline rail_z;            // z_r(y), rail profile frame (inclined)
  ProfilePairParameters parameters;
  double rail_top_y_m = 0, rail_top_z_m = 0;   // highest rail point
  double gauge_point_y_m = 0;                  // innermost rail point at the measuring height
  double rail_offset_y_m = 0;    // y_T = rail_offset_y_m + y_rail (left side)
  double wheel_offset_y_m = 0;   // y_I of the wheel profile origin (left side)
  // Lateral position of the wheel profile origin in the rail profile frame
  // with the wheelset centred (y = 0, roll = 0): wheel_offset - rail_offset.
  double nominal_wheel_lateral_m() const { return wheel_offset_y_m - rail_offset_y_m; }
};

// Checks the parameters (ProfileError naming the key and the expected range)
// and places the pair as described above.
ProfilePair make_profile_pair(Profile wheel, Profile rail, const ProfilePairParameters& p);

}  // namespace railstab
