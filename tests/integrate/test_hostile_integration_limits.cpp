// The integration driver under hostile settings (issue 10): SUNDIALS'
// return-flag names (malloc'ed per call) are freed, and a run length that
// would overflow the output count stops with a message instead of silently
// simulating one output interval.
#include <gtest/gtest.h>

#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/integrate/integrator.hpp>
#include <railstab/setup/build_model.hpp>
#include <railstab/model/model.hpp>
#include "model/scene_builders.hpp"

#include <cmath>
#include <limits>
#include <malloc.h>

using namespace railstab;

namespace {

constexpr double kSpeed_m_per_s = 10.0;
Model oscillator() { return build_model(test::two_body_oscillator(test::straight_track(), kSpeed_m_per_s)); }

IntegrationOptions options(IntegratorKind kind, double t_end_s, double output_interval_s) {
  IntegrationOptions o;
  o.kind = kind;
  o.t_end_s = t_end_s;
  o.output_interval_s = output_interval_s;
  o.relative_tolerance = 1e-4;
  o.absolute_tolerance = 1e-7;
  o.cpu_time_budget_s = 20.0;  // a bound on the run should the limits regress
  return o;
}

size_t heap_in_use() { return mallinfo2().uordblks; }

}  // namespace

// One flag-name string (24 bytes, a 32-byte heap chunk) leaked per output
// interval before the fix: 20,000 outputs leaked ~640 kB. After the run the
// trajectory is freed, so the heap in use must come back to where it was
// (within 64 kB of allocator slack).
TEST(SundialsFlagNames, AreFreedAfterEveryStepCall) {
  const Model model = oscillator();
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(model.state_size());
  for (IntegratorKind kind :
       {IntegratorKind::cvode_bdf, IntegratorKind::arkode_erk, IntegratorKind::arkode_dirk}) {
    const IntegrationOptions o = options(kind, 20.0, 1e-3);
    { const Trajectory warm_up = integrate(model, kSpeed_m_per_s, x0, o); }
    const size_t before = heap_in_use();
    size_t outputs = 0;
    {
      const Trajectory traj = integrate(model, kSpeed_m_per_s, x0, o);
      outputs = traj.times_s.size();
    }
    const long growth = long(heap_in_use()) - long(before);
    EXPECT_EQ(outputs, 20001u);
    EXPECT_LT(growth, 64 * 1024) << integrator_name(kind) << ": heap grew by " << growth
                                 << " bytes over " << outputs << " outputs";
  }
}

TEST(IntegrationLimits, OutputCountOverflowIsRefusedNamingTheSettings) {
  const Model model = oscillator();
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(model.state_size());
  struct Case {
    double t_end, interval;
    const char* expected;
  };
  // Only cases that end at once even without the check (a regression must
  // fail the test, not fill the memory with 1e13 outputs).
  for (const Case& c : {Case{1e20, 0.01, "at most"},
                        Case{std::numeric_limits<double>::infinity(), 0.01, "finite end time"},
                        Case{1.0, std::nan(""), "output interval"},
                        Case{1.0, 0.0, "output interval"}}) {
    try {
      const Trajectory traj = integrate(model, kSpeed_m_per_s, x0, options(IntegratorKind::cvode_bdf, c.t_end,
                                                           c.interval));
      ADD_FAILURE() << "t_end " << c.t_end << " interval " << c.interval << " ran to t = "
                    << traj.times_s.back();
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(c.expected), std::string::npos) << what;
      EXPECT_NE(what.find("t_end_s"), std::string::npos) << what;
    }
  }
  // The bound itself, at a size that is cheap either way: 10 s every 1 ms
  // is 10,000 outputs, over a limit of 1,000.
  IntegrationOptions o = options(IntegratorKind::cvode_bdf, 10.0, 1e-3);
  o.max_outputs = 1000;
  try {
    integrate(model, kSpeed_m_per_s, x0, o);
    ADD_FAILURE() << "10,000 outputs accepted with max_outputs 1,000";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("would keep 10000 output states; at most 1000"),
              std::string::npos)
        << e.what();
  }
}
