#include <railstab/io/ride_files.hpp>

#include <railstab/io/csv.hpp>

#include <iomanip>
#include <sstream>

namespace railstab {

namespace {

const char* const kSides[2] = {"left", "right"};
const char* const kWheelColumns[4] = {"lateral_force_N", "wheel_load_N", "y_over_q",
                                      "delta_q_over_q0"};
const char* const kAccelerationColumns[3] = {"longitudinal_acceleration_m_per_s2",
                                             "lateral_acceleration_m_per_s2",
                                             "vertical_acceleration_m_per_s2"};

void put(std::ostream& out, double value, const std::string& column, double t) {
  out << ',';
  put_csv_number(out, value, [&] {
    std::ostringstream what;
    what << column << " at t = " << t << " s";
    return what.str();
  });
}

}  // namespace

std::string wheel_forces_csv_header(const Model& model, const RideHistory& history) {
  std::string header = "time_s";
  for (const StaticWheelLoad& load : history.static_loads) {
    const std::string& ws = model.bodies[size_t(load.body)].name;
    header += ',' + csv_field(ws + ".sum_y_N") + ',' + csv_field(ws + ".angle_of_attack_rad");
    for (const char* side : kSides)
      for (const char* column : kWheelColumns)
        header += ',' + csv_field(ws + "." + side + "." + column);
  }
  return header;
}

std::string accelerations_csv_header(const RideHistory& history) {
  std::string header = "time_s";
  for (const AccelerationPoint& p : history.points)
    for (const char* column : kAccelerationColumns) header += ',' + csv_field(p.label + "." + column);
  return header;
}

void write_wheel_forces_csv(std::ostream& out, const Model& model, const RideHistory& history, int digits) {
  out << wheel_forces_csv_header(model, history) << '\n' << std::setprecision(digits);
  for (size_t i = 0; i < history.times_s.size(); ++i) {
    const double t = history.times_s[i];
    put_csv_number(out, t, [] { return std::string("time_s"); });
    for (const WheelsetForces& f : history.wheelsets[i]) {
      const std::string& ws = model.bodies[size_t(f.body)].name;
      put(out, f.sum_y_N, ws + ".sum_y_N", t);
      put(out, f.angle_of_attack_rad, ws + ".angle_of_attack_rad", t);
      const WheelForces* wheels[2] = {&f.left, &f.right};
      const double unloading[2] = {f.left_delta_q_over_q0, f.right_delta_q_over_q0};
      for (int s = 0; s < 2; ++s) {
        const std::string prefix = ws + "." + kSides[s] + ".";
        put(out, wheels[s]->Y_N, prefix + kWheelColumns[0], t);
        put(out, wheels[s]->Q_N, prefix + kWheelColumns[1], t);
        if (wheels[s]->y_over_q)
          put(out, *wheels[s]->y_over_q, prefix + kWheelColumns[2], t);
        else
          out << ',';  // lifted wheel: no Y/Q
        put(out, unloading[s], prefix + kWheelColumns[3], t);
      }
    }
    out << '\n';
  }
}

void write_accelerations_csv(std::ostream& out, const RideHistory& history, int digits) {
  out << accelerations_csv_header(history) << '\n' << std::setprecision(digits);
  for (size_t i = 0; i < history.times_s.size(); ++i) {
    const double t = history.times_s[i];
    put_csv_number(out, t, [] { return std::string("time_s"); });
    for (size_t p = 0; p < history.points.size(); ++p)
      for (int c = 0; c < 3; ++c)
        put(out, history.accelerations[i][p](c),
            history.points[p].label + "." + kAccelerationColumns[c], t);
    out << '\n';
  }
}

}  // namespace railstab
