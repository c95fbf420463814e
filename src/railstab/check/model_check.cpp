#include <railstab/check/model_check.hpp>

#include <railstab/core/dual.hpp>
#include <railstab/curving/steady_curving.hpp>
#include <railstab/frames/rotations.hpp>
#include <railstab/linear/jacobian.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/setup/build_model.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <railstab/linalg/dense_decompositions.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <type_traits>

namespace railstab {

namespace {

constexpr double kPi = 3.14159265358979323846;

void warn(ModelCheckReport& r, const std::string& kind, const std::string& subject,
          const std::string& message) {
  r.warnings.push_back({kind, subject, message});
}

// --- bodies: roles, masses, inertias, placement ------------------------------------

// Role of each body from the topology (ModelCheckLimits explains the ranges).
std::vector<std::string> body_roles(const Model& model) {
  const size_t n = model.bodies.size();
  std::vector<bool> joined_to_wheelset(n, false);
  for (const ElementTpl<double>& e : model.elements) {
    const ElementEnds& ends = ends_of(e);
    if (ends.body1 == kTrackBody) continue;
    if (model.bodies[size_t(ends.body1)].wheelset()) joined_to_wheelset[size_t(ends.body2)] = true;
    if (model.bodies[size_t(ends.body2)].wheelset()) joined_to_wheelset[size_t(ends.body1)] = true;
  }
  std::vector<std::string> role(n, "rigid body");
  for (size_t b = 0; b < n; ++b) {
    if (model.bodies[b].wheelset()) role[b] = "wheelset";
    else if (joined_to_wheelset[b]) role[b] = "bogie frame";
  }
  for (const ElementTpl<double>& e : model.elements) {
    const ElementEnds& ends = ends_of(e);
    if (ends.body1 == kTrackBody) continue;
    for (const auto& [a, b] : {std::pair{ends.body1, ends.body2}, std::pair{ends.body2, ends.body1}})
      if (role[size_t(a)] == "bogie frame" && role[size_t(b)] == "rigid body")
        role[size_t(b)] = "car body";
  }
  return role;
}

void check_bodies(const SceneSpec& spec, const Model& model, const ModelCheckLimits& L,
                  ModelCheckReport& r) {
  const std::vector<std::string> roles = body_roles(model);
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const BodySpec& body = spec.bodies[b];
    const std::string& role = roles[b];
    const double m = body.mass_kg;
    r.bodies.push_back({body.name, role, m});
    r.total_mass_kg += m;

    double lo = L.other_body_mass_min_kg, hi = L.other_body_mass_max_kg;
    if (role == "wheelset") lo = L.wheelset_mass_min_kg, hi = L.wheelset_mass_max_kg;
    else if (role == "bogie frame") lo = L.bogie_frame_mass_min_kg, hi = L.bogie_frame_mass_max_kg;
    else if (role == "car body") lo = L.car_body_mass_min_kg, hi = L.car_body_mass_max_kg;
    if (m < lo || m > hi) {
      const bool tonnes = m < lo && m * 1000.0 >= lo && m * 1000.0 <= hi;
      std::ostringstream msg;
      msg << body.name << " (" << role << "): mass_kg = " << m << " is outside " << lo << " - "
          << hi << " kg, the range of a railway " << role;
      if (tonnes) msg << "; it looks like tonnes (" << m * 1000.0 << " kg?)";
      warn(r, tonnes ? "unit_looks_wrong" : "body_mass_out_of_range", body.name, msg.str());
    }
    static const char* axes[3] = {"x (roll)", "y (pitch)", "z (yaw)"};
    for (int i = 0; i < 3 && m > 0.0; ++i) {
      const double J = body.inertia_kg_m2(i);
      const double radius = std::sqrt(std::max(J, 0.0) / m);
      if (radius < L.radius_of_gyration_min_m || radius > L.radius_of_gyration_max_m) {
        std::ostringstream msg;
        msg << body.name << ": inertia_kg_m2 about " << axes[i] << " = " << J
            << " gives a radius of gyration sqrt(J/m) = " << radius << " m, outside "
            << L.radius_of_gyration_min_m << " - " << L.radius_of_gyration_max_m
            << " m (an inertia in t m^2 or g m^2, or another body's?)";
        warn(r, "inertia_out_of_range", body.name, msg.str());
      }
    }
    if (role == "wheelset" && std::abs(body.position_m.x()) > L.wheelset_position_x_max_m) {
      std::ostringstream msg;
      msg << body.name << ": position_m.x = " << body.position_m.x()
          << " m; a wheelset is placed along the track by track_offset_m (now "
          << body.track_offset_m << " m), its contact is evaluated in its own track frame. "
          << "Move " << body.position_m.x() << " m into track_offset_m and set position_m.x = 0";
      warn(r, "wheelset_placed_by_position", body.name, msg.str());
    }
    for (int i = 0; i < 3; ++i)
      if (std::abs(body.position_m(i)) > L.body_position_max_m) {
        std::ostringstream msg;
        msg << body.name << ": position_m[" << i << "] = " << body.position_m(i)
            << " m is beyond " << L.body_position_max_m
            << " m from its track frame: it looks like millimetres (a body is placed along "
               "the track by track_offset_m)";
        warn(r, "unit_looks_wrong", body.name, msg.str());
      }
    if (std::abs(body.track_offset_m) > L.track_offset_max_m) {
      std::ostringstream msg;
      msg << body.name << ": track_offset_m = " << body.track_offset_m << " m is beyond "
          << L.track_offset_max_m << " m: it looks like millimetres";
      warn(r, "unit_looks_wrong", body.name, msg.str());
    }
  }
}

// --- contacts ---------------------------------------------------------------------------
void check_contacts(const SceneSpec& spec, const ModelCheckLimits& L, ModelCheckReport& r) {
  const double D = spec.track.rail_contact_distance_m;
  for (const ContactSpec& c : spec.contacts) {
    const double e0 = c.half_contact_distance_m;
    if (std::abs(2.0 * e0 - D) > L.contact_distance_mismatch_max_m) {
      std::ostringstream msg;
      msg << "contacts." << c.name << ".half_contact_distance_m = " << e0
          << " m: 2 x that = " << 2.0 * e0 << " m disagrees with track.rail_contact_distance_m = "
          << D << " m (by more than " << L.contact_distance_mismatch_max_m
          << " m); the cant angle asin(cant / D) and the wheel contact use different rails";
      warn(r, "contact_distance_mismatch", c.name, msg.str());
    }
    for (const auto& [key, value] : {std::pair<const char*, double>{"half_contact_distance_m", e0},
                                     {"nominal_rolling_radius_m", c.nominal_rolling_radius_m}})
      if (std::abs(value) > L.wheel_geometry_max_m) {
        std::ostringstream msg;
        msg << "contacts." << c.name << "." << key << " = " << value << " m is beyond "
            << L.wheel_geometry_max_m << " m: it looks like millimetres";
        warn(r, "unit_looks_wrong", c.name, msg.str());
      }
  }
  if (std::abs(D) > L.wheel_geometry_max_m) {
    std::ostringstream msg;
    msg << "track.rail_contact_distance_m = " << D << " m is beyond " << L.wheel_geometry_max_m
        << " m: it looks like millimetres";
    warn(r, "unit_looks_wrong", "track", msg.str());
  }
}

// --- elements: geometry and static deflection ---------------------------------------
template <class E> void add_deflections(const E& e, ModelCheckReport& r) {
  const std::string& name = e.ends.name;
  auto add = [&](const std::string& axis, const char* unit, double preload, double k) {
    // An axis without stiffness deflects by nothing; a preload below 1 mN
    // (N m) is round-off of the preload solve on an unloaded axis.
    if (!(k > 0.0) || std::abs(preload) < 1e-3) return;
    r.static_deflections.push_back({name, E::kType, axis, unit, preload, k, preload / k});
  };
  e.for_each_preloaded_axis(add);
}

// A damper in series with a spring (series_spring_damper): its corner
// frequency f_c = k_s / (2 pi c) against the band of the modes that matter
// (ModelCheckLimits). c is the damper's slope at zero velocity, the damping
// the linearisation sees (a table's slope at 0: 9000 N / 0.02 m/s for the
// coach's yaw dampers).
template <class E>
void check_series_damper(const E& e, const ModelCheckLimits& L, ModelCheckReport& r) {
  const double k = value_of(e.series_stiffness_N_per_m);
  // dF/dv at v = 0 by forward-mode AD: exact, as the linearisation sees it
  // (slope_at_zero's central difference is off by ~1 N s/m on a PCHIP table).
  const double c = e.damper.force(Dual<double>(0.0, 1.0)).d;
  if (!(k > 0.0) || !(c > 0.0)) return;
  const double f_c = k / (2.0 * kPi * c);
  const double low = L.series_damper_band_min_hz / L.series_damper_corner_factor_below;
  const double high = L.series_damper_band_max_hz * L.series_damper_corner_factor_above;
  if (f_c >= low && f_c <= high) return;
  const bool below = f_c < low;
  const double f_band = below ? L.series_damper_band_min_hz : L.series_damper_band_max_hz;
  const double kept = 1.0 / (1.0 + (f_band / f_c) * (f_band / f_c));  // c_eff / c at f_band
  std::ostringstream msg;
  msg << e.ends.name << " (series_spring_damper): corner frequency k_s / (2 pi c) = " << k
      << " N/m / (2 pi x " << c << " N s/m) = " << f_c << " Hz is "
      << (below ? "below" : "above") << " the band of body and hunting modes ["
      << L.series_damper_band_min_hz << ", " << L.series_damper_band_max_hz << "] Hz by more than "
      << (below ? L.series_damper_corner_factor_below : L.series_damper_corner_factor_above)
      << " x; ";
  if (below)
    msg << "the damper keeps " << kept * 100.0 << " % of its damping at " << f_band
        << " Hz and does nothing in the band: series_stiffness_N_per_m in MN/m or kN/m where "
           "N/m is expected? (yaw-damper mounts are ~5-20 MN/m)";
  else
    msg << "the series spring is rigid for every modelled motion (a plain damper with a time "
           "constant c / k_s = "
        << c / k << " s): series_stiffness_N_per_m in N/mm where N/m is expected?";
  warn(r, below ? "series_damper_corner_below_band" : "series_damper_corner_above_band",
       e.ends.name, msg.str());
}

void check_elements(const Model& model, const ModelCheckLimits& L, ModelCheckReport& r) {
  for (const ElementTpl<double>& element : model.elements) {
    std::visit(
        [&](const auto& e) {
          add_deflections(e, r);
          const ElementEnds& ends = e.ends;
          for (const auto& [key, p] : {std::pair{"point1_m", ends.point1_m},
                                       std::pair{"point2_m", ends.point2_m}})
            if (p.cwiseAbs().maxCoeff() > L.element_point_max_m) {
              std::ostringstream msg;
              msg << ends.name << ": " << key << " = [" << p.x() << ", " << p.y() << ", "
                  << p.z() << "] m has a coordinate beyond " << L.element_point_max_m
                  << " m from its body: it looks like millimetres";
              warn(r, "unit_looks_wrong", ends.name, msg.str());
            }
          if constexpr (requires { e.series_stiffness_N_per_m; }) check_series_damper(e, L, r);
          // Elements acting on the displacement of two points (free vector d0).
          if constexpr (requires { e.free_vector_m; }) {
            const double apart = e.free_vector_m.norm();
            if (apart > L.spring_end_separation_max_m) {
              std::ostringstream msg;
              msg << ends.name << " (" << std::decay_t<decltype(e)>::kType
                  << "): its end points are " << apart << " m apart at rest (body1 "
                  << ends.body1_name << " point1_m, body2 " << ends.body2_name
                  << " point2_m), more than " << L.spring_end_separation_max_m
                  << " m: a point given in the other body's frame, or measured from the "
                     "wrong origin?";
              warn(r, "spring_ends_apart", ends.name, msg.str());
            }
          }
        },
        element);
  }
  for (const SpringDeflection& d : r.static_deflections)
    if (std::abs(d.deflection) > L.static_deflection_max_m && d.unit == std::string("m")) {
      std::ostringstream msg;
      msg << d.element << ": static deflection " << d.axis << " = preload " << d.preload
          << " N / stiffness " << d.stiffness << " N/m = " << d.deflection << " m, beyond "
          << L.static_deflection_max_m << " m (a stiffness in kN/m, or on the wrong axis?)";
      warn(r, "static_deflection_large", d.element, msg.str());
    }
}

void static_checks(const SceneSpec& spec, const Model& model, const ModelCheckLimits& L,
                   ModelCheckReport& r) {
  r.scene = model.name;
  r.gravity_m_per_s2 = model.gravity_m_per_s2;
  check_bodies(spec, model, L, r);
  check_contacts(spec, L, r);
  check_elements(model, L, r);
}

// --- equilibrium: axle loads, wheel-load balance, lateral shift ----------------------------
// Wheel-load balance of one axle: larger over smaller wheel load.
void check_wheel_load_ratio(const AxleLoad& a, const ModelCheckLimits& L, ModelCheckReport& r) {
  const double larger = std::max(a.left_N, a.right_N), smaller = std::min(a.left_N, a.right_N);
  if (!(larger > 0.0)) return;  // an unloaded axle is the axle-load warning's
  if (smaller > 0.0 && larger / smaller <= L.wheel_load_ratio_max) return;
  std::ostringstream msg;
  msg << a.wheelset << ": wheel loads left " << a.left_N / 1e3 << " kN, right "
      << a.right_N / 1e3 << " kN in the steady state, ratio ";
  if (smaller > 0.0) msg << larger / smaller;
  else msg << "infinite (a wheel unloaded)";
  msg << " beyond wheel_load_ratio_max = " << L.wheel_load_ratio_max
      << " (dQ/Q0 = " << (larger - smaller) / (larger + smaller)
      << "): a cant on the wrong rail, a curve too tight for the speed, or a body's centre of "
         "mass off the centre line?";
  warn(r, "wheel_loads_unbalanced", a.wheelset, msg.str());
}

// A flangeless contact (knife-edge cone, linear conicity) has no flange: a
// steady lateral shift beyond its flange_clearance_m is a state the real
// wheelset cannot reach (it would be flanging), so results from it describe
// no vehicle.
void check_lateral_shift(const Model& model, int b, double y_m, ModelCheckReport& r) {
  const ContactSpec& c = model.contacts[size_t(model.bodies[size_t(b)].wheelset()->contact)].spec;
  if (uses_contact_table(c.geometry) || !(c.flange_clearance_m > 0.0)) return;
  if (std::abs(y_m) <= c.flange_clearance_m) return;
  std::ostringstream msg;
  msg << model.bodies[size_t(b)].name << ": steady lateral shift " << y_m * 1e3
      << " mm is beyond contacts." << c.name << ".flange_clearance_m = "
      << c.flange_clearance_m * 1e3 << " mm; the " << contact_geometry_name(c.geometry)
      << " contact has no flange, a real wheelset would be flanging: the results describe no "
         "vehicle (a curve too tight or a cant deficiency too large for this model?)";
  warn(r, "lateral_shift_beyond_flange_clearance", model.bodies[size_t(b)].name, msg.str());
}

// Cant against the curve at every wheelset's track position (t = 0):
// direction (cant > 0 raises the right rail, the outer rail of a left-hand
// curve kappa > 0), deficiency I = D V^2 |kappa| / g - cant_outer and excess
// E = -I against the line limits (ModelCheckLimits).
void check_cant(const Model& model, double V, const ModelCheckLimits& L, ModelCheckReport& r) {
  const double g = model.gravity_m_per_s2;
  const double D = model.track.spec().rail_contact_distance_m;
  struct Worst {
    double value = 0.0;
    std::string wheelsets;
    TrackGeometryPoint at;
  } inner, deficiency, excess;
  auto note = [](Worst& w, double value, const std::string& name, const TrackGeometryPoint& p) {
    if (w.wheelsets.empty() || value > w.value) w.value = value, w.at = p;
    w.wheelsets += (w.wheelsets.empty() ? "" : ", ") + name;
  };
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    if (!model.bodies[b].wheelset()) continue;
    const TrackGeometryPoint p = model.track.geometry_at(model.arc_length_of(int(b), 0.0, V));
    const double kappa = p.curvature_per_m, cant = p.cant_m;
    const std::string& name = model.bodies[b].name;
    // Cant on the outer rail (> 0) or the inner one (< 0); on tangent track
    // any cant is excess.
    const double cant_outer = kappa > 0.0 ? cant : kappa < 0.0 ? -cant : -std::abs(cant);
    if (kappa != 0.0 && cant_outer < -L.cant_direction_min_m) note(inner, -cant_outer, name, p);
    if (!(g > 0.0)) continue;
    const double I = cant_deficiency_m(CurvingCondition{kappa, cant, V}, D, g);
    if (I > L.cant_deficiency_max_m) note(deficiency, I, name, p);
    if (-I > L.cant_excess_max_m) note(excess, -I, name, p);
  }
  auto where = [](const TrackGeometryPoint& p) {
    std::ostringstream s;
    s << "at s = " << p.s_m << " m: curvature " << p.curvature_per_m << " 1/m";
    if (p.curvature_per_m != 0.0) s << " (R = " << 1.0 / std::abs(p.curvature_per_m) << " m "
                                    << (p.curvature_per_m > 0.0 ? "left" : "right") << ")";
    s << ", cant " << p.cant_m * 1e3 << " mm";
    return s.str();
  };
  if (!inner.wheelsets.empty()) {
    std::ostringstream msg;
    msg << "the cant raises the inner rail under " << inner.wheelsets << " (" << where(inner.at)
        << "): cant > 0 raises the right rail, the outer rail of a left-hand curve (curvature "
           "> 0); give the cant the curvature's sign (track.segments[i].end_cant_m), unless "
           "the line really has adverse cant (a turnout's diverging track)";
    warn(r, "cant_on_inner_rail", "track", msg.str());
  }
  if (!deficiency.wheelsets.empty()) {
    std::ostringstream msg;
    msg << "cant deficiency " << deficiency.value * 1e3 << " mm at " << V << " m/s under "
        << deficiency.wheelsets << " (" << where(deficiency.at)
        << "; I = D V^2 |curvature| / g - cant, D = " << D << " m) is beyond "
        << "cant_deficiency_max_m = " << L.cant_deficiency_max_m * 1e3
        << " mm (EN 13803-1 maximum for conventional vehicles): no line runs this";
    warn(r, "cant_deficiency_beyond_limit", "track", msg.str());
  }
  if (!excess.wheelsets.empty()) {
    std::ostringstream msg;
    msg << "cant excess " << excess.value * 1e3 << " mm at " << V << " m/s under "
        << excess.wheelsets << " (" << where(excess.at)
        << "; E = cant - D V^2 |curvature| / g, D = " << D << " m) is beyond "
        << "cant_excess_max_m = " << L.cant_excess_max_m * 1e3
        << " mm (EN 13803-1 maximum): no line runs this";
    warn(r, "cant_excess_beyond_limit", "track", msg.str());
  }
}

// --- equilibrium: axle loads --------------------------------------------------------------
void axle_loads(const Model& model, double V, const EquilibriumResult& eq,
                const ModelCheckLimits& L, ModelCheckReport& r) {
  EvaluationDetails details;
  rhs(model, V, 0.0, eq.state, &details);
  Eigen::MatrixXd q6, qd6;
  model.full_coordinates(0.0, V, eq.state, q6, qd6);
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    if (!model.bodies[b].wheelset()) continue;
    AxleLoad a;
    a.wheelset = model.bodies[b].name;
    // Wheel load: the rail's total force on the wheel (normal and creep
    // forces) along the track normal z_T; force_I is in the wheelset's
    // non-spinning frame I, R_TI = Rz(yaw) Rx(roll).
    const Eigen::Matrix3d R_TI = rot_z(q6(5, b)) * rot_x(q6(3, b));
    for (const ContactSnapshot& c : details.contacts) {
      if (c.body != int(b)) continue;
      const double load = (R_TI * c.wheel.force_I).z();
      (c.wheel.side > 0 ? a.left_N : a.right_N) += load;
    }
    a.total_N = a.left_N + a.right_N;
    r.axle_load_sum_N += a.total_N;
    if (a.total_N < L.axle_load_min_N || a.total_N > L.axle_load_max_N) {
      std::ostringstream msg;
      msg << a.wheelset << ": axle load " << a.total_N / 1e3 << " kN";
      if (r.gravity_m_per_s2 > 0.0) msg << " (" << a.total_N / r.gravity_m_per_s2 / 1e3 << " t)";
      msg << " is outside " << L.axle_load_min_N / 1e3 << " - " << L.axle_load_max_N / 1e3
          << " kN, the range of railway vehicles (masses in tonnes, or the wrong body "
             "carried by this wheelset?)";
      warn(r, "axle_load_out_of_range", a.wheelset, msg.str());
    }
    check_wheel_load_ratio(a, L, r);
    check_lateral_shift(model, int(b), q6(int(CoordinateIndex::y), Eigen::Index(b)), r);
    r.axle_loads.push_back(a);
  }
}

// --- stiffness: unheld longitudinal coordinates ----------------------------------------------
// Stiffness part of the Jacobian of the right-hand side (AD) at the state x:
// with x = [q; u], the block d(du/dt)/dq = -M^-1 K. An eigenvalue
// -omega^2 ~ 0 is a motion nothing resists (creep forces resist its rate
// only); when its eigenvector is mostly body x coordinates, that is a free
// longitudinal coordinate with nothing holding it. A coordinate whose column
// is exactly zero (nothing depends on it) is reported directly. Translation
// along the track changes no force whether or not x is an equilibrium, so
// the test also runs on a model whose equilibrium failed (at its nominal
// state).
void unheld_longitudinal(const Model& model, double V, const Eigen::VectorXd& x,
                         const ModelCheckLimits& L, ModelCheckReport& r) {
  const Eigen::MatrixXd jac = rhs_jacobian_ad(model, V, 0.0, x);
  const int n = model.n_coordinates;
  std::vector<int> positions;  // state indices of the positions kept in K
  for (int k = 0; k < n; ++k) {
    if (is_spin_angle(model, k)) continue;  // cyclic by design (ERRATA 11a)
    const auto [b, c] = model.coordinate_of_state[size_t(k)];
    if (!jac.block(n, k, n, 1).isZero(0.0)) {
      positions.push_back(k);
    } else if (c == int(CoordinateIndex::x)) {
      warn(r, "longitudinal_unheld", model.bodies[size_t(b)].name,
           model.bodies[size_t(b)].name +
               ".x is free but no force depends on it (no stiffness along x): it drifts; hold "
               "it (remove \"x\" from free) or connect it longitudinally");
    }
  }
  const int m = int(positions.size());
  if (m == 0) return;
  Eigen::MatrixXd K(m, m);  // d(acceleration)/d(position), 1/s^2
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      K(i, j) = jac(n + positions[size_t(i)], positions[size_t(j)]);
    }
  Eigen::EigenSolver<Eigen::MatrixXd> es(K);
  if (es.info() != Eigen::Success) return;
  const double omega2_max = std::pow(2.0 * kPi * L.unheld_frequency_max_hz, 2);
  for (int i = 0; i < m; ++i) {
    if (std::abs(es.eigenvalues()(i)) > omega2_max) continue;
    const Eigen::VectorXcd v = es.eigenvectors().col(i);
    double total = v.squaredNorm(), along_x = 0.0, largest = 0.0;
    for (int j = 0; j < m; ++j)
      if (model.coordinate_of_state[size_t(positions[size_t(j)])].second == 0) {
        along_x += std::norm(v(j));
        largest = std::max(largest, std::norm(v(j)));
      }
    if (!(total > 0.0) || along_x < 0.5 * total) continue;
    std::string bodies;
    for (int j = 0; j < m; ++j) {
      const auto [b, c] = model.coordinate_of_state[size_t(positions[size_t(j)])];
      if (c == 0 && std::norm(v(j)) > 0.1 * largest)
        bodies += (bodies.empty() ? "" : ", ") + model.bodies[size_t(b)].name;
    }
    std::ostringstream msg;
    msg << "nothing holds the longitudinal position (x) of " << bodies
        << ": the linearised stiffness has an eigenvalue omega^2 = "
        << std::abs(es.eigenvalues()(i)) << " 1/s^2 (below "
        << L.unheld_frequency_max_hz
        << " Hz) along their x; creep forces resist its rate only. Hold one body's x (as the "
           "thesis vehicle holds the car body's) or add a longitudinal connection";
    warn(r, "longitudinal_unheld", bodies, msg.str());
  }
}

void natural_frequencies(const Model& model, double V, const EquilibriumResult& eq,
                         const ModelCheckOptions& o, ModelCheckReport& r) {
  r.natural_frequency_speed_m_per_s = o.natural_frequency_speed_m_per_s;
  r.natural_frequency_min_hz = o.natural_frequency_min_hz;
  r.natural_frequency_max_hz = o.natural_frequency_max_hz;
  StabilityOptions so;
  so.solver = EigenSolverKind::dense;
  so.max_frequency_hz = o.natural_frequency_max_hz;
  SpeedStability stability(model, eq.state, V, so);
  const StabilityPoint p = stability.at(o.natural_frequency_speed_m_per_s);
  for (const ModeReport& mode : p.modes) {
    if (mode.neutral || !(mode.eigenvalue.imag() > 0.0)) continue;
    if (mode.frequency_hz < o.natural_frequency_min_hz ||
        mode.frequency_hz > o.natural_frequency_max_hz)
      continue;
    if (!std::isfinite(mode.frequency_hz) || !std::isfinite(mode.damping_ratio)) continue;
    r.natural_frequencies.push_back({mode.frequency_hz, mode.damping_ratio, mode.name});
  }
  if (r.natural_frequencies.empty()) {
    std::ostringstream note;
    note << "no natural frequency at rest between " << o.natural_frequency_min_hz << " and "
         << o.natural_frequency_max_hz << " Hz";
    r.natural_frequency_note = note.str();
  }
  std::sort(r.natural_frequencies.begin(), r.natural_frequencies.end(),
            [](const NaturalFrequency& a, const NaturalFrequency& b) {
              return a.frequency_hz < b.frequency_hz;
            });
}

}  // namespace

bool ModelCheckReport::has_warning(const std::string& kind) const {
  return std::any_of(warnings.begin(), warnings.end(),
                     [&](const ModelWarning& w) { return w.kind == kind; });
}

ModelCheckReport check_model(const SceneSpec& spec, const Model& model, double speed_m_per_s,
                             const EquilibriumResult& equilibrium,
                             const ModelCheckOptions& options) {
  ModelCheckReport r;
  r.speed_m_per_s = speed_m_per_s;
  static_checks(spec, model, options.limits, r);
  check_cant(model, speed_m_per_s, options.limits, r);
  axle_loads(model, speed_m_per_s, equilibrium, options.limits, r);
  unheld_longitudinal(model, speed_m_per_s, equilibrium.state, options.limits, r);
  if (options.natural_frequencies) {
    try {
      natural_frequencies(model, speed_m_per_s, equilibrium, options, r);
    } catch (const std::exception& e) {
      r.natural_frequency_note = "no natural frequencies: " + std::string(e.what());
    }
  }
  return r;
}

std::vector<ModelWarning> check_speed_range(const Model& model,
                                            const std::vector<SpeedSteadyState>& speeds,
                                            const ModelCheckLimits& limits) {
  struct Seen {
    std::string kind, subject;
    double first = 0.0, last = 0.0;
    int count = 0;
    std::string worst_message;
  };
  std::vector<Seen> seen;  // in the order first met
  int checked = 0;
  for (const SpeedSteadyState& p : speeds) {
    ModelCheckReport r;
    r.gravity_m_per_s2 = model.gravity_m_per_s2;
    check_cant(model, p.speed_m_per_s, limits, r);
    if (p.state) {
      EquilibriumResult eq;
      eq.state = *p.state;
      axle_loads(model, p.speed_m_per_s, eq, limits, r);
    }
    ++checked;
    for (const ModelWarning& w : r.warnings) {
      // Speed-independent warnings (the cant's direction, the axle load's
      // size) are check_model's at the run's speed.
      if (w.kind != "cant_deficiency_beyond_limit" && w.kind != "cant_excess_beyond_limit" &&
          w.kind != "wheel_loads_unbalanced" && w.kind != "lateral_shift_beyond_flange_clearance")
        continue;
      auto it = std::find_if(seen.begin(), seen.end(), [&](const Seen& x) {
        return x.kind == w.kind && x.subject == w.subject;
      });
      if (it == seen.end()) {
        seen.push_back({w.kind, w.subject, p.speed_m_per_s, p.speed_m_per_s, 0, w.message});
        it = seen.end() - 1;
      }
      // Excess is worst at the lowest speed, the others at the highest.
      const bool worse = w.kind == "cant_excess_beyond_limit" ? p.speed_m_per_s < it->first
                                                              : p.speed_m_per_s > it->last;
      if (worse) it->worst_message = w.message;
      it->first = std::min(it->first, p.speed_m_per_s);
      it->last = std::max(it->last, p.speed_m_per_s);
      ++it->count;
    }
  }
  std::vector<ModelWarning> out;
  for (const Seen& x : seen) {
    std::ostringstream msg;
    msg << "in the speed range, at " << x.count << " of " << checked << " speeds checked";
    if (x.first != x.last) msg << " (" << x.first << " to " << x.last << " m/s)";
    else msg << " (" << x.first << " m/s)";
    msg << "; the worst: " << x.worst_message;
    out.push_back({x.kind, x.subject, msg.str()});
  }
  return out;
}

ModelCheckReport check_model_without_equilibrium(const SceneSpec& spec, const Model& model,
                                                 const std::string& error,
                                                 const ModelCheckOptions& options) {
  ModelCheckReport r;
  r.speed_m_per_s = spec.speed_m_per_s;
  static_checks(spec, model, options.limits, r);
  check_cant(model, spec.speed_m_per_s, options.limits, r);
  unheld_longitudinal(model, spec.speed_m_per_s,
                      lowered_nominal_state(model, spec.speed_m_per_s), options.limits, r);
  r.errors.push_back(error);
  r.natural_frequency_note = "no natural frequencies: no equilibrium";
  return r;
}

ModelCheckReport check_scene(const SceneSpec& spec, const ModelCheckOptions& options) {
  // Without its preloads (their solve is a static equilibrium and fails on
  // the same mistakes) the model is still worth checking.
  std::optional<Model> model;
  try {
    model.emplace(build_model(spec));
  } catch (const std::exception& e) {
    SceneSpec unloaded = spec;
    unloaded.preload = PreloadMode::none;
    const Model m = build_model(unloaded);
    return check_model_without_equilibrium(
        spec, m, std::string("the gravity preloads could not be solved: ") + e.what(), options);
  }
  const double V = spec.speed_m_per_s;
  EquilibriumResult eq;
  try {
    eq = solve_equilibrium(*model, V, lowered_nominal_state(*model, V));
  } catch (const std::exception& e) {
    return check_model_without_equilibrium(spec, *model, e.what(), options);
  }
  return check_model(spec, *model, V, eq, options);
}

}  // namespace railstab
