#include <railstab/integrate/root_functions.hpp>

#include <railstab/contact/wheel_rail.hpp>
#include <railstab/model/equations_of_motion.hpp>

#include <algorithm>
#include <cmath>

namespace railstab {

RootFunctionSet::RootFunctionSet(const Model& model, double speed_m_per_s)
    : model_(&model), speed_m_per_s_(speed_m_per_s) {
  // One function of `kind` per wheel of wheelset b.
  auto add_wheels = [&](RootFunction::Kind kind, int b) {
    for (int side : {1, -1}) {
      RootFunction f;
      f.kind = kind;
      f.body = b;
      f.side = side;
      functions_.push_back(f);
    }
    has_wheels_ = true;
  };
  for (int b = 0; b < int(model.bodies.size()); ++b) {
    const Body& body = model.bodies[size_t(b)];
    if (!body.wheelset()) continue;
    const int contact = body.wheelset()->contact;
    // Profile (or table) contact has its flange: no validity limit to stop
    // at, and its contact points come and go smoothly (Hertz, C1 at zero
    // overlap; the table's slots) without events; the run stops only where
    // a wheel reaches the edge of its table.
    if (uses_contact_table(model.contacts[size_t(contact)].spec.geometry)) {
      add_wheels(RootFunction::Kind::table_edge, b);
      continue;
    }
    const int k = body.state_index[int(CoordinateIndex::y)];
    if (k >= 0) {
      RootFunction f;
      f.kind = RootFunction::Kind::flange_clearance;
      f.body = b;
      f.state = k;
      f.clearance_m = model.contacts[size_t(contact)].spec.flange_clearance_m;
      functions_.push_back(f);
    }
    // A prescribed wheel load never lifts off.
    if (model.contacts[size_t(contact)].spec.normal != NormalForceKind::hertz) continue;
    add_wheels(RootFunction::Kind::wheel_contact, b);
  }
  // The penetration does not depend on the force laws; with a prescribed zero
  // load and no creep, evaluate_wheel_contact stops after the geometry.
  geometry_only_ = model.contacts;
  for (ModelContact& c : geometry_only_) {
    c.spec.tangential = TangentialForceKind::none;
    if (c.spec.normal_damping_N_s_per_m > 0.0) continue;  // needs the force law
    c.spec.normal = NormalForceKind::prescribed;
    c.spec.prescribed_wheel_load_N = 0.0;
  }
}

void RootFunctionSet::evaluate(double t_s, const Eigen::Ref<const Eigen::VectorXd>& x,
                               double* g) const {
  Workspace<double> ws;
  const bool irregular = model_->track.irregularities() != nullptr;
  if (has_wheels_) compute_all_body_motions<double>(*model_, ws, t_s, speed_m_per_s_, x);
  else if (irregular) ws.update_frames(*model_, t_s, speed_m_per_s_);
  for (size_t i = 0; i < functions_.size(); ++i) {
    const RootFunction& f = functions_[i];
    if (f.kind == RootFunction::Kind::table_edge) {
      const TablePosition p = table_position_in(ws, f);
      g[i] = kTableEdgeFraction - std::max(std::abs(p.lateral_m) / p.half_range_m,
                                           std::abs(p.roll_rad) / p.roll_half_range_rad);
      continue;
    }
    if (f.kind == RootFunction::Kind::flange_clearance) {
      const double y = x(f.state), c = f.clearance_m;
      if (irregular) {
        // Each flange's clearance from its own (displaced) rail:
        // (c + dy_left - y)(y + c - dy_right), c^2 - y^2 on perfect track.
        const TrackFrameKinematics& k = ws.frames[size_t(f.body)];
        g[i] = (c + k.rail(+1).lateral_m - y) * (y + c - k.rail(-1).lateral_m);
      } else {
        g[i] = c * c - y * y;
      }
    } else {
      const ModelContact& c =
          geometry_only_[size_t(model_->bodies[size_t(f.body)].wheelset()->contact)];
      const WheelContact<double> w =
          evaluate_wheel_contact(c, ws.motions[size_t(f.body)], f.side,
                                 model_->speed_at(t_s, speed_m_per_s_));
      const double penetration = w.penetration_m;
      if (c.spec.normal_damping_N_s_per_m > 0.0 && penetration > 0.0) {
        g[i] = w.unclipped_normal_force_N != 0.0 ? w.unclipped_normal_force_N : -1e-20;
        continue;
      }
      // The penetration is a difference of two radii near 0.45 m, quantised
      // to ~1e-16 m, so it is exactly zero on a short plateau around a
      // crossing; SUNDIALS rejects a root function that stays exactly zero
      // ("root found at and very near t"). Zero means no force in the model
      // (contact iff penetration > 0), so it counts as a negative far below
      // the rounding quantum (not a denormal: the root finder divides by g).
      g[i] = penetration != 0.0 ? penetration : -1e-20;
    }
  }
}

RootFunctionSet::TablePosition RootFunctionSet::table_position_in(const Workspace<double>& ws,
                                                                  const RootFunction& f,
                                                                  bool with_lift) const {
  const ModelContact& c = model_->contacts[size_t(model_->bodies[size_t(f.body)].wheelset()->contact)];
  const ProfileContactGeometry& pg = *c.spec.profile_geometry;
  const BodyMotion<double>& m = ws.motions[size_t(f.body)];
  // As the contact sees it (wheel_rail.hpp): the wheelset from this rail.
  const RailDisplacement& rail = m.track->rail(f.side);
  const ProfilePair& pair = pg.pair_for(f.side);  // (each wheel its own on an asymmetric wheelset)
  const WheelPoseOf<double> pose = wheel_pose_in_rail_frame<double>(
      pair, f.side, m.q(1) - rail.lateral_m, m.q(2) - rail.vertical_m, m.q(3));
  const ContactTable& table = pg.table_for(f.side);
  TablePosition p;
  p.lateral_m = pose.lateral_m - table.nominal_lateral_m();
  p.half_range_m = table.options().lateral_half_range_m;
  p.roll_rad = pose.roll_rad;
  p.roll_half_range_rad = table.options().roll_half_range_rad;
  if (with_lift) {  // for the stop message only, not the root function
    const WheelPoseOf<double> centred = wheel_pose_in_rail_frame<double>(
        pair, f.side, 0.0, pair.parameters.nominal_rolling_radius_m, 0.0);
    p.lift_m = pose.vertical_m - centred.vertical_m;
  }
  return p;
}

RootFunctionSet::TablePosition RootFunctionSet::table_position(
    int i, double t_s, const Eigen::Ref<const Eigen::VectorXd>& x) const {
  Workspace<double> ws;
  compute_all_body_motions<double>(*model_, ws, t_s, speed_m_per_s_, x);
  return table_position_in(ws, functions_[size_t(i)], true);
}

std::string RootFunctionSet::wheel_name(int i) const {
  const RootFunction& f = functions_[size_t(i)];
  return model_->bodies[size_t(f.body)].name + (f.side > 0 ? " left wheel" : " right wheel");
}

}  // namespace railstab
