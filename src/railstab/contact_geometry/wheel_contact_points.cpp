#include <railstab/contact_geometry/wheel_contact_points.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace railstab {
namespace {

// The gap along the wheel profile and its first two derivatives in u.
struct GapAt {
  double g, dg, d2g;
  double Y;  // rail y under the wheel point
};

class GapFunction {
 public:
  GapFunction(const ProfilePair& pair, const WheelPose& pose)
      : pair_(pair), pose_(pose), c_(std::cos(pose.roll_rad)), s_(std::sin(pose.roll_rad)) {}

  // Y = lat + u c - z_w s, Z = vert + u s + z_w c, g = Z - z_r(Y):
  //   g'  = Z' - z_r' Y',  Y' = c - z_w' s,  Z' = s + z_w' c
  //   g'' = Z'' - z_r'' Y'^2 - z_r' Y'',  Y'' = -z_w'' s,  Z'' = z_w'' c
  GapAt at(double u) const {
    const CubicSpline::Value w = pair_.wheel_z.evaluate(u);
    const double Y = pose_.lateral_m + u * c_ - w.f * s_;
    const double Z = pose_.vertical_m + u * s_ + w.f * c_;
    const CubicSpline::Value r = pair_.rail_z.evaluate(Y);
    const double dY = c_ - w.df * s_, dZ = s_ + w.df * c_;
    const double d2Y = -w.d2f * s_, d2Z = w.d2f * c_;
    return {Z - r.f, dZ - r.df * dY, d2Z - r.d2f * dY * dY - r.df * d2Y, Y};
  }
  // at(u).g alone (the same expressions, so the same bits), for the samples.
  double gap(double u) const {
    const double w = pair_.wheel_z(u);
    const double Y = pose_.lateral_m + u * c_ - w * s_;
    const double Z = pose_.vertical_m + u * s_ + w * c_;
    return Z - pair_.rail_z(Y);
  }
  double rail_y(double u) const { return pose_.lateral_m + u * c_ - pair_.wheel_z(u) * s_; }

  // Wheel range [u0, u1] whose points lie above the rail profile (Y within
  // the rail's range); Y(u) is increasing while |z_w'| tan|roll| < 1.
  bool overlap(double& u0, double& u1) const {
    u0 = pair_.wheel_z.x_min();
    u1 = pair_.wheel_z.x_max();
    const double r0 = pair_.rail_z.x_min(), r1 = pair_.rail_z.x_max();
    if (rail_y(u1) < r0 || rail_y(u0) > r1) return false;
    u0 = invert(r0, u0, u1, true);
    u1 = invert(r1, u0, u1, false);
    return u1 > u0;
  }

  ContactPoint contact_at(double u, bool interior) const {
    const CubicSpline::Value w = pair_.wheel_z.evaluate(u);
    const GapAt g = at(u);
    const CubicSpline::Value r = pair_.rail_z.evaluate(g.Y);
    ContactPoint p;
    p.wheel_u_m = u;
    p.rail_y_m = g.Y;
    p.rail_z_m = r.f;
    p.vertical_gap_m = g.g;
    p.contact_angle_rad = std::atan(r.df);
    p.normal_gap_m = g.g * std::cos(p.contact_angle_rad);
    p.wheel_slope_rad = std::atan(w.df);
    p.rolling_radius_m = pair_.parameters.nominal_rolling_radius_m - w.f;
    p.wheel_curvature_per_m = w.d2f / std::pow(1.0 + w.df * w.df, 1.5);
    p.rail_curvature_per_m = -r.d2f / std::pow(1.0 + r.df * r.df, 1.5);
    p.A_per_m = 0.5 * std::cos(p.wheel_slope_rad) / p.rolling_radius_m;
    p.B_per_m = 0.5 * (p.wheel_curvature_per_m + p.rail_curvature_per_m);
    p.interior = interior;
    return p;
  }

  // Local minimum of g in (a, b) around u_guess: safeguarded Newton on g' = 0
  // when g' changes sign over the bracket, else golden-section search on g.
  double refine(double a, double b, double u_guess) const {
    double ga = at(a).dg, gb = at(b).dg;
    if (ga < 0.0 && gb > 0.0) {
      double u = u_guess;
      for (int it = 0; it < 60; ++it) {
        const GapAt g = at(u);
        if (g.dg < 0.0) a = u; else b = u;
        double next = (g.d2g > 0.0) ? u - g.dg / g.d2g : 0.5 * (a + b);
        if (!(next > a && next < b)) next = 0.5 * (a + b);
        if (std::abs(next - u) < 1e-13) return next;
        u = next;
      }
      return u;
    }
    const double phi = 0.5 * (std::sqrt(5.0) - 1.0);
    double x1 = b - phi * (b - a), x2 = a + phi * (b - a);
    double f1 = at(x1).g, f2 = at(x2).g;
    while (b - a > 1e-12) {
      if (f1 < f2) {
        b = x2, x2 = x1, f2 = f1, x1 = b - phi * (b - a), f1 = at(x1).g;
      } else {
        a = x1, x1 = x2, f1 = f2, x2 = a + phi * (b - a), f2 = at(x2).g;
      }
    }
    return 0.5 * (a + b);
  }

 private:
  // u in [lo, hi] with rail_y(u) = y (bisection; rail_y is increasing).
  double invert(double y, double lo, double hi, bool) const {
    if (rail_y(lo) >= y) return lo;
    if (rail_y(hi) <= y) return hi;
    for (int it = 0; it < 80 && hi - lo > 1e-13; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (rail_y(mid) < y) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
  }

  const ProfilePair& pair_;
  WheelPose pose_;
  double c_, s_;
};

// Samples g uniformly over [u0, u1].
void sample(const GapFunction& f, double u0, double u1, std::vector<double>& u,
            std::vector<double>& g) {
  const int n = std::max(3, int(std::ceil((u1 - u0) / kContactSearchStep_m)) + 1);
  u.resize(n);
  g.resize(n);
  for (int i = 0; i < n; ++i) {
    u[i] = u0 + (u1 - u0) * double(i) / double(n - 1);
    g[i] = f.gap(u[i]);
  }
}

}  // namespace

std::vector<ContactPoint> find_contact_points(const ProfilePair& pair, const WheelPose& pose) {
  const GapFunction f(pair, pose);
  std::vector<ContactPoint> out;
  double u0, u1;
  if (!f.overlap(u0, u1)) return out;
  std::vector<double> u, g;
  sample(f, u0, u1, u, g);
  for (size_t i = 1; i + 1 < u.size(); ++i) {
    if (!(g[i] <= g[i - 1] && g[i] < g[i + 1])) continue;
    const double us = f.refine(u[i - 1], u[i + 1], u[i]);
    out.push_back(f.contact_at(us, true));
  }
  std::sort(out.begin(), out.end(), [](const ContactPoint& a, const ContactPoint& b) {
    return a.vertical_gap_m < b.vertical_gap_m;
  });
  return out;
}

ContactPoint minimum_gap_in_wheel_range(const ProfilePair& pair, const WheelPose& pose,
                                        double u_min, double u_max) {
  const GapFunction f(pair, pose);
  // The whole part of the wheel, not only where it overlaps the rail: beyond
  // its ends the rail continues as the straight line of its end slope (the
  // spline's extension), steeply downwards for a rail head, so the gap there
  // is large and smooth in the pose.
  double u0 = std::max(u_min, pair.wheel_z.x_min());
  double u1 = std::min(u_max, pair.wheel_z.x_max());
  if (!(u1 > u0)) throw std::invalid_argument("minimum_gap_in_wheel_range: empty wheel range");
  std::vector<double> u, g;
  sample(f, u0, u1, u, g);
  const size_t i = size_t(std::min_element(g.begin(), g.end()) - g.begin());
  if (i == 0 || i + 1 == u.size()) {
    // At an end; a minimum just inside is still possible between the end and
    // its neighbour: refine there and keep the lower.
    const size_t j = i == 0 ? 1 : u.size() - 2;
    const double us = f.refine(std::min(u[i], u[j]), std::max(u[i], u[j]), u[j]);
    const double gs = f.at(us).g;
    const bool inside = gs < g[i] - 1e-15 && std::abs(us - u[i]) > 1e-10;
    return f.contact_at(inside ? us : u[i], inside);
  }
  return f.contact_at(f.refine(u[i - 1], u[i + 1], u[i]), true);
}

double maximum_gap_between(const ProfilePair& pair, const WheelPose& pose, double u_a, double u_b) {
  const GapFunction f(pair, pose);
  const double u0 = std::min(u_a, u_b), u1 = std::max(u_a, u_b);
  if (!(u1 > u0)) return f.at(u0).g;
  // The largest sample: g is smooth and flat at its maximum, so a sample
  // within h/2 of it is below it by at most |g''| h^2 / 8, ~1e-8 m for the
  // ~1 1/m curvature differences of wheel and rail at h = 0.25 mm.
  std::vector<double> u, g;
  sample(f, u0, u1, u, g);
  return *std::max_element(g.begin(), g.end());
}

}  // namespace railstab
