#pragma once
// Exact derivatives of the linearised model with respect to one scene
// parameter p (a stiffness, a damping, a mass, ...), by forward-mode AD
// along p on top of the state AD (core/dual.hpp):
//
//   x*(p):   steady state, f_u(x*, p) = 0 on the equilibrium unknowns u;
//            dx*/dp = -J_u^+ df_u/dp   (implicit function theorem; J_u^+ the
//            minimum-norm solve the equilibrium solver uses)
//   A(p) = df/dx (x*(p), p),
//   dA/dp = d2f/dxdp + sum_k d2f/dx dx_k dx*_k/dp
//         = the derivative of the state Jacobian along (dx*/dp, 1),
//            evaluated exactly with the scalar Dual<AdScalar>.
// Preloads (ERRATA 13) depend on p as well (they are the elastic loads of
// the straight twin's sagged equilibrium): they are differentiated the same
// way, so dA/dp is the derivative of exactly what `railstab eigen` analyses.
//
// Parameters are named by their scene key: "bodies.<body>.mass_kg",
// "bodies.<body>.inertia_kg_m2[2]", "elements.<element>.<key>[i]" (vector
// keys) or "elements.<element>.<key>" (scalar keys). A mirrored element
// (mirror_lateral) is one scene entry: its key moves both halves.
// Contact parameters: "contacts.<contact>.<key>" for the cone angle or the
// conicity (by geometry) and the creep law's friction coefficient and
// reduction factors (by law).
//
// The speed V is a parameter too, kSpeedParameter ("scene.speed_m_per_s",
// the key --set takes): the model depends on V through the track frames'
// rates (velocities V t, angular velocities V kappa; accelerations ~ V^2),
// the wheelsets' prescribed spin V / r0 and the creepages' 1 / V, and the
// steady state (curving, the free spin rates) and the preloads' twin through
// these. ModelTpl::differentiated_in_speed seeds dV/dV = 1 in all of them,
// so dA/dV is as exact as dA/dp (no longer a central difference).
#include <railstab/linear/linearization.hpp>
#include <railstab/model/model.hpp>
#include <railstab/scene/scene_spec.hpp>

#include <complex>
#include <string>
#include <vector>

namespace railstab {

struct StateMatrixDerivative {
  std::string parameter;
  double parameter_value = 0.0;
  Eigen::VectorXd equilibrium;             // x*
  Eigen::VectorXd equilibrium_derivative;  // dx*/dp
  LinearModel linear;                      // A at x* (cyclic states removed)
  Eigen::MatrixXd A_derivative;            // dA/dp on linear.kept_states
};

inline constexpr const char* kSpeedParameter = "scene.speed_m_per_s";

// Throws std::invalid_argument naming the key when no parameter has it
// (the message lists the keys that exist).
StateMatrixDerivative state_matrix_derivative(const SceneSpec& scene, double speed_m_per_s,
                                              const std::string& parameter,
                                              const LinearizationOptions& options = {});

// The value of a parameter in a scene (for finite-difference checks and
// reports) and a copy of the scene with it set; same keys as above.
double parameter_value(const SceneSpec& scene, const std::string& parameter);
SceneSpec with_parameter(const SceneSpec& scene, const std::string& parameter, double value);

// Every differentiable parameter key of a scene.
std::vector<std::string> parameter_keys(const SceneSpec& scene);

// d(lambda)/dp = (w^H dA v) / (w^H v) for a simple eigenvalue lambda of A
// with right eigenvector v (w: its left eigenvector, computed here).
std::complex<double> eigenvalue_derivative(const Eigen::MatrixXd& A, const Eigen::MatrixXd& dA_dp,
                                           std::complex<double> lambda,
                                           const Eigen::VectorXcd& right_vector);

}  // namespace railstab
