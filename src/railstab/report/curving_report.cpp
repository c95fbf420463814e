#include <railstab/report/curving_report.hpp>

#include <railstab/io/json_writer.hpp>
#include <railstab/report/run_conditions.hpp>

#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace railstab {

namespace {

double radius_of(const CurvingCondition& c) {
  return c.curvature_per_m == 0.0 ? INFINITY : 1.0 / std::abs(c.curvature_per_m);
}

void check_finite(const CurvingPoint& p) {
  auto bad = [&](double v) { return !std::isfinite(v); };
  bool any = bad(p.state.condition.speed_m_per_s) || bad(p.lateral_acceleration_m_per_s2);
  for (const CurvingWheelset& w : p.wheelsets)
    any = any || bad(w.lateral_shift_m) || bad(w.angle_of_attack_rad) || bad(w.sum_y_N) ||
          bad(w.left.Y_N) || bad(w.left.Q_N) || bad(w.right.Y_N) || bad(w.right.Q_N);
  if (any)
    throw std::runtime_error("curving: a steady state holds a non-finite number at speed " +
                             std::to_string(p.state.condition.speed_m_per_s) +
                             " m/s; no output written");
}

void csv_wheel(std::ostream& out, const WheelForces& w, bool flange) {
  out << ',' << w.Y_N << ',' << w.Q_N << ',';
  if (w.y_over_q) out << *w.y_over_q;
  out << ',';
  if (w.nadal_limit) out << *w.nadal_limit;
  out << ',' << (flange ? 1 : 0);
}

void json_wheel(JsonWriter& j, const char* side, const WheelForces& w, bool flange) {
  j.key(side).begin_object().field("lateral_force_N", w.Y_N).field("wheel_load_N", w.Q_N);
  if (w.y_over_q) j.field("y_over_q", *w.y_over_q);
  else j.key("y_over_q").null();
  if (w.nadal_limit) j.field("nadal_limit", *w.nadal_limit);
  else j.key("nadal_limit").null();
  j.field("max_contact_angle_rad", w.max_contact_angle_rad).field("flange_contact", flange);
  j.end_object();
}

}  // namespace

std::string write_curving_results(const Model& model, const CurvingSweep& sweep,
                                  CurvingSweepKind kind, OutputSet& outputs,
                                  const std::string& stem) {
  for (const CurvingPoint& p : sweep.points) check_finite(p);
  const double D = model.track.spec().rail_contact_distance_m, g = model.gravity_m_per_s2;
  outputs.write(stem + "_curving.csv", [&](std::ostream& out) {
    out << std::setprecision(10)
        << "cant_deficiency_m,speed_m_per_s,radius_m,cant_m,lateral_acceleration_m_per_s2,stable,"
           "divergent_modes,growing_oscillations,largest_real_part_per_s";
    if (!sweep.points.empty())
      for (const CurvingWheelset& w : sweep.points.front().wheelsets) {
        const std::string n = model.bodies[size_t(w.body)].name;
        out << ',' << n << "_lateral_shift_m," << n << "_angle_of_attack_rad," << n << "_roll_rad,"
            << n << "_sum_y_N," << n << "_prudhomme_limit_N";
        for (const char* side : {"left", "right"})
          out << ',' << n << '_' << side << "_Y_N," << n << '_' << side << "_Q_N," << n << '_'
              << side << "_y_over_q," << n << '_' << side << "_nadal_limit," << n << '_' << side
              << "_flange_contact";
      }
    out << "\n";
    for (const CurvingPoint& p : sweep.points) {
      const CurvingCondition& c = p.state.condition;
      out << p.state.cant_deficiency_m << ',' << c.speed_m_per_s << ',' << radius_of(c) << ','
          << c.cant_m << ',' << p.lateral_acceleration_m_per_s2 << ','
          << (p.stability.stable() ? 1 : 0) << ',' << p.stability.divergent << ','
          << p.stability.oscillatory << ',' << p.stability.largest_real_part;
      for (const CurvingWheelset& w : p.wheelsets) {
        out << ',' << w.lateral_shift_m << ',' << w.angle_of_attack_rad << ',' << w.roll_rad << ','
            << w.sum_y_N << ',' << w.prudhomme_limit_N;
        csv_wheel(out, w.left, w.left_flange);
        csv_wheel(out, w.right, w.right_flange);
      }
      out << "\n";
    }
  });
  outputs.write(stem + "_curving.json", [&](std::ostream& out) {
    JsonWriter j(out);
    j.begin_object().field("scene", model.name);
    write_conditions_json(j, run_conditions(model));
    j.field("sweep", kind == CurvingSweepKind::radius ? "radius" : "cant_deficiency");
    j.key("points").begin_array();
    for (const CurvingPoint& p : sweep.points) {
      const CurvingCondition& c = p.state.condition;
      j.begin_object()
          .field("cant_deficiency_m", p.state.cant_deficiency_m)
          .field("speed_m_per_s", c.speed_m_per_s)
          .field("radius_m", radius_of(c))
          .field("turn", c.curvature_per_m >= 0.0 ? "left" : "right")
          .field("cant_m", c.cant_m)
          .field("lateral_acceleration_m_per_s2", p.lateral_acceleration_m_per_s2)
          .field("rail_lateral_force_N", p.rail_lateral_force_N)
          .field("mass_times_lateral_acceleration_N", p.mass_times_lateral_acceleration_N)
          .field("method", p.state.method);
      j.key("stability")
          .begin_object()
          .field("stable", p.stability.stable())
          .field("divergent_modes", p.stability.divergent)
          .field("growing_oscillations", p.stability.oscillatory)
          .field("largest_real_part_per_s", p.stability.largest_real_part)
          .field("statement", p.stability.describe())
          .end_object();
      j
          .field("max_acceleration_residual", p.state.equilibrium.max_acceleration);
      j.key("wheelsets").begin_array();
      for (const CurvingWheelset& w : p.wheelsets) {
        j.begin_object()
            .field("name", model.bodies[size_t(w.body)].name)
            .field("lateral_shift_m", w.lateral_shift_m)
            .field("angle_of_attack_rad", w.angle_of_attack_rad)
            .field("roll_rad", w.roll_rad)
            .field("sum_y_N", w.sum_y_N)
            .field("prudhomme_limit_N", w.prudhomme_limit_N);
        json_wheel(j, "left", w.left, w.left_flange);
        json_wheel(j, "right", w.right, w.right_flange);
        j.end_object();
      }
      j.end_array();
      if (p.nadal_warning.empty()) j.key("warning").null();
      else j.field("warning", p.nadal_warning);
      j.end_object();
    }
    j.end_array();
    if (sweep.physical_limit.empty()) {
      j.key("no_steady_state").null();
    } else {
      j.key("no_steady_state").begin_object().field("statement", sweep.physical_limit);
      if (sweep.limit_condition)
        j.field("first_condition_not_reached",
                describe_condition(*sweep.limit_condition, D, g));
      j.end_object();
    }
    j.end_object();
  });

  std::ostringstream s;
  s << std::fixed;
  s << "steady curving of " << model.name << ": " << sweep.points.size() << " steady state(s)\n";
  s << "  h_d [mm]  V [m/s]   R [m]   a_y [m/s2]  max Y/Q (Nadal)           max |Sum Y| / Prud'homme  on the flange\n";
  int unstable = 0;
  for (const CurvingPoint& p : sweep.points) {
    const CurvingCondition& c = p.state.condition;
    double worst_yq = -INFINITY, worst_nadal = NAN, worst_sumy = 0.0;
    std::string worst_wheel, flanges;
    for (const CurvingWheelset& w : p.wheelsets) {
      for (const WheelForces* wf : {&w.left, &w.right})
        if (wf->y_over_q && *wf->y_over_q > worst_yq) {
          worst_yq = *wf->y_over_q;
          worst_nadal = wf->nadal_limit.value_or(NAN);
          worst_wheel = wf->name(model);
        }
      worst_sumy = std::max(worst_sumy, std::abs(w.sum_y_N) / w.prudhomme_limit_N);
      if (w.left_flange) flanges += (flanges.empty() ? "" : ", ") + w.left.name(model);
      if (w.right_flange) flanges += (flanges.empty() ? "" : ", ") + w.right.name(model);
    }
    // (+ 0.0: no "-0.0" for a balanced cant)
    s << std::setw(10) << std::setprecision(1) << (std::abs(p.state.cant_deficiency_m) < 5e-5 ? 0.0 : p.state.cant_deficiency_m * 1e3) << std::setw(9)
      << std::setprecision(2) << c.speed_m_per_s << std::setw(8) << std::setprecision(0)
      << radius_of(c) << std::setw(12) << std::setprecision(3) << p.lateral_acceleration_m_per_s2
      << "  " << std::setprecision(3) << worst_yq << " (" << worst_nadal << ") " << std::left
      << std::setw(22) << worst_wheel << std::right << std::setw(6) << std::setprecision(3)
      << worst_sumy << "                  " << (flanges.empty() ? "-" : flanges)
      << (p.stability.stable() ? "" : "  [" + p.stability.describe() + "]") << "\n";
    if (!p.stability.stable()) ++unstable;
  }
  if (unstable > 0)
    s << unstable << " of these steady states are unstable (no stable one was found there: the "
      << "vehicle does not stay in them; docs/steady_curving.md)\n";
  if (!sweep.physical_limit.empty()) s << sweep.physical_limit << "\n";
  return s.str();
}

}  // namespace railstab
