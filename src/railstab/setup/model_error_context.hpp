#pragma once
// Errors raised deep in the model (a Hertz ellipse with a negative curvature,
// a non-finite Jacobian entry, a track position outside the track) know
// nothing of the scene: their messages name a quantity, not a body, a speed
// or a scene key. The analyses catch them at their boundaries (equilibrium
// solve, linearisation, eigen-analysis, start of a time integration) and
// rethrow one ModelError whose message says
//   <scene file>: <stage> of scene '<name>' at V = <speed> m/s, reference
//   point at arc length <s> m: <what failed, in words>. At this state:
//   <the body furthest from its nominal place>. Most likely responsible:
//   <scene keys>.
// A ModelError is a std::runtime_error, so a speed sweep treats it as "no
// result at this speed" (whatever the inner exception type was).
#include <railstab/model/model.hpp>

#include <Eigen/Dense>

#include <exception>
#include <stdexcept>
#include <string>
#include <string_view>

namespace railstab {

struct ModelError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct EvaluationPlace {
  std::string_view stage;  // "steady state", "linearisation", ...
  double speed_m_per_s = 0.0;
  double time_s = 0.0;
  // The state the model was evaluated at, when the caller knows it (an
  // EquilibriumError carries its own last iterate).
  const Eigen::VectorXd* state = nullptr;
  // The matrix an eigen-solver refused, when that was the failure.
  const Eigen::MatrixXd* matrix = nullptr;
  const std::vector<std::string>* matrix_state_names = nullptr;
  // False for a model that is not the user's track (the straight twin of
  // the preload solve): its arc length would mean nothing to the user.
  bool on_scene_track = true;
};

// The full message for `error` raised at `place` (see the file comment).
std::string describe_model_failure(const Model& model, const EvaluationPlace& place,
                                   const std::exception& error);

// An internal message with its function-name prefix ("hertz_shape: ",
// "eigen_dense: ") replaced by words ("Hertz contact ellipse: ").
std::string without_function_name(std::string_view message);

// Runs f(); any exception but a ModelError (already placed) or bad_alloc
// becomes a ModelError with the context of `place`.
template <class F>
auto with_model_context(const Model& model, const EvaluationPlace& place, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const ModelError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw ModelError(describe_model_failure(model, place, e));
  }
}

}  // namespace railstab
