#include <railstab/integrate/model_callbacks.hpp>

#include <railstab/linear/jacobian.hpp>
#include <railstab/model/equations_of_motion.hpp>

#include <sunmatrix/sunmatrix_dense.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <cstring>

namespace railstab {

ModelCallbackData::ModelCallbackData(const Model& m, double speed, const RootFunctionSet& r,
                                     double cpu_budget_s)
    : model(&m), speed_m_per_s(speed), roots(&r), workspace(m), jacobian_plan(plan_rhs_jacobian(m)),
      cpu_start_(std::clock()),
      cpu_budget_s_(cpu_budget_s) {}

bool ModelCallbackData::within_budget() {
  if (cpu_budget_s_ <= 0.0) return true;
  // std::clock is a system call; every 16th evaluation is often enough
  // (an evaluation takes microseconds, the budget is seconds).
  if ((++calls_ & 15) != 0) return !budget_exhausted;
  if (double(std::clock() - cpu_start_) / CLOCKS_PER_SEC > cpu_budget_s_) budget_exhausted = true;
  return !budget_exhausted;
}

void prepare_imex_split(ModelCallbackData& data) { data.imex_split = true; }

Eigen::Map<Eigen::VectorXd> as_eigen(N_Vector v) {
  return Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(v), N_VGetLength(v));
}

namespace {

// Runs `f`; turns an exception into SUNDIALS' "recoverable" code 1 (the
// integrator retries with a smaller step) and keeps the first message.
template <class F> int guarded(ModelCallbackData& data, F&& f) {
  if (!data.within_budget()) {
    if (data.error.empty()) data.error = "CPU time budget exhausted";
    return -1;  // unrecoverable: stop now
  }
  try {
    return f();
  } catch (const std::exception& e) {
    if (data.error.empty()) data.error = e.what();
    return 1;
  }
}

// The sparse Newton matrix's Jacobian: every entry of the fixed layout
// written (explicit zeros included), so KLU's symbolic analysis stays valid.
int sparse_jacobian(const ModelCallbackData& data, ForceSelection forces, double t, N_Vector y,
                    SUNMatrix J) {
  const SparseJacobianLayout& layout = data.sparse_layout;
  if (SUNSparseMatrix_NNZ(J) < layout.nonzeros() || SUNSparseMatrix_Columns(J) != layout.n)
    throw std::logic_error("sparse Newton matrix smaller than the Jacobian's layout");
  std::copy(layout.column_starts.begin(), layout.column_starts.end(), SUNSparseMatrix_IndexPointers(J));
  std::copy(layout.row_indices.begin(), layout.row_indices.end(), SUNSparseMatrix_IndexValues(J));
  double* values = SUNSparseMatrix_Data(J);
  std::fill(values, values + SUNSparseMatrix_NNZ(J), 0.0);
  const SparsityPattern& pattern = data.jacobian_plan.pattern;
  bool finite = true;
  rhs_jacobian_ad_entries(*data.model, data.jacobian_plan, data.speed_m_per_s, t, as_eigen(y),
                          forces, [&](int i, int j, double v) {
                            const std::vector<int>& cols = pattern.columns_of_row[size_t(i)];
                            const size_t k = size_t(std::lower_bound(cols.begin(), cols.end(), j) -
                                                    cols.begin());
                            values[layout.position_of[size_t(i)][k]] = v;
                            finite = finite && std::isfinite(v);
                          });
  return finite ? 0 : 1;
}

int dense_jacobian(const ModelCallbackData& data, ForceSelection forces, double t, N_Vector y,
                   SUNMatrix J) {
  if (SUNMatGetID(J) == SUNMATRIX_SPARSE) return sparse_jacobian(data, forces, t, y, J);
  const long n = SUNDenseMatrix_Rows(J);
  Eigen::Map<Eigen::MatrixXd> jac(SUNDenseMatrix_Data(J), n, n);  // column-major
  jac = rhs_jacobian_ad(*data.model, data.jacobian_plan, data.speed_m_per_s, t, as_eigen(y),
                        forces);
  return jac.allFinite() ? 0 : 1;
}

// The right-hand side into data.xdot_buffer with the callback's workspace
// (no allocation); a non-finite entry is an error naming its state.
const Eigen::VectorXd& evaluate(ModelCallbackData& data, ForceSelection forces, double t,
                                N_Vector y) {
  const Eigen::Map<const Eigen::VectorXd> x(N_VGetArrayPointer(y), N_VGetLength(y));
  evaluate_rhs<double>(*data.model, data.workspace, t, data.speed_m_per_s, x, data.xdot_buffer,
                       nullptr, forces);
  for (Eigen::Index i = 0; i < data.xdot_buffer.size(); ++i)
    if (!std::isfinite(data.xdot_buffer(i)))
      throw std::runtime_error("non-finite derivative of state " +
                               data.model->state_name(int(i)) + " at t = " + std::to_string(t) +
                               " s (state value " + std::to_string(x(i)) + ")");
  return data.xdot_buffer;
}
const Eigen::VectorXd& full_rhs(ModelCallbackData& data, double t, N_Vector y) {
  return evaluate(data, ForceSelection::all, t, y);
}
const Eigen::VectorXd& implicit_rhs(ModelCallbackData& data, double t, N_Vector y) {
  return evaluate(data, ForceSelection::contact_and_inertia, t, y);
}

bool same_point(const ModelCallbackData& d, double t, N_Vector y) {
  return d.cache_valid && d.cached_t == t && d.cached_x.size() == N_VGetLength(y) &&
         std::memcmp(d.cached_x.data(), N_VGetArrayPointer(y),
                     sizeof(double) * size_t(d.cached_x.size())) == 0;
}

}  // namespace

int full_rhs_callback(double t, N_Vector y, N_Vector ydot, void* user) {
  auto& data = *static_cast<ModelCallbackData*>(user);
  return guarded(data, [&] {
    as_eigen(ydot) = full_rhs(data, t, y);
    ++data.model_evaluations;
    return 0;
  });
}

int implicit_rhs_callback(double t, N_Vector y, N_Vector ydot, void* user) {
  auto& data = *static_cast<ModelCallbackData*>(user);
  return guarded(data, [&] {
    data.cache_valid = false;
    data.cached_fi = implicit_rhs(data, t, y);
    ++data.model_evaluations;
    data.cached_x = as_eigen(y);
    data.cached_t = t;
    data.cache_valid = true;
    as_eigen(ydot) = data.cached_fi;
    return 0;
  });
}

int explicit_rhs_callback(double t, N_Vector y, N_Vector ydot, void* user) {
  auto& data = *static_cast<ModelCallbackData*>(user);
  return guarded(data, [&] {
    const Eigen::VectorXd f = full_rhs(data, t, y);  // a copy: implicit_rhs reuses the buffer
    ++data.model_evaluations;
    if (same_point(data, t, y)) {
      as_eigen(ydot) = f - data.cached_fi;
    } else {
      as_eigen(ydot) = f - implicit_rhs(data, t, y);
      ++data.model_evaluations;
    }
    return 0;
  });
}

int full_jacobian_callback(double t, N_Vector y, N_Vector, SUNMatrix J, void* user, N_Vector,
                           N_Vector, N_Vector) {
  auto& data = *static_cast<ModelCallbackData*>(user);
  return guarded(data, [&] { return dense_jacobian(data, ForceSelection::all, t, y, J); });
}

int implicit_jacobian_callback(double t, N_Vector y, N_Vector, SUNMatrix J, void* user, N_Vector,
                               N_Vector, N_Vector) {
  auto& data = *static_cast<ModelCallbackData*>(user);
  return guarded(data,
                 [&] { return dense_jacobian(data, ForceSelection::contact_and_inertia, t, y, J); });
}

int root_callback(double t, N_Vector y, double* g, void* user) {
  auto& data = *static_cast<ModelCallbackData*>(user);
  try {
    data.roots->evaluate(t, as_eigen(y), g);
  } catch (const std::exception& e) {
    if (data.error.empty()) data.error = std::string("root function: ") + e.what();
    return -1;  // root functions have no recoverable failure in SUNDIALS
  }
  return 0;
}

void error_handler_callback(int error_code, const char* module, const char* function, char* msg,
                            void* user) {
  auto& data = *static_cast<ModelCallbackData*>(user);
  if (error_code > 0) {  // a warning: the run goes on
    std::fprintf(stderr, "[%s WARNING] %s: %s\n", module, function, msg);
    return;
  }
  data.sundials_message = std::string(function) + ": " + msg;
}

}  // namespace railstab
