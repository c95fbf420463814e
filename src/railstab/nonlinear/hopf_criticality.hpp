#pragma once
// Criticality of a Hopf bifurcation: the first Lyapunov coefficient l1 from
// exact second and third derivatives (nonlinear/multilinear_forms.hpp), and
// the small-amplitude limit cycle it predicts. docs/nonlinear.md has the
// derivation, the normalisation and the frames.
//
// For x' = f(x) with A = f'(x0) at the equilibrium x0 and a simple pair
// lambda = +-i w0 (Kuznetsov, Elements of Applied Bifurcation Theory, 3rd
// ed., 3.5 and 5.4):
//   A q = i w0 q,  A^T p = -i w0 p,  <q, q> = 1,  <p, q> = 1,
//   <a, b> = sum conj(a_k) b_k   (conjugate-linear in the first argument),
//   h11 = -A^{-1} B(q, qbar),     h20 = (2 i w0 I - A)^{-1} B(q, q),
//   c1  = 1/2 <p, C(q, q, qbar) + B(qbar, h20) + 2 B(q, h11)>,
//   l1  = Re(c1) / w0
//       = 1/(2 w0) Re[<p, C(q,q,qbar)> - 2 <p, B(q, A^{-1} B(q,qbar))>
//                      + <p, B(qbar, (2 i w0 I - A)^{-1} B(q,q))>].
// On the centre manifold x = x0 + w q + conj(w q) + O(|w|^2) the normal form
// is w' = lambda w + c1 w |w|^2 + O(|w|^4), so with Re(lambda) = alpha the
// cycle has |w|^2 = rho^2 = -alpha / Re(c1) (a cycle exists where alpha and
// l1 have opposite signs) and
//   x(t) = x0 + 2 rho Re(q e^{i w t}) + O(rho^2):  state k's amplitude 2 rho |q_k|.
// l1 depends on the normalisation of q (it scales with |q|^2), rho q does
// not: the predicted amplitudes are invariant under a change of coordinates.
//
// A singular A (neutral modes that the linearisation did not remove, e.g. a
// free longitudinal translation): A^{-1} B(q, qbar) is solved in the
// complement of A's kernel K (bordered system [A K; K^T 0] [h; s] = [r; 0],
// the part s of r along K is the secular drift of the neutral coordinates).
// That is right when the neutral directions are symmetries of f (f(x + K a)
// = f(x): then B(K, .) = 0 and the drift does not feed back); the result
// reports ||B(k, q)|| relative to ||B(q, qbar)|| so a caller sees whether
// they are (kernel_coupling ~ 1e-12 for a translation symmetry).
#include <railstab/model/model.hpp>
#include <railstab/nonlinear/multilinear_forms.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <Eigen/Dense>

#include <complex>
#include <string>
#include <vector>

namespace railstab {

// supercritical: l1 < 0, a stable cycle on the unstable side of the steady
// state; subcritical: l1 > 0, an unstable cycle on the stable side
// (degenerate: l1 = 0 within round-off, the cubic order does not decide).
enum class HopfKind { supercritical, subcritical, degenerate };
std::string hopf_kind_name(HopfKind kind);  // "supercritical", "subcritical", "degenerate"

struct HopfOptions {
  // Singular values of A below this times the largest count as A's kernel.
  double kernel_tolerance = 1e-11;
  // |l1| below this times |<p, C(q,q,qbar)>| / (2 w0) plus the other two
  // terms' magnitudes counts as zero (degenerate).
  double degenerate_tolerance = 1e-9;
  // Central difference of d Re(lambda)/dV for the model (hopf_criticality).
  double speed_step_m_per_s = 0.05;
};

// The coefficient for any system given its Jacobian and forms.
struct HopfCoefficient {
  std::complex<double> eigenvalue;  // lambda of A nearest the guess (Im > 0)
  double omega0 = 0.0;              // Im(lambda), rad/s
  double real_part = 0.0;           // Re(lambda): ~0 at the Hopf point
  Eigen::VectorXcd q, p;            // <q, q> = 1, <p, q> = 1; q's largest entry real > 0
  Eigen::VectorXd h11;              // -A^{-1} B(q, qbar) (in the kernel's complement)
  Eigen::VectorXcd h20;             // (2 i w0 I - A)^{-1} B(q, q)
  // The three terms of <p, 2 c1>: cubic, quadratic through h11 (2 <p, B(q,
  // h11)>), quadratic through h20 (<p, B(qbar, h20)>).
  std::complex<double> cubic_term, h11_term, h20_term;
  std::complex<double> c1;          // 1/2 (sum of the three)
  double first_lyapunov_coefficient = 0.0;  // Re(c1) / w0
  HopfKind kind = HopfKind::degenerate;
  // Neutral modes of A handled as above (0: A regular).
  int kernel_dimension = 0;
  double kernel_drift = 0.0;     // |s| / ||B(q, qbar)||
  double kernel_coupling = 0.0;  // max_k ||B(k, q)|| / ||B(q, qbar)||
  double eigen_residual = 0.0;   // max(||A q - lambda q||, ||A^T p - conj(lambda) p|| / ||p||) / ||A||
  int form_evaluations = 0;      // of f in Dual3
};

// lambda: the eigenvalue of A nearest eigenvalue_guess (Im > 0 taken).
// Throws std::invalid_argument for size mismatches and std::runtime_error
// when the nearest eigenvalue is real (no Hopf pair) or the kernel is
// defective (a zero eigenvalue with a Jordan block).
HopfCoefficient hopf_coefficient(const Eigen::MatrixXd& A, const MultilinearForms& forms,
                                 std::complex<double> eigenvalue_guess,
                                 const HopfOptions& options = {});

// rho^2 = -alpha / Re(c1) of the cycle at growth rate alpha (NaN when no
// cycle: alpha and l1 of the same sign, or l1 degenerate).
double cycle_radius_squared(const HopfCoefficient& hopf, double real_part);

// The railway model at (near) its linear critical speed.
struct HopfCriticality {
  double speed_m_per_s = 0.0;           // where A, B, C were evaluated
  // The Hopf point from the evaluation speed and the real part there:
  // V_c = V - Re(lambda) / (d Re(lambda)/dV).
  double critical_speed_m_per_s = 0.0;
  HopfCoefficient hopf;
  double first_lyapunov_coefficient = 0.0;  // = hopf.first_lyapunov_coefficient
  HopfKind kind = HopfKind::degenerate;
  // d Re(lambda)/dV (1/s per m/s): central difference of the eigenvalue's
  // first-order perturbation, p^H (A(V+h) - A(V-h)) q / (2 h), h =
  // HopfOptions::speed_step_m_per_s, the steady state solved at each speed.
  double real_part_speed_derivative = 0.0;
  // Side of V_c where the small cycle exists: +1 above (supercritical,
  // stable cycle, when Re(lambda) grows with V), -1 below (subcritical,
  // unstable cycle), 0 none (degenerate, or d Re(lambda)/dV = 0).
  int cycle_side = 0;
  // The linear model's kept states (names, indices into the full state):
  // amplitude_k(V) = amplitude_per_sqrt_speed(k) sqrt(|V - V_c|) on the
  // cycle's side, = 2 |q_k| / sqrt(w0 |l1| / |d Re(lambda)/dV|).
  std::vector<int> kept_states;
  std::vector<std::string> state_names;
  Eigen::VectorXd amplitude_per_sqrt_speed;
  double seconds = 0.0;                 // CPU time of the whole analysis
};

// At the steady state `equilibrium` (full state) at `speed_m_per_s`, for the
// eigenvalue nearest `eigenvalue_guess` (the hunting mode's). The steady
// states at V +- h are solved from `equilibrium`.
HopfCriticality hopf_criticality(const Model& model, double speed_m_per_s,
                                 const Eigen::VectorXd& equilibrium,
                                 std::complex<double> eigenvalue_guess,
                                 const HopfOptions& options = {}, double time_s = 0.0);

// The same at a critical-speed search's result: at_critical's speed, steady
// state, time and least stable mode. Throws std::invalid_argument when the
// search found no critical speed (critical_speed_found false) or has no
// least stable mode there.
HopfCriticality hopf_criticality(const Model& model, const CriticalSpeedResult& result,
                                 const HopfOptions& options = {});

// The amplitude of kept state `state_name` at speed V (0 on the side of V_c
// without a cycle). Throws std::invalid_argument for an unknown name.
double predicted_amplitude(const HopfCriticality& h, const std::string& state_name,
                           double speed_m_per_s);

}  // namespace railstab
