#pragma once
// The root functions every integrator watches (SUNDIALS root finding):
//  - flange clearance, g = c^2 - y^2 for every wheelset with a free lateral
//    coordinate: a validity limit, the run stops where it reaches zero;
//  - wheel contact, g = penetration (m) of every Hertz wheel: lift-off
//    (g falls through zero) and touch-down (g rises through zero) are events
//    the run records and goes on through, or stops at on request. With
//    contact damping the normal force (Hertz plus damper, before it is
//    clipped at zero) can vanish while the wheel still penetrates, so there
//    g = that force (N) while penetrating and the penetration (m, <= 0)
//    otherwise: the sign is what counts, and it changes where the force does;
//  - table edge, for every wheel of a profile (or table) contact:
//    g = kTableEdgeFraction - max(|q| / H_q, |theta| / H_theta), q and theta
//    the wheel's lateral shift and roll relative to its rail from the centred
//    pose (the contact table's variables), H their half ranges: the run stops
//    where a wheel reaches 95 % of its table, with a physical statement of
//    the wheel's state (flange climbing, or a shift beyond the table), before
//    a step would leave the table (a contact outside it is not defined).
//
// The penetration is the one evaluate_rhs uses (the same
// evaluate_wheel_contact), computed from the geometry alone: the contacts are
// evaluated with no creep and, without damping, no normal-force law, so a
// root evaluation costs the body kinematics, not a full right-hand side.
#include <railstab/model/model.hpp>
#include <railstab/model/workspace.hpp>

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace railstab {

// Fraction of a contact table's half ranges where a run stops (table_edge).
inline constexpr double kTableEdgeFraction = 0.95;

struct RootFunction {
  enum class Kind { flange_clearance, wheel_contact, table_edge };
  Kind kind = Kind::flange_clearance;
  int body = 0;
  int side = 1;            // wheel_contact, table_edge: +1 left, -1 right
  int state = -1;          // flange_clearance: index of the lateral coordinate
  double clearance_m = 0;  // flange_clearance
};

class RootFunctionSet {
 public:
  RootFunctionSet(const Model& model, double speed_m_per_s);

  int size() const { return int(functions_.size()); }
  const RootFunction& operator[](int i) const { return functions_[size_t(i)]; }

  // g for all functions at (t, x). May throw (non-finite geometry); the
  // SUNDIALS callback catches.
  void evaluate(double t_s, const Eigen::Ref<const Eigen::VectorXd>& x, double* g) const;

  // "wheelset2 left wheel"
  std::string wheel_name(int i) const;

  // Where a table_edge function's wheel sits in its contact table at (t, x).
  struct TablePosition {
    double lateral_m = 0, half_range_m = 0;   // q and H_q
    double roll_rad = 0, roll_half_range_rad = 0;
    double lift_m = 0;  // the wheel's height over its rail minus a centred wheel's
  };
  TablePosition table_position(int i, double t_s, const Eigen::Ref<const Eigen::VectorXd>& x) const;

 private:
  TablePosition table_position_in(const Workspace<double>& ws, const RootFunction& f,
                                  bool with_lift = false) const;
  const Model* model_;
  double speed_m_per_s_;
  std::vector<RootFunction> functions_;
  std::vector<ModelContact> geometry_only_;  // per Model::contacts
  bool has_wheels_ = false;
};

}  // namespace railstab
