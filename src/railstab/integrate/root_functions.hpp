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
//    otherwise: the sign is what counts, and it changes where the force does.
//
// The penetration is the one evaluate_rhs uses (the same
// evaluate_wheel_contact), computed from the geometry alone: the contacts are
// evaluated with no creep and, without damping, no normal-force law, so a
// root evaluation costs the body kinematics, not a full right-hand side.
#include <railstab/model/model.hpp>

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace railstab {

struct RootFunction {
  enum class Kind { flange_clearance, wheel_contact };
  Kind kind = Kind::flange_clearance;
  int body = 0;
  int side = 1;            // wheel_contact: +1 left, -1 right
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

 private:
  const Model* model_;
  double speed_m_per_s_;
  std::vector<RootFunction> functions_;
  std::vector<ModelContact> geometry_only_;  // per Model::contacts
  bool has_wheels_ = false;
};

}  // namespace railstab
