#include <railstab/sensitivity/parameter_derivative.hpp>

#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/linear/jacobian.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/setup/build_model.hpp>

#include <railstab/linalg/dense_decompositions.hpp>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace railstab {

namespace {

std::string indexed(const std::string& key, int i) {
  return i < 0 ? key : key + "[" + std::to_string(i) + "]";
}

// The scene name of an element: a mirrored pair "<name>_left"/"<name>_right"
// answers to "<name>" as well as to its own name.
bool element_answers_to(const std::string& element_name, const std::string& name) {
  if (element_name == name) return true;
  for (const char* side : {"_left", "_right"})
    if (element_name == name + side) return true;
  return false;
}

// f(key, value&) for every parameter key that `element_name` answers to.
template <class S, class F> void visit_elements(std::vector<ElementTpl<S>>& elements, F&& f) {
  for (ElementTpl<S>& element : elements)
    std::visit(
        [&](auto& e) {
          e.for_each_parameter([&](const char* field, int i, S& value) {
            const std::string own = "elements." + e.ends.name + "." + indexed(field, i);
            f(own, e.ends.name, std::string(field), i, value);
          });
        },
        element);
}

// Does `key` ("elements.<name>.<field>[i]") name this element parameter?
bool key_matches(const std::string& key, const std::string& element_name, const std::string& field,
                 int i) {
  const std::string tail = "." + indexed(field, i);
  if (key.rfind("elements.", 0) != 0 || key.size() <= tail.size() + 9) return false;
  if (key.compare(key.size() - tail.size(), tail.size(), tail) != 0) return false;
  const std::string name = key.substr(9, key.size() - 9 - tail.size());
  return element_answers_to(element_name, name);
}

template <class S, class F> int visit_parameter(ModelTpl<S>& model, const std::string& key, F&& f) {
  int matched = 0;
  for (BodyTpl<S>& b : model.bodies)
    b.for_each_parameter([&](const char* field, int i, S& value) {
      if (key == "bodies." + b.name + "." + indexed(field, i)) f(value), ++matched;
    });
  visit_elements(model.elements, [&](const std::string&, const std::string& name,
                                     const std::string& field, int i, S& value) {
    if (key_matches(key, name, field, i)) f(value), ++matched;
  });
  for (ModelContactTpl<S>& c : model.contacts)
    c.for_each_parameter([&](const char* field, int i, S& value) {
      if (key == "contacts." + c.spec.name + "." + indexed(field, i)) f(value), ++matched;
    });
  return matched;
}

[[noreturn]] void unknown_parameter(const SceneSpec& scene, const std::string& key) {
  std::string known;
  for (const std::string& k : parameter_keys(scene)) known += (known.empty() ? "" : ", ") + k;
  throw std::invalid_argument("parameter '" + key + "': no such differentiable scene parameter in '" +
                              scene.name + "' (expected one of: " + known + ")");
}

ModelTpl<ParamDual> seeded(const Model& model, const SceneSpec& scene, const std::string& key) {
  ModelTpl<ParamDual> m = model.cast<ParamDual>();
  if (key == kSpeedParameter) {
    m.differentiated_in_speed = true;
    return m;
  }
  if (visit_parameter(m, key, [](ParamDual& p) { p.d = 1.0; }) == 0) unknown_parameter(scene, key);
  return m;
}

VecX<ParamDual> dual_state(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) {
  VecX<ParamDual> xd(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) xd(i) = ParamDual(x(i), dx(i));
  return xd;
}

// dx*/dp = -J_u^+ df_u/dp at the equilibrium x of `model` (values) and
// `model_d` (the same model with the parameter's derivative seeded).
Eigen::VectorXd equilibrium_derivative(const Model& model, const ModelTpl<ParamDual>& model_d,
                                       double V, double t, const Eigen::VectorXd& x) {
  const int n = model.n_coordinates;
  const std::vector<int> unknowns = equilibrium_unknowns(model);
  const int m = int(unknowns.size());
  const Eigen::MatrixXd jac = rhs_jacobian_ad(model, V, t, x);
  Eigen::MatrixXd J(m, m);
  for (int j = 0; j < m; ++j) J.col(j) = jac.block(n, unknowns[j], m, 1);
  Workspace<ParamDual> ws(model_d);
  VecX<ParamDual> f;
  evaluate_rhs<ParamDual>(model_d, ws, t, V, dual_state(x, Eigen::VectorXd::Zero(x.size())), f);
  Eigen::VectorXd r_p(m);
  for (int i = 0; i < m; ++i) r_p(i) = f(n + i).d;
  const Eigen::VectorXd du = J.completeOrthogonalDecomposition().solve(-r_p);
  Eigen::VectorXd dx = Eigen::VectorXd::Zero(x.size());
  for (int j = 0; j < m; ++j) dx(unknowns[j]) = du(j);
  return dx;
}

// The preloads of ERRATA 13 with their derivatives along the parameter.
std::vector<Vec3<ParamDual>> preload_derivatives(const SceneSpec& scene, const std::string& key) {
  const GravityTwin gravity = gravity_twin(scene);  // as build_model
  const Model twin = assemble_model(gravity.spec);
  const double V = scene.speed_m_per_s;
  const Eigen::VectorXd xs = solve_equilibrium(twin, V, lowered_nominal_state(twin, V)).state;
  // A key may name only elements left out of the sag: then nothing to seed.
  ModelTpl<ParamDual> twin_d = twin.cast<ParamDual>();
  visit_parameter(twin_d, key, [](ParamDual& p) { p.d = 1.0; });
  twin_d.differentiated_in_speed = key == kSpeedParameter;  // the twin runs at the scene's speed
  const Eigen::VectorXd dxs = equilibrium_derivative(twin, twin_d, V, 0.0, xs);
  Workspace<ParamDual> ws(twin_d);
  compute_all_body_motions<ParamDual>(twin_d, ws, 0.0, V, dual_state(xs, dxs));
  std::vector<Vec3<ParamDual>> preloads(scene.elements.size(), Vec3<ParamDual>::Zero());
  for (size_t j = 0; j < twin_d.elements.size(); ++j)
    preloads[gravity.kept[j]] = std::visit(
        [&](const auto& e) {
          const auto [a1, a2] = element_attachments(e.ends, ws);
          return e.template elastic_load<ParamDual>(a1, a2);
        },
        twin_d.elements[j]);
  return preloads;
}

}  // namespace

std::vector<std::string> parameter_keys(const SceneSpec& scene) {
  std::vector<std::string> keys;
  for (const BodySpec& b : scene.bodies) {
    keys.push_back("bodies." + b.name + ".mass_kg");
    for (int i = 0; i < 3; ++i) keys.push_back("bodies." + b.name + ".inertia_kg_m2[" + std::to_string(i) + "]");
  }
  std::vector<ElementSpec> elements = scene.elements;
  std::vector<std::string> names;
  for (const ElementSpec& e : elements) names.push_back(ends_of(e).name);
  visit_elements(elements, [&](const std::string&, const std::string& name,
                               const std::string& field, int i, double&) {
    // A mirrored pair is listed once, by its scene name.
    std::string shown = name;
    for (const std::string side : {"_left", "_right"})
      if (name.size() > side.size() && name.compare(name.size() - side.size(), side.size(), side) == 0) {
        const std::string base = name.substr(0, name.size() - side.size());
        const std::string other = base + (side == "_left" ? "_right" : "_left");
        if (std::find(names.begin(), names.end(), other) != names.end()) shown = base;
      }
    const std::string key = "elements." + shown + "." + indexed(field, i);
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
  });
  for (const ContactSpec& spec : scene.contacts) {
    ModelContact c = make_model_contact(spec);
    c.for_each_parameter([&](const char* field, int i, double&) {
      keys.push_back("contacts." + spec.name + "." + indexed(field, i));
    });
  }
  return keys;
}

double parameter_value(const SceneSpec& scene, const std::string& key) {
  if (key == kSpeedParameter) return scene.speed_m_per_s;
  const Model model = assemble_model(scene);
  double value = std::numeric_limits<double>::quiet_NaN();
  ModelTpl<double> copy = model;
  if (visit_parameter(copy, key, [&](double& p) { value = p; }) == 0) unknown_parameter(scene, key);
  return value;
}

SceneSpec with_parameter(const SceneSpec& scene, const std::string& key, double value) {
  SceneSpec out = scene;
  if (key == kSpeedParameter) {
    out.speed_m_per_s = value;
    return out;
  }
  int matched = 0;
  for (BodySpec& b : out.bodies) {
    if (key == "bodies." + b.name + ".mass_kg") b.mass_kg = value, ++matched;
    for (int i = 0; i < 3; ++i)
      if (key == "bodies." + b.name + ".inertia_kg_m2[" + std::to_string(i) + "]")
        b.inertia_kg_m2(i) = value, ++matched;
  }
  visit_elements(out.elements, [&](const std::string&, const std::string& name,
                                   const std::string& field, int i, double& p) {
    if (key_matches(key, name, field, i)) p = value, ++matched;
  });
  for (ContactSpec& c : out.contacts)
    visit_contact_parameters(c, c.cone_angle_rad, c.conicity, c.creep_law,
                             [&](const char* field, int i, double& p) {
                               if (key == "contacts." + c.name + "." + indexed(field, i))
                                 p = value, ++matched;
                             });
  if (matched == 0) unknown_parameter(scene, key);
  return out;
}

StateMatrixDerivative state_matrix_derivative(const SceneSpec& scene, double speed_m_per_s,
                                              const std::string& key,
                                              const LinearizationOptions& options) {
  SceneSpec spec = scene;
  spec.speed_m_per_s = speed_m_per_s;
  const double V = speed_m_per_s, t = options.time_s;
  StateMatrixDerivative out;
  out.parameter = key;
  out.parameter_value = parameter_value(spec, key);

  // Values: exactly what the analyses evaluate.
  const Model model = build_model(spec);
  EquilibriumOptions eq;
  eq.time_s = t;
  out.equilibrium = solve_equilibrium(model, V, lowered_nominal_state(model, V), eq).state;
  out.linear = linearize(model, V, out.equilibrium, options);

  // The same model with the parameter's derivative seeded, preloads included.
  ModelTpl<ParamDual> model_d = seeded(assemble_model(spec), spec, key);
  if (spec.preload == PreloadMode::balance_gravity_at_nominal) {
    const std::vector<Vec3<ParamDual>> preloads = preload_derivatives(spec, key);
    for (size_t i = 0; i < model_d.elements.size(); ++i)
      std::visit([&](auto& e) { e.set_preload(preloads[i]); }, model_d.elements[i]);
  }
  out.equilibrium_derivative = equilibrium_derivative(model, model_d, V, t, out.equilibrium);

  // A and dA/dp in chunks of kAdChunk state directions.
  const int n = model.state_size();
  Eigen::MatrixXd A(n, n), dA(n, n);
  Workspace<ParamAdScalar> ws(model_d);
  VecX<ParamAdScalar> xa(n), f;
  for (int first = 0; first < n; first += kAdChunk) {
    const int width = std::min(kAdChunk, n - first);
    for (int i = 0; i < n; ++i) {
      AdScalar value(out.equilibrium(i), AdDerivatives::Zero());
      if (i >= first && i < first + width) value.derivatives()(i - first) = 1.0;
      xa(i) = ParamAdScalar(value, AdScalar(out.equilibrium_derivative(i), AdDerivatives::Zero()));
    }
    evaluate_rhs<ParamAdScalar>(model_d, ws, t, V, xa, f);
    for (int r = 0; r < n; ++r) {
      A.block(r, first, 1, width) = f(r).v.derivatives().head(width).transpose();
      dA.block(r, first, 1, width) = f(r).d.derivatives().head(width).transpose();
    }
  }
  const std::vector<int>& kept = out.linear.kept_states;
  const int m = int(kept.size());
  out.A_derivative.resize(m, m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) out.A_derivative(i, j) = dA(kept[i], kept[j]);
  // The value part must be the state matrix the analyses use.
  double worst = 0.0;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      worst = std::max(worst, std::abs(A(kept[i], kept[j]) - out.linear.A(i, j)));
  if (!(worst <= 1e-9 * std::max(1.0, out.linear.A.cwiseAbs().maxCoeff())))
    throw std::logic_error("state_matrix_derivative: the parameter-AD state matrix differs from "
                           "the linearisation by " + std::to_string(worst));
  return out;
}

std::complex<double> eigenvalue_derivative(const Eigen::MatrixXd& A, const Eigen::MatrixXd& dA_dp,
                                           std::complex<double> lambda,
                                           const Eigen::VectorXcd& v) {
  // Left eigenvector: w^H A = lambda w^H  <=>  A^T u = lambda u with u = conj(w).
  // A^T copied into a MatrixXd: EigenSolver on a Transpose expression would be
  // a second instantiation (the shared one takes a MatrixXd,
  // linalg/dense_decompositions.hpp); the decomposition reads the same numbers.
  const Eigen::EigenSolver<Eigen::MatrixXd> left(Eigen::MatrixXd(A.transpose()));
  Eigen::Index best = 0;
  (left.eigenvalues().array() - lambda).abs().minCoeff(&best);
  const Eigen::VectorXcd u = left.eigenvectors().col(best);
  const std::complex<double> numerator = u.transpose() * (dA_dp.cast<std::complex<double>>() * v);
  const std::complex<double> denominator = u.transpose() * v;
  return numerator / denominator;
}

}  // namespace railstab
