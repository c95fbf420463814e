#pragma once
// Quasi-linear critical speed by amplitude (issue 22 item 4): the critical
// speed of the model whose profile contacts are replaced by their harmonic
// (describing-function) linearisation at a wheelset lateral amplitude A
// (contact_geometry/quasi_linear_contact.hpp), by the unchanged critical-
// speed search (find_critical_speed). The curve V_c(A) over A is the
// classical engineering estimate of the branch of hunting cycles: a cycle of
// amplitude A is expected near the speed where the quasi-linear model at A
// is neutrally stable. docs/quasi_linear.md.
//
// The centre of each wheelset's motion is its steady lateral shift y_c in
// the steady state given (on tangent track 0 by symmetry at every speed; in
// a curve, the steady state at the guess speed: the tables are built about
// that state once, and the search at other speeds keeps them).
//
// Contacts without profiles (knife_edge_cone, linear_conicity) have contact
// functions linear in the wheelset's shift: their harmonic linearisation is
// the function itself (N(A) = the slope at every A), so they are left as
// they are, and a model without profile contacts is its own quasi-linear
// model (the result equals the plain critical speed).
#include <railstab/contact_geometry/quasi_linear_contact.hpp>
#include <railstab/model/model.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace railstab {

// One wheelset's quasi-linear contact at an amplitude.
struct QuasiLinearWheelset {
  std::string body;
  double centre_m = 0;              // y_c
  double equivalent_conicity = 0;   // N_{delta r}(A) / 2
  double rolling_radius_gain = 0;   // N_{r_L}(A) about y_c (m per m)
  double contact_angle_gain_per_m = 0;  // N_{gamma_L}(A)
  double roll_gain_per_m = 0;       // N_theta(A)
};

struct QuasiLinearModel {
  Model model;
  double amplitude_m = 0;
  bool has_profile_contact = false;  // false: `model` is the model given
  std::vector<QuasiLinearWheelset> wheelsets;  // profile-contact wheelsets only
};

// Builds quasi-linear models of one model about one steady state: the rigid
// characteristic functions of each profile contact are sampled once (~0.1 s
// per contact) and serve every amplitude.
class QuasiLinearModelBuilder {
 public:
  QuasiLinearModelBuilder(const Model& model, const Eigen::VectorXd& steady_state);
  bool has_profile_contact() const { return !contacts_.empty(); }
  // The largest amplitude every wheelset's contact covers (the table's
  // lateral range less 1 mm, less |y_c|); 0 without profile contact.
  double max_amplitude_m() const;
  // The smallest flange-contact shift of the profile contacts, less the
  // largest |y_c| (0 if no contact has a flange).
  double flange_contact_amplitude_m() const;
  // Throws std::invalid_argument naming the amplitude (mm) and the range
  // unless 0 < A <= max_amplitude_m() (any A > 0 without profile contact).
  QuasiLinearModel at(double amplitude_m) const;

 private:
  const Model& model_;
  struct ProfileContactOf {
    int contact = -1;  // index into Model::contacts
    std::shared_ptr<QuasiLinearContact> builder;
  };
  std::vector<ProfileContactOf> contacts_;
  std::vector<std::pair<int, double>> wheelset_centres_;  // (body, y_c)
};

// The critical speed of the quasi-linear model at one amplitude.
struct QuasiLinearCriticalSpeed {
  double amplitude_m = 0;
  std::vector<QuasiLinearWheelset> wheelsets;
  bool has_profile_contact = false;
  CriticalSpeedResult result;
};

// `steady_state` at `speed_m_per_s`: the model's steady state (as for
// find_critical_speed); the quasi-linear models' searches start from it.
QuasiLinearCriticalSpeed find_quasi_linear_critical_speed(const Model& model,
                                                          const Eigen::VectorXd& steady_state,
                                                          double speed_m_per_s, double amplitude_m,
                                                          const CriticalSpeedOptions& options);

// The curve V_c(A): one point per amplitude, each a critical-speed search
// (without mode shapes and the damping criterion, for speed).
struct QuasiLinearCurvePoint {
  double amplitude_m = 0;
  double equivalent_conicity = 0;  // of the first profile wheelset (0: none)
  bool critical_speed_found = false;
  bool stable_in_range = false, unstable_at_start = false;
  double critical_speed_m_per_s = 0;
  double frequency_Hz = 0;         // of the crossing mode at V_c
  std::string mode;                // its name
  std::string note;                // why no speed: the partial reason or the verdict sentence; else empty
};
struct QuasiLinearCurve {
  std::vector<QuasiLinearCurvePoint> points;
  bool has_profile_contact = false;
  double flange_contact_amplitude_m = 0;
  double cpu_seconds = 0;
};
// amplitudes in metres, each in (0, builder.max_amplitude_m()]; the builder
// of the model and steady state the searches start from; progress(i, n, A)
// after each point (may be empty).
QuasiLinearCurve quasi_linear_critical_speed_curve(
    const QuasiLinearModelBuilder& builder, const Eigen::VectorXd& steady_state,
    double speed_m_per_s, const std::vector<double>& amplitudes_m,
    const CriticalSpeedOptions& options, const std::function<void(int, int, double)>& progress = {});

}  // namespace railstab
