#pragma once
// Modes of a linearised model: frequency, damping ratio, the mode shape
// (stability/mode_shape.hpp), a name from the shape (stability/mode_names.hpp),
// and the neutral / rigid-body classification that keeps them out of the
// stability decision.
#include <railstab/eigen/eigen_analysis.hpp>
#include <railstab/linear/linearization.hpp>
#include <railstab/model/model.hpp>
#include <railstab/stability/mode_shape.hpp>

#include <complex>
#include <string>
#include <vector>

namespace railstab {

struct Participation {
  std::string body;
  int coordinate;  // 0..5
  double share;    // of the mode's kinetic energy, 0..1
};

struct ModeReport {
  std::complex<double> eigenvalue;
  double frequency_hz = 0.0;
  double damping_ratio = 0.0;
  double residual = 0.0;  // eigenpair residual (scale free)
  bool neutral = false;   // |lambda| at round-off level: rigid-body / cyclic
  // Unique within the analysis, e.g. "bogie hunting, bogies in phase",
  // "car body lower sway (2)"; the conjugate partner (Im < 0) has its
  // mate's name.
  std::string name;
  std::string shape_name;  // from the shape alone, before making names unique
  std::string dominant_body;  // the body with the most kinetic energy ("" for none)
  // The shape itself is not kept (26 KB per mode of a 16-car train, at every
  // speed of a sweep): describe_mode_shapes gives it again, reports form it
  // with the potential shares (stability/point_mode_shapes.hpp full_mode_shapes).
  std::vector<Participation> participation;  // largest first (at most 6)
  // Share of the kinetic energy in the lateral plane (lateral, roll and yaw
  // of every body): near 1 for hunting and sway, near 0 for bounce, pitch
  // and longitudinal modes.
  double lateral_share = 0.0;
  Eigen::VectorXcd vector;  // eigenvector on the linear model's kept states
};

// A tracked mode's name is its track's (the shape it has at most speeds of
// the sweep, stability/speed_analysis.hpp name_tracked_modes); a mode that
// changes shape along the speed range (the coach in cases/
// coach_s1002_curve.toml: its car-body upper sway becomes a wheelset spin
// mode where it crosses) is, at one speed, what its shape_name says. This is
// that shape name where it differs from the track's name (which does not
// start with it), else "".
std::string shape_here_if_different(const ModeReport& m);
// m.name, followed by "(its shape here: <shape>)" where they differ.
std::string mode_label_here(const ModeReport& m);

// Kinetic-energy participation: share_k ~ M_k |v_rate_k|^2 with M_k the mass
// (translations) or the principal inertia (rotations) of that coordinate.
// Names from the shapes, unique among `pairs` (suffixes in ascending damping
// ratio: the least damped of a name keeps it plain).
// speed_m_per_s: the linearisation's speed (mode names: hunting needs the
// kinematic relation psi / y = i omega / V, stability/mode_names.hpp).
std::vector<ModeReport> describe_modes(const Model& model, const LinearModel& lin,
                                       const std::vector<EigenPair>& pairs, double speed_m_per_s);

// The shapes describe_modes names the modes from (displacements and kinetic
// shares, no potential shares), one per pair; a complex pair's partner (the
// exact conjugate of the pair before, as eigen_dense returns it) gets its
// mate's shape with the displacements conjugated.
std::vector<ModeShape> describe_mode_shapes(const Model& model, const LinearModel& lin,
                                            const std::vector<EigenPair>& pairs);

// Index of the least stable non-neutral mode at or below max_frequency_hz
// (largest real part; among equal real parts the oscillatory one), or -1.
int least_stable_mode(const std::vector<ModeReport>& modes, double max_frequency_hz);

// As least_stable_mode, among the oscillatory modes with lateral_share of at
// least min_lateral_share (the candidates for hunting), or -1.
int least_stable_lateral_mode(const std::vector<ModeReport>& modes, double max_frequency_hz,
                              double min_lateral_share = 0.5);

// Index of the least damped non-neutral lateral-plane mode at or below
// max_frequency_hz: smallest damping ratio (a real root has ratio 1 when it
// decays, -1 when it grows, so a decaying overdamped root never outranks an
// oscillatory mode); among equal ratios the larger real part; -1 if none.
// Lateral-plane: lateral_share >= min_lateral_share (hunting, sway, yaw; a
// lightly damped longitudinal or bounce mode is not a lateral-stability
// concern and would otherwise fill the tables: the thesis vehicle's bogie
// longitudinal modes, 1.06 Hz, ratio 0.005, at every speed). Unstable modes
// of any kind still decide stability through least_stable_mode. Conjugate
// partners with Im < 0 are skipped.
int least_damped_mode(const std::vector<ModeReport>& modes, double max_frequency_hz,
                      double min_lateral_share = 0.5);

// For each mode with Im < 0, the index of its conjugate partner (Im > 0,
// conj(lambda) within 1e-8 max(1, |lambda|)); -1 for the others and for a
// mode whose partner the solver did not return (ARPACK's subset).
std::vector<int> conjugate_partners(const std::vector<ModeReport>& modes);

std::string coordinate_word(int coordinate);

}  // namespace railstab
