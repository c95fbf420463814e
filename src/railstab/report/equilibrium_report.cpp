#include <railstab/report/equilibrium_report.hpp>
#include <railstab/io/file_names.hpp>

#include <railstab/curving/steady_curving.hpp>
#include <railstab/model/wheel_forces.hpp>
#include <railstab/ride/wheelset_forces.hpp>

#include <railstab/io/json_writer.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/report/run_conditions.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace railstab {

namespace {
// A body's offset from its nominal position per coordinate (kCoordinateNames
// order), the unit at the end: "x_offset_m", not "x_m_offset".
const char* const kOffsetKeys[6] = {"x_offset_m",    "y_offset_m",     "z_offset_m",
                                    "roll_offset_rad", "pitch_offset_rad", "yaw_offset_rad"};
}  // namespace

void check_finite_equilibrium(const Model& model, double speed_m_per_s,
                              const Eigen::MatrixXd& q6, const Eigen::MatrixXd& qd6) {
  for (Eigen::Index b = 0; b < q6.cols(); ++b)
    for (int c = 0; c < 6; ++c)
      if (!std::isfinite(q6(c, b)) || !std::isfinite(qd6(c, b))) {
        std::ostringstream msg;
        msg << "equilibrium of " << model.name << " at " << speed_m_per_s
            << " m/s: " << model.bodies[size_t(b)].name << '.' << kCoordinateNames[c]
            << " is not finite (position " << q6(c, b) << ", rate " << qd6(c, b)
            << "); no output written";
        throw std::runtime_error(msg.str());
      }
}

std::string write_equilibrium_results(const PreparedScene& s, OutputSet& outputs,
                                      const std::string& stem) {
  const Model& model = s.model;
  EvaluationDetails details;
  rhs(model, s.speed_m_per_s, 0.0, s.equilibrium.state, &details);
  const std::vector<WheelForces> wheels =
      wheel_forces(model, s.speed_m_per_s, 0.0, s.equilibrium.state);
  // Sum Y, angle of attack and Delta Q/Q0 (ride/wheelset_forces.hpp).
  const std::vector<WheelsetForces> wheelsets =
      wheelset_forces(model, s.speed_m_per_s, 0.0, s.equilibrium.state,
                      static_wheel_loads(model, s.speed_m_per_s), s.spec.assessment.prudhomme_factor);
  auto wheelset_of = [&](int body) -> const WheelsetForces* {
    for (const WheelsetForces& f : wheelsets)
      if (f.body == body) return &f;
    return nullptr;
  };
  Eigen::MatrixXd q6, qd6;
  model.full_coordinates(0.0, s.speed_m_per_s, s.equilibrium.state, q6, qd6);
  check_finite_equilibrium(model, s.speed_m_per_s, q6, qd6);
  // The text for the terminal is collected while the JSON is rendered and
  // returned only once the JSON holds no non-finite value.
  std::ostringstream shown;
  shown << std::setprecision(6) << "equilibrium of " << model.name << " at "
        << s.speed_m_per_s << " m/s: " << s.equilibrium.iterations
        << " Newton iterations";
  if (s.equilibrium.pseudo_transient_steps > 0)
    shown << " (after " << s.equilibrium.pseudo_transient_steps
          << " pseudo-transient steps from the nominal guess)";
  shown << ", max acceleration residual " << s.equilibrium.max_acceleration << "\n";
  outputs.write(stem + "_equilibrium_" + speed_file_tag(s.speed_m_per_s) + ".json", [&](std::ostream& out) {
    JsonWriter j(out);
    j.begin_object().field("scene", model.name).field("speed_m_per_s", s.speed_m_per_s);
    write_conditions_json(j, run_conditions(model), {s.speed_m_per_s});
    j.field("newton_iterations", s.equilibrium.iterations)
        .field("pseudo_transient_steps", s.equilibrium.pseudo_transient_steps)
        .field("max_acceleration_residual", s.equilibrium.max_acceleration);
    j.key("bodies").begin_array();
    for (size_t b = 0; b < model.bodies.size(); ++b) {
      j.begin_object().field("name", model.bodies[b].name);
      for (int c = 0; c < 6; ++c) {
        const double offset = q6(c, b) - model.bodies[b].nominal_q(c);
        if (c == int(CoordinateIndex::pitch) && model.bodies[b].wheelset()) {
          j.field("spin_rate_rad_per_s", qd6(c, b));
          continue;
        }
        j.field(kOffsetKeys[c], offset);
      }
      shown << "  " << std::left << std::setw(10) << model.bodies[b].name << std::right
            << " lateral " << std::setw(12) << q6(1, b) * 1e3 << " mm  yaw " << std::setw(12)
            << q6(5, b) * 1e3 << " mrad  roll " << std::setw(12) << q6(3, b) * 1e3
            << " mrad  vertical offset " << std::setw(12)
            << (q6(2, b) - model.bodies[b].nominal_q(2)) * 1e3 << " mm\n";
      j.key("wheels").begin_array();
      for (const ContactSnapshot& c : details.contacts) {
        if (c.body != int(b)) continue;
        const WheelContact<double>& w = c.wheel;
        j.begin_object()
            .field("side", w.side > 0 ? "left" : "right")
            .field("contact_point", w.slot)
            .field("contact_angle_rad", w.contact_angle_rad)
            .field("normal_force_N", w.normal_force_N)
            .field("penetration_m", w.penetration_m)
            .field("rolling_radius_m", w.rolling_radius_m)
            .field("creepage_longitudinal", w.creep_x)
            .field("creepage_lateral", w.creep_y)
            .field("creepage_spin_per_m", w.creep_spin_per_m)
            .field("creep_force_longitudinal_N", w.creep_force_x_N)
            .field("creep_force_lateral_N", w.creep_force_y_N)
            .field("spin_creep_moment_N_m", w.spin_moment_N_m)
            .field("total_force_on_wheelset_x_N", w.force_I.x())
            .field("total_force_on_wheelset_y_N", w.force_I.y())
            .field("total_force_on_wheelset_z_N", w.force_I.z())
            .end_object();
        shown << "      " << (w.side > 0 ? "left " : "right") << " wheel load "
              << w.normal_force_N << " N, creepages (" << w.creep_x << ", " << w.creep_y
              << ", " << w.creep_spin_per_m << " 1/m), creep forces (" << w.creep_force_x_N
              << ", " << w.creep_force_y_N << " N, " << w.spin_moment_N_m << " N m)\n";
      }
      j.end_array();
      const WheelsetForces* ws = wheelset_of(int(b));
      if (ws) {
        j.field("sum_y_N", ws->sum_y_N)
            .field("angle_of_attack_rad", ws->angle_of_attack_rad)
            .field("static_axle_load_N", ws->static_axle_load_N)
            .field("prudhomme_limit_N", ws->prudhomme_limit_N)
            .field("sum_y_over_prudhomme_limit", std::abs(ws->sum_y_N) / ws->prudhomme_limit_N);
        shown << "      Sum Y " << ws->sum_y_N << " N (Prud'homme's limit " << ws->prudhomme_limit_N
              << " N), angle of attack " << ws->angle_of_attack_rad * 1e3 << " mrad\n";
      }
      // Y, Q and Y/Q per wheel (model/wheel_forces.hpp), against Nadal.
      j.key("wheel_forces").begin_array();
      for (const WheelForces& w : wheels) {
        if (w.body != int(b)) continue;
        j.begin_object()
            .field("side", w.side > 0 ? "left" : "right")
            .field("lateral_force_N", w.Y_N)
            .field("wheel_load_N", w.Q_N);
        if (ws) {
          const double unloading = w.side > 0 ? ws->left_delta_q_over_q0 : ws->right_delta_q_over_q0;
          j.field("static_wheel_load_N", w.side > 0 ? ws->left_static_load_N : ws->right_static_load_N)
              .field("delta_q_over_q0", unloading);
        }
        if (w.y_over_q) j.field("y_over_q", *w.y_over_q);
        else j.key("y_over_q").null();
        if (w.nadal_limit) j.field("nadal_limit", *w.nadal_limit);
        else j.key("nadal_limit").null();
        j.end_object();
        shown << "      " << (w.side > 0 ? "left " : "right") << " wheel Y " << w.Y_N
              << " N, Q " << w.Q_N << " N";
        if (w.y_over_q) shown << ", Y/Q " << *w.y_over_q;
        if (w.nadal_limit) shown << " (Nadal's limit " << *w.nadal_limit << ")";
        if (ws) shown << ", Delta Q/Q0 " << (w.side > 0 ? ws->left_delta_q_over_q0 : ws->right_delta_q_over_q0);
        shown << "\n";
      }
      j.end_array().end_object();
    }
    j.end_array();
    // Whether the vehicle stays in this state (curving/steady_curving.hpp):
    // between two folds of a branch on real profiles the continuation can
    // only reach unstable ones.
    const SteadyStateStability stability = steady_state_stability(model, s.speed_m_per_s, s.equilibrium.state);
    j.key("stability")
        .begin_object()
        .field("stable", stability.stable())
        .field("divergent_modes", stability.divergent)
        .field("growing_oscillations", stability.oscillatory)
        .field("largest_real_part_per_s", stability.largest_real_part)
        .end_object();
    if (!stability.stable())
      shown << "warning: this steady state is " << stability.describe()
            << " (modes below 20 Hz): the vehicle does not stay in it\n";
    if (const auto w = wheel_beyond_nadal_limit(wheels)) {
      j.field("warning", nadal_warning(model, *w));
      shown << "warning: " << nadal_warning(model, *w) << "\n";
    } else
      j.key("warning").null();
    j.end_object();
  });
  return shown.str();
}

}  // namespace railstab
