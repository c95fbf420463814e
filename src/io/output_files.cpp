#include "io/output_files.hpp"

#include "model/equations_of_motion.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace railstab {

void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write) {
  const std::filesystem::path target(path);
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
  const std::string tmp = path + ".partial";
  {
    std::ofstream out(tmp);
    if (!out) throw std::runtime_error("cannot write " + tmp);
    try {
      write(out);
    } catch (...) {
      out.close();
      std::remove(tmp.c_str());
      throw;
    }
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw std::runtime_error("error while writing " + path);
    }
  }
  std::filesystem::rename(tmp, target);
}

void write_trajectory_csv(const std::string& path, const Model& model, double speed_m_per_s,
                          const Trajectory& traj) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "time_s";
    for (const Body& b : model.bodies)
      for (const std::string& c : kCoordinateNames) out << ',' << b.name << '.' << c;
    out << '\n' << std::setprecision(10);
    Eigen::MatrixXd q6, qd6;
    for (size_t i = 0; i < traj.times_s.size(); ++i) {
      model.full_coordinates(traj.times_s[i], speed_m_per_s, traj.states[i], q6, qd6);
      out << traj.times_s[i];
      for (Eigen::Index b = 0; b < q6.cols(); ++b)
        for (int c = 0; c < 6; ++c) {
          if (!std::isfinite(q6(c, b))) {
            std::ostringstream msg;
            msg << "non-finite " << model.bodies[b].name << '.' << kCoordinateNames[c]
                << " at t = " << traj.times_s[i] << " s; nothing written to " << path;
            throw std::runtime_error(msg.str());
          }
          out << ',' << q6(c, b);
        }
      out << '\n';
    }
  });
}

void write_absolute_roll_csv(const std::string& path, const Model& model, double speed_m_per_s,
                             const Trajectory& traj) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "time_s";
    for (const Body& b : model.bodies) out << ',' << b.name << ".absolute_roll_rad";
    out << '\n' << std::setprecision(10);
    Workspace<double> ws(model);
    for (size_t i = 0; i < traj.times_s.size(); ++i) {
      const double t = traj.times_s[i];
      compute_all_body_motions<double>(model, ws, t, speed_m_per_s, traj.states[i]);
      out << t;
      for (const BodyMotion<double>& m : ws.motions) {
        const Eigen::Matrix3d R_WB = m.R_WI * m.R_IB;
        out << ',' << std::asin(std::clamp(R_WB(2, 1), -1.0, 1.0));
      }
      out << '\n';
    }
  });
}

}  // namespace railstab
