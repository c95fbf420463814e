// Cost of profile contact (geometry = "profiles", S1002 on UIC60 1:40)
// against the thesis' knife-edge cone on the same vehicle, measured in one
// run: one right-hand side, one AD Jacobian, reading the scene and building
// its contact table (the set-up step), and a whole critical-speed search (no
// plots).
// CPU time (CLOCK_PROCESS_CPUTIME_ID), 7 repeats, medians and ratios.
//   build/bench_profile_contact [cases-dir]
#include "cpu_timing.hpp"
#include <railstab/eigen/eigen_analysis.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/linear/jacobian.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/setup/contact_tables.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

using namespace railstab;

namespace {

// Median over 7 repeats of the CPU seconds per call (each repeat >= 0.1 s).
double median_cpu_per_call(const std::function<void()>& f) {
  return bench::median_of_batches(f, 7, 0.1);
}

struct Figures {
  double rhs_s, jacobian_s, load_s, search_s, critical_m_per_s;
};

Figures measure(const std::string& path) {
  const PreparedScene scene = prepare_scene(path, {});
  const Model& model = scene.model;
  const double V = scene.speed_m_per_s;
  const Eigen::VectorXd x = scene.equilibrium.state;
  Workspace<double> ws(model);
  Eigen::VectorXd xdot;
  Figures f{};
  f.rhs_s = median_cpu_per_call([&] { evaluate_rhs<double>(model, ws, 0.0, V, x, xdot); });
  f.jacobian_s = median_cpu_per_call([&] { rhs_jacobian_ad(model, V, 0.0, x); });
  f.load_s = median_cpu_per_call([&] {  // reading the scene and building its contact tables
    SceneSpec spec = load_scene_file(path);
    build_contact_tables(spec);
  });
  CriticalSpeedOptions o;  // the command's default range: 5 .. 150 m/s, grid 2.5 m/s
  o.to_m_per_s = 150.0;
  o.grid_step_m_per_s = 2.5;
  CriticalSpeedResult r;
  f.search_s = median_cpu_per_call([&] { r = find_critical_speed(model, x, V, o); });
  f.critical_m_per_s = r.critical_speed_m_per_s;
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string cases = argc > 1 ? argv[1] : "cases";
  std::printf("%-32s %12s %12s %12s %12s %10s\n", "scene", "rhs [us]", "AD jac [ms]",
              "read [ms]", "search [s]", "Vcrit");
  std::vector<Figures> all;
  for (const char* name : {"thesis_vehicle_tangent", "thesis_vehicle_s1002_tangent"}) {
    const Figures f = measure(cases + "/" + name + ".toml");
    all.push_back(f);
    std::printf("%-32s %12.2f %12.3f %12.2f %12.3f %10.2f\n", name, f.rhs_s * 1e6,
                f.jacobian_s * 1e3, f.load_s * 1e3, f.search_s, f.critical_m_per_s);
  }
  std::printf("ratio profiles / knife edge:      %12.2f %12.2f %12.2f %12.2f\n",
              all[1].rhs_s / all[0].rhs_s, all[1].jacobian_s / all[0].jacobian_s,
              all[1].load_s / all[0].load_s, all[1].search_s / all[0].search_s);
  return 0;
}
