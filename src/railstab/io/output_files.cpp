#include <railstab/io/output_files.hpp>

#include <functional>

#include <railstab/io/csv.hpp>
#include <railstab/model/equations_of_motion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace railstab {

std::string trajectory_csv_header(const Model& model) {
  std::string header = "time_s";
  for (const Body& b : model.bodies)
    for (const std::string& c : kCoordinateNames) header += ',' + csv_field(b.name + '.' + c);
  return header;
}

std::string absolute_roll_csv_header(const Model& model) {
  std::string header = "time_s";
  for (const Body& b : model.bodies)
    header += ',' + csv_field(b.name + ".absolute_roll_rad");
  return header;
}

void write_trajectory_csv(std::ostream& out, const Model& model, double speed_m_per_s,
                          const Trajectory& traj, int digits) {
  out << trajectory_csv_header(model) << '\n' << std::setprecision(digits);
  Eigen::MatrixXd q6, qd6;
  for (size_t i = 0; i < traj.times_s.size(); ++i) {
    const double t = traj.times_s[i];
    model.full_coordinates(t, speed_m_per_s, traj.states[i], q6, qd6);
    put_csv_number(out, t, [] { return std::string("time_s"); });
    for (Eigen::Index b = 0; b < q6.cols(); ++b)
      for (int c = 0; c < 6; ++c) {
        out << ',';
        put_csv_number(out, q6(c, b), [&] {
          std::ostringstream what;
          what << model.bodies[b].name << '.' << kCoordinateNames[c] << " at t = " << t << " s";
          return what.str();
        });
      }
    out << '\n';
  }
}

void write_absolute_roll_csv(std::ostream& out, const Model& model, double speed_m_per_s,
                             const Trajectory& traj, int digits) {
  out << absolute_roll_csv_header(model) << '\n' << std::setprecision(digits);
  Workspace<double> ws(model);
  const std::vector<BodyMotion<double>>& motions = ws.motions;
  for (size_t i = 0; i < traj.times_s.size(); ++i) {
    const double t = traj.times_s[i];
    compute_all_body_motions<double>(model, ws, t, speed_m_per_s, traj.states[i]);
    put_csv_number(out, t, [] { return std::string("time_s"); });
    for (size_t b = 0; b < motions.size(); ++b) {
      const Eigen::Matrix3d R_WB = motions[b].R_WI * motions[b].R_IB;
      const double roll = std::asin(std::clamp(R_WB(2, 1), -1.0, 1.0));
      out << ',';
      put_csv_number(out, roll, [&] {
        std::ostringstream what;
        what << model.bodies[b].name << ".absolute_roll_rad at t = " << t << " s";
        return what.str();
      });
    }
    out << '\n';
  }
}

}  // namespace railstab
