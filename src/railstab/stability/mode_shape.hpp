#pragma once
// Mode shape of one eigenvector: the displacement of every free coordinate of
// every body as a complex amplitude (amplitude and phase), normalised, and
// how the mode's kinetic and potential energy divide among the coordinates.
//
// Displacement. The eigenvector v of A on the kept states holds positions q
// and rates u (u = lambda q for a mode of dx/dt = A x). The displacement of
// coordinate i is v_q(i) where the position is kept, and v_u(i) / lambda
// where a cyclic position was removed (a wheelset's spin angle).
// Normalisation: q_hat = q / q_ref with q_ref the largest lateral (y)
// displacement; when no lateral coordinate moves (below 1e-6 of the largest
// |q_i|: a bounce or pitch mode), the largest translation; when no
// translation moves either, the largest rotation. q_ref is then 1 with phase
// 0; translations are in m and rotations in rad per metre (or per radian) of
// the reference.
//
// Energy shares, on the motion x(t) = Re(q_hat e^{lambda t}) averaged over one
// period (the common factor e^{2 Re(lambda) t} and 1/4 cancel in a share):
//   kinetic   T_i = m_i |u_i|^2 / sum_j m_j |u_j|^2,
//             m_i the body's mass (x, y, z) or principal inertia (roll, pitch,
//             yaw): the kinetic energy about an equilibrium on level track,
//             where the body axes are the track axes to first order;
//   potential V_i = Re(conj(q_i) (K_s q)_i) / Re(q^H K_s q),
//             K_s = (K + K^T) / 2 and K = -M dA_el/dq the stiffness of the
//             force elements (suspension, its preloads) and gravity: the
//             acceleration Jacobian of everything except the wheel-rail
//             contact and the inertial terms (ForceSelection), times M. The
//             contact is left out on purpose: creep forces are circulatory and
//             dissipative and have no potential; this also leaves out the
//             gravitational stiffness that reaches the wheelsets through the
//             contact. Element internal states (the damper node of a
//             series spring-damper) are held fixed: its spring acts as a
//             spring to that node. V_i is coordinate i's part of the
//             quadratic form q^H K_s q: the V_i sum to 1 exactly; a V_i is
//             negative where a spring's other end moves further the same way
//             than coordinate i (k (|q_i|^2 - Re(conj(q_i) q_j)) < 0 for a
//             spring k between i and j). In a kinematic (hunting) mode the
//             suspension is barely deflected, so the shares are differences of
//             large terms and several are negative. For an undamped normal
//             mode K q = omega^2 M q, so V_i = T_i (a test oracle).
//             When the quadratic form vanishes (no suspension moves: a lone
//             wheelset on its contact), the potential shares are undefined.
#include <railstab/linear/linearization.hpp>
#include <railstab/model/model.hpp>

#include <Eigen/Dense>

#include <complex>
#include <string>
#include <vector>

namespace railstab {

struct CoordinateMotion {
  int body = 0;
  int coordinate = 0;                  // 0..5: x, y, z, roll, pitch, yaw
  std::complex<double> displacement;   // normalised: m or rad per unit of the reference
  double kinetic_share = 0.0;
  double potential_share = 0.0;        // meaningful only when ModeShape::potential_defined
};

struct ModeShape {
  int reference = -1;                  // index into coordinates of q_ref
  bool potential_defined = false;
  std::vector<CoordinateMotion> coordinates;  // every free coordinate, state order
};

// The stiffness K (n_coordinates x n_coordinates, free coordinates in state
// order) of the force elements and gravity at state x, as defined above.
Eigen::MatrixXd suspension_stiffness(const Model& model, double speed_m_per_s, double t_s,
                                     const Eigen::VectorXd& x);

// Mass (or principal inertia) of each free coordinate, state order.
Eigen::VectorXd coordinate_inertia(const Model& model);

// The shape of eigenvector `vector` (on lin.kept_states) with eigenvalue
// `lambda`. `stiffness`: suspension_stiffness at the linearisation point, or
// an empty matrix when only the displacements and kinetic shares are wanted
// (potential_defined is then false).
// Throws std::invalid_argument on mismatched sizes.
ModeShape mode_shape(const Model& model, const LinearModel& lin, const Eigen::MatrixXd& stiffness,
                     std::complex<double> lambda, const Eigen::VectorXcd& vector);

// What mode_shape needs of the model and the linear model besides the
// eigenpair, formed once for all the modes of one linearisation (describing
// every mode at every speed of a search: issue 11).
struct ModeShapeBasis {
  std::vector<int> kept_of;  // state index -> index in lin.kept_states, -1 if removed
  Eigen::VectorXd inertia;   // coordinate_inertia(model)
};
ModeShapeBasis mode_shape_basis(const Model& model, const LinearModel& lin);
// As mode_shape, with the basis formed by mode_shape_basis(model, lin).
ModeShape mode_shape(const Model& model, const LinearModel& lin, const ModeShapeBasis& basis,
                     const Eigen::MatrixXd& stiffness, std::complex<double> lambda,
                     const Eigen::VectorXcd& vector);

// "wheelset1 lateral": the body and coordinate of a CoordinateMotion.
std::string coordinate_label(const Model& model, const CoordinateMotion& c);

}  // namespace railstab
