#pragma once
// What the two CVODES runs of a flow share (flow_sensitivity.cpp: the state
// and, with CVODES's sensitivity module, X and s_V; variational_pass.cpp: X
// and s_V in a second pass): the owners of the SUNDIALS objects, a checked
// call, an Eigen view of an N_Vector and the error handler that keeps
// CVODES's first message for the exception.
#include <cvodes/cvodes.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include <railstab/integrate/stepper.hpp>

#include <Eigen/Core>

#include <sstream>
#include <stdexcept>
#include <string>

namespace railstab::flow_support {

inline Eigen::Map<Eigen::VectorXd> view(N_Vector v) {
  return Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(v), N_VGetLength(v));
}

inline void check(int flag, const char* call) {
  if (flag < 0) throw std::runtime_error(std::string("integrate_flow: ") + call + " failed (flag " +
                                         std::to_string(flag) + ")");
}

// A run that CVODES stopped with `flag` < 0: "integrate_flow: <what>
// stopped at t = ... s of <span> s (<flag name>)[: <first error>]".
[[noreturn]] inline void throw_stopped(void* mem, int flag, const char* what, double span_s,
                                       const std::string& error) {
  double t_reached = 0.0;
  CVodeGetCurrentTime(mem, &t_reached);
  std::ostringstream msg;
  msg << "integrate_flow: " << what << " stopped at t = " << t_reached << " s of " << span_s
      << " s (" << take_sundials_string(CVodeGetReturnFlagName(flag)) << ")";
  if (!error.empty()) msg << ": " << error;
  throw std::runtime_error(msg.str());
}

// CVODES's error handler; `user` is the std::string that keeps the first message.
inline void keep_first_error(int, const char*, const char* function, char* msg, void* user) {
  auto& error = *static_cast<std::string*>(user);
  if (error.empty()) error = std::string(function) + ": " + msg;
}

// A callback body run with exceptions turned into CVODES's recoverable
// failure (CVODES retries with a smaller step); the first message is kept.
template <class F> int guarded(std::string& error, F&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    if (error.empty()) error = e.what();
    return 1;
  }
}

// Owners of the SUNDIALS objects, freed in reverse order.
struct CvodesRun {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  N_Vector* yS = nullptr;
  int Ns = 0;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  void* mem = nullptr;
  CvodesRun() = default;
  CvodesRun(const CvodesRun&) = delete;
  CvodesRun& operator=(const CvodesRun&) = delete;
  ~CvodesRun() {
    if (mem) CVodeFree(&mem);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (yS) N_VDestroyVectorArray(yS, Ns);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }
};

}  // namespace railstab::flow_support
