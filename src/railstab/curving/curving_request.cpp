#include <railstab/curving/curving_request.hpp>

#include <cmath>
#include <stdexcept>

namespace railstab {

namespace {

struct QuantityRange {
  double low, high;
  const char* shown;
};

QuantityRange range_of(CurvingQuantity q) {
  return q == CurvingQuantity::cant_deficiency ? QuantityRange{-0.5, 0.5, "in [-0.5, 0.5] m"}
                                               : QuantityRange{10.0, 1e6, "in [10, 1e6] m"};
}

const std::string& name_of(CurvingQuantity q, const CurvingRequestNames& names) {
  return q == CurvingQuantity::cant_deficiency ? names.cant_deficiency : names.radius;
}

}  // namespace

std::string curving_value_message(CurvingQuantity quantity, const std::string& shown,
                                  const std::string& why, const CurvingRequestNames& names) {
  return name_of(quantity, names) + ": expected a value or " + names.range + " in metres, each " +
         range_of(quantity).shown + " (" + names.step + " > 0), got '" + shown + "': " + why;
}

std::vector<double> curving_values(const std::vector<double>& fields, CurvingQuantity quantity,
                                   const std::string& shown, const CurvingRequestNames& names) {
  auto fail = [&](const std::string& why) {
    throw std::invalid_argument(curving_value_message(quantity, shown, why, names));
  };
  if (fields.size() != 1 && fields.size() != 3) fail("not one value or three fields");
  const QuantityRange r = range_of(quantity);
  auto in_range = [&](double v, const std::string& what) {
    if (!std::isfinite(v)) fail(what + " is not a finite number");
    if (!(v >= r.low && v <= r.high)) fail(what + " is outside the range");
    return v;
  };
  if (fields.size() == 1) return {in_range(fields[0], "the value")};
  const double from = in_range(fields[0], names.from);
  const double to = in_range(fields[1], names.to);
  const double step = fields[2];
  if (!std::isfinite(step)) fail(names.step + " is not a finite number");
  if (!(step > 0.0)) fail(names.step + " is not positive");
  if (std::abs(to - from) / step + 1 > kMaxCurvingPoints)
    fail("more than " + std::to_string(kMaxCurvingPoints) + " values");
  const double direction = to >= from ? 1.0 : -1.0;
  std::vector<double> values;
  for (int i = 0;; ++i) {
    const double v = from + direction * i * step;
    if (direction * (v - to) > 1e-3 * step) break;
    values.push_back(v);
  }
  return values;
}

void check_curving_request(const std::vector<double>& deficiencies, const std::vector<double>& radii,
                           const CurvingRequestNames& names) {
  if (deficiencies.size() > 1 && radii.size() > 1)
    throw std::invalid_argument(names.cant_deficiency + " and " + names.radius +
                                ": expected a range in one of them at most (the other one "
                                "value), got two ranges");
  if (deficiencies.empty() && radii.empty())
    throw std::invalid_argument("curving: expected " + names.cant_deficiency + " " + names.range +
                                " (m, at the scene's radius or " + names.one_radius + ") or " +
                                names.radius + " " + names.range +
                                " (m, at the scene's cant deficiency or " + names.one_cant_deficiency +
                                ")");
}

CurvingSweepPlan plan_curving_sweep(const Model& model, double scene_speed_m_per_s,
                                    const std::vector<double>& deficiencies,
                                    const std::vector<double>& radii,
                                    const CurvingRequestNames& names) {
  check_curving_request(deficiencies, radii, names);
  const double D = model.track.spec().rail_contact_distance_m, g = model.gravity_m_per_s2;
  CurvingSweepPlan plan;
  plan.scene = condition_at_reference(model, scene_speed_m_per_s);
  const bool radius_sweep = radii.size() > 1 || deficiencies.empty();
  plan.kind = radius_sweep ? CurvingSweepKind::radius : CurvingSweepKind::cant_deficiency;
  if (radius_sweep) {
    if (!deficiencies.empty()) {
      plan.fixed = deficiencies.front();
    } else {
      if (plan.scene.curvature_per_m == 0.0)
        throw std::invalid_argument(
            names.radius + ": the scene's reference point is on a straight, so it has no cant "
            "deficiency to keep: give " + names.one_cant_deficiency + " (m)");
      plan.fixed = cant_deficiency_m(plan.scene, D, g);
    }
  } else {
    if (!radii.empty()) {
      plan.fixed = radii.front();
    } else {
      if (plan.scene.curvature_per_m == 0.0)
        throw std::invalid_argument(names.cant_deficiency +
                                    ": the scene's reference point is on a straight: give " +
                                    names.one_radius + " (m)");
      plan.fixed = 1.0 / std::abs(plan.scene.curvature_per_m);
    }
  }
  plan.values = radius_sweep ? radii : deficiencies;
  // Every condition must have a positive speed: said before any solve, naming
  // the quantity that set it.
  for (double v : plan.values) {
    const double R = radius_sweep ? v : plan.fixed, h_d = radius_sweep ? plan.fixed : v;
    try {
      (void)speed_for_cant_deficiency(1.0 / R, plan.scene.cant_m, h_d, D, g);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(
          (radius_sweep && deficiencies.empty() ? names.radius : names.cant_deficiency) + ": " + e.what());
    }
  }
  return plan;
}

}  // namespace railstab
