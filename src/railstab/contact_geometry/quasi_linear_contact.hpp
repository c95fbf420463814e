#pragma once
// Quasi-linear (describing-function) contact of a profile pair at a wheelset
// amplitude A: the contact whose geometry is the harmonic linearisation
// (harmonic_linearisation.hpp) of the pair's rigid-contact characteristic
// functions for the lateral motion y = y_c + A sin(theta) of the wheelset
// about its steady shift y_c. docs/quasi_linear.md has the derivation.
//
// The characteristic functions F(y) of the left wheel (rigid contact,
// rigid_contact.hpp: the roll and height at which both wheels touch; the
// primary contact point of the wheel) are sampled over the table's lateral
// range with step `sample_step_m` and interpolated linearly (they jump where
// the contact jumps, e.g. S1002/UIC60 at y ~ 0.2 mm and onto the flange):
//   q(y)      the wheel's lateral displacement in its rail frame, as the
//             contact table has it (q = y + r0 sin(phi) + ...: with roll)
//   theta(y)  the table's roll variable (phi for the left wheel)
//   gap0(y) = -vertical pose at contact (the table's gap at vertical pose 0)
//   wheel_u, rail_y, contact angle, rolling radius, Hertz A and B.
// For each F its gain N_F(A) (the first harmonic over A) about y_c.
//
// The equivalent contact is one contact point per wheel whose table
// quantities are planes in the table variables (q, theta) about the rigid
// contact's pose at y_c (ContactTable::plane_table):
//   f(q, theta) = F(y_c) + a_f (q - q(y_c)) + b_f (theta - theta(y_c)),
//   b_f = df/dtheta of the profile pair's own table at that pose (its
//         loaded slot; local: the table's roll dependence at a fixed
//         lateral displacement, which a wheelset's roll of ~1 mrad per mm
//         hardly moves),
//   a_f = (N_F - b_f N_theta) / N_q,
// so that along the rigid motion (q, theta) = (q(y), theta(y)) the
// equivalent's slope df/dy = a_f q'(y) + b_f theta'(y) is N_F when q and
// theta move with their gains N_q, N_theta. The roll of the equivalent
// wheelset in stiff contact then also has the gain N_theta (its gap plane
// makes both wheels touch along that line: docs/quasi_linear.md).
// The right wheel is the left's mirror image: its table is the left wheel's
// equivalent about -y_c (one table for both when y_c = 0).
//
// The values at the centre are the rigid contact's at y_c, not the elastic
// table's loaded slots: as A -> 0 the quasi-linear contact tends to a
// one-point contact with the rigid contact's local slopes (where they exist),
// close to but not the profile table's linearisation (which has several
// slots, each loaded elastically).
#include <railstab/contact_geometry/contact_tables.hpp>
#include <railstab/contact_geometry/profile_contact_geometry.hpp>

#include <array>
#include <memory>
#include <vector>

namespace railstab {

// The sampled functions of the rigid contact, in this order.
enum class RigidFunction : int {
  lateral_q_m = 0,
  roll_theta_rad,
  gap0_m,
  wheel_u_m,
  rail_y_m,
  contact_angle_rad,
  rolling_radius_m,
  A_per_m,
  B_per_m,
  count
};
inline constexpr int kRigidFunctions = int(RigidFunction::count);

// What the equivalent at one amplitude is made of (for reports and tests).
struct QuasiLinearGains {
  double centre_m = 0, amplitude_m = 0;
  std::array<double, kRigidFunctions> at_centre{};  // F(y_c)
  std::array<double, kRigidFunctions> gain{};       // N_F(A), per metre of y
  std::array<double, kRigidFunctions> bias{};       // mean of F over the cycle
  // Harmonic equivalent conicity N_{delta r}(A) / 2, delta r(y) = r_L(y) -
  // r_R(y) = r_L(y) - r_L(-y): (N_r(about y_c) + N_r(about -y_c)) / 2.
  double equivalent_conicity = 0;
};

class QuasiLinearContact {
 public:
  // Samples the rigid-contact functions over the table's lateral range
  // (minus 1 mm, where a wheel still has its rail) every sample_step_m.
  // Throws ContactGeometryError where the rigid contact has no solution.
  // The geometry is shared: the builder keeps it alive.
  explicit QuasiLinearContact(std::shared_ptr<const ProfileContactGeometry> geometry,
                              double sample_step_m = kDefaultSampleStep_m);
  static constexpr double kDefaultSampleStep_m = 2e-5;

  // The largest |y_c| + A the samples cover.
  double half_range_m() const { return y_m_.back(); }
  // Flange contact: the smallest shift at which the left wheel's contact
  // angle exceeds 45 degrees (characteristic_functions.hpp), 0 if none.
  double flange_contact_shift_m() const { return flange_contact_m_; }

  // F(y) by linear interpolation of the samples.
  double function(RigidFunction f, double y_m) const;
  // Gains about y_c for amplitude A (breakpoints at the samples: exact for
  // the interpolated function). Throws std::invalid_argument naming the
  // amplitude unless 0 < A and |y_c| + A <= half_range_m().
  QuasiLinearGains gains(double centre_m, double amplitude_m) const;
  // The left wheel's equivalent table about y_c for amplitude A (the right
  // wheel's: equivalent_table(-y_c, A)).
  ContactTable equivalent_table(double centre_m, double amplitude_m) const;
  // The quasi-linear geometry of a wheelset about y_c: the pair, the left
  // table about y_c and, where y_c != 0, the right table about -y_c.
  std::shared_ptr<const ProfileContactGeometry> equivalent_geometry(double centre_m,
                                                                    double amplitude_m) const;

 private:
  std::shared_ptr<const ProfileContactGeometry> geometry_;
  std::vector<double> y_m_;
  std::array<std::vector<double>, kRigidFunctions> f_;
  double flange_contact_m_ = 0;
};

}  // namespace railstab
