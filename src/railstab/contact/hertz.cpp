// Hertz normal contact from complete elliptic integrals (ERRATA 7-8).
//
// Notation used below (Johnson, Contact Mechanics, 4.2):
//   m_ax, n_ax  major and minor semi-axes of the contact ellipse; the major
//               axis lies along the direction of the smaller relative curvature
//   k = n_ax / m_ax <= 1,  e^2 = 1 - k^2 (e: eccentricity = elliptic modulus)
//   p = e^2            the elliptic *parameter*; K(e), E(e) are smooth in p
//   rho = max(A, B) / min(A, B) >= 1
// Every Hertz quantity is a smooth function of p, whereas e = sqrt(p) has an
// infinite derivative at the circle. The curvature-ratio equation is therefore
// solved for x = ln(k^2) = ln(1 - p), which keeps both k^2 = exp(x) and
// p = -expm1(x) accurate for nearly circular and for very slender ellipses.
#include <railstab/contact/hertz.hpp>

#include <railstab/core/nested_dual.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace railstab {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEps = std::numeric_limits<double>::epsilon();

// A function g of a scalar x, known at x's value as g and dg/dx, returned as
// scalar T: for AdScalar the derivatives follow the chain rule
// d g = (dg/dx) d x; for double only the value is kept.
template <class T> T with_chain_rule(double value, double slope, const T& x) {
  if constexpr (std::is_same_v<T, double>) {
    return value;
  } else {
    return T(value, slope * x.derivatives());
  }
}

// The complete elliptic integrals at parameter p = e^2 together with two
// cancellation-free combinations (both stay O(1) as p -> 0 and as p -> 1):
//   D(p) = (K - E) / p,   N(p) = (E - (1 - p) K) / p = K - D,
// and their derivatives (from dK/de = E/(e(1-e^2)) - K/e, dE/de = (E-K)/e):
//   dK/dp = N / (2 (1 - p)),   dE/dp = -D / 2,
//   dD/dp = (K - (2 - p) D) / (2 p (1 - p)),   dN/dp = dK/dp - dD/dp.
struct EllipticAtParameter {
  double K, E, D, N;
  double dK_dp, dE_dp, dD_dp, dN_dp;
};

// Below this parameter dD/dp comes from its power series; above it the
// direct formula loses at most a few bits.
constexpr double kSeriesParameterLimit = 0.1;

// D(p) = (pi/2) sum_{j>=1} w_j p^(j-1),  w_j = c_j^2 2j/(2j-1),
// c_j = (1/2)_j / j! = prod_{i<=j} (2i-1)/(2i)  (from the hypergeometric
// series of K and E). Returns D and dD/dp.
void d_integral_series(double p, double& D, double& dD_dp) {
  double sum = 0.0, slope_sum = 0.0;
  double c = 1.0;           // c_j
  double p_power = 1.0;     // p^(j-1)
  double p_power_m1 = 0.0;  // (j-1) p^(j-2)
  for (int j = 1; j < 400; ++j) {
    c *= (2.0 * j - 1.0) / (2.0 * j);
    const double w = c * c * (2.0 * j) / (2.0 * j - 1.0);
    const double term = w * p_power;
    sum += term;
    slope_sum += w * p_power_m1;
    // Stop when the next terms of both series are below rounding (the slope
    // series carries an extra factor j).
    if (j > 2 && term * j <= 0.1 * kEps * std::min(sum, slope_sum)) break;
    p_power_m1 = j * p_power;  // becomes j p^(j-1) for the next index j+1
    p_power *= p;
  }
  D = 0.5 * kPi * sum;
  dD_dp = 0.5 * kPi * slope_sum;
}

// K and D = (K - E)/p by the arithmetic-geometric mean (quadratic
// convergence: 4-6 square roots to full precision; this is the hot path of
// every wheel contact). With a_0 = 1, b_0 = k' = sqrt(1 - p), c_0^2 = p:
//   K = pi / (2 a_inf),  K - E = K sum_{n>=0} 2^(n-1) c_n^2,
// and c_1 = p / (2 (1 + k')), c_{n+1} = c_n^2 / (4 a_{n+1}) avoid the
// cancellation of (a_n - b_n) / 2, so D = K sum 2^(n-1) c_n^2 / p is exact
// to rounding at every p.
void elliptic_by_agm(double p, double complement, double& K, double& D) {
  double a = 1.0, b = std::sqrt(complement);
  double q = 1.0;        // c_n^2 / p, n = 0
  double weight = 0.5;   // 2^(n-1)
  double sum = weight * q;
  double c = p / (2.0 * (1.0 + b));  // c_1
  for (int n = 1; n < 40; ++n) {
    const double a_next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = a_next;
    weight *= 2.0;
    q = c * c / p;
    const double term = weight * q;
    sum += term;
    if (term <= 0.25 * kEps * sum) break;
    c = c * c / (4.0 * (0.5 * (a + b)));  // c_{n+1} = c_n^2 / (4 a_{n+1})
  }
  K = 0.5 * kPi / a;
  D = K * sum;
}

// p and its complement 1 - p are passed separately: either may be tiny.
EllipticAtParameter elliptic_at_parameter(double p, double complement) {
  EllipticAtParameter r{};
  if (p == 0.0) {
    r.K = r.E = 0.5 * kPi;
    d_integral_series(p, r.D, r.dD_dp);
  } else {
    elliptic_by_agm(p, complement, r.K, r.D);
    r.E = r.K - p * r.D;
    if (p < kSeriesParameterLimit) {
      double D_series;
      d_integral_series(p, D_series, r.dD_dp);
    } else {
      r.dD_dp = (r.K - (1.0 + complement) * r.D) / (2.0 * p * complement);
    }
  }
  r.N = r.K - r.D;
  r.dK_dp = r.N / (2.0 * complement);
  r.dE_dp = -0.5 * r.D;
  r.dN_dp = r.dK_dp - r.dD_dp;
  return r;
}

// --- Curvature ratio as a function of x = ln(k^2) ------------------------
// rho = [(1/k^2) E - K] / [K - E] = N / (k^2 D), hence
//   ln rho = ln N - x - ln D,
//   d ln rho / dx = -k^2 (N'/N - D'/D) - 1   (' = d/dp, dp/dx = -k^2).
struct CurvatureRatioModel {
  double log_ratio;  // ln rho(x)
  double slope;      // d ln rho / dx  (< 0: rho grows as the ellipse narrows)
  double k_squared, parameter;
  EllipticAtParameter integrals;
};

CurvatureRatioModel curvature_ratio_model(double x) {
  CurvatureRatioModel c{};
  c.k_squared = std::exp(x);
  c.parameter = -std::expm1(x);
  c.integrals = elliptic_at_parameter(c.parameter, c.k_squared);
  const EllipticAtParameter& I = c.integrals;
  c.log_ratio = std::log(I.N / I.D) - x;
  c.slope = -c.k_squared * (I.dN_dp / I.N - I.dD_dp / I.D) - 1.0;
  return c;
}

[[noreturn]] void throw_not_converged(double ratio) {
  std::ostringstream msg;
  msg << "hertz_shape: the curvature-ratio equation did not converge for B/A or A/B = "
      << ratio;
  throw std::runtime_error(msg.str());
}

// Solves ln rho(x) = ln(ratio) for x = ln(k^2) <= 0 in double precision:
// Newton's method inside a bracket [lo, hi] with bisection whenever a Newton
// step leaves the bracket. ln rho(x) is decreasing, about -3x/4 near the
// circle (x -> 0) and about -x for slender ellipses, so Newton is nearly
// linear-exact at both ends. Start: the classic k ~ rho^(-2/3).
double solve_log_k_squared(double ratio) {
  const double target = std::log(ratio);
  if (target <= 0.0) return 0.0;  // circle: k = 1
  auto residual = [&](double x) { return curvature_ratio_model(x).log_ratio - target; };

  const double start = -4.0 / 3.0 * target;
  double hi = 0.0;  // residual(0) = -target < 0
  double lo = start;
  for (int expand = 0; residual(lo) < 0.0; ++expand) {
    if (expand > 60) throw_not_converged(ratio);
    hi = lo;
    lo = 2.0 * lo - 1.0;
  }

  double x = start;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const CurvatureRatioModel model = curvature_ratio_model(x);
    const double f = model.log_ratio - target;
    if (f == 0.0) return x;
    if (f > 0.0) lo = x; else hi = x;
    double next = x - f / model.slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    // ln rho has an absolute rounding error of a few eps and |slope| >= ~3/4,
    // so x is determined to an absolute few eps (relative for |x| > 1).
    if (std::abs(next - x) <= 4.0 * kEps * std::max(1.0, std::abs(x))) return next;
    x = next;
  }
  throw_not_converged(ratio);
}

void require_positive_curvatures(double A, double B) {
  if (!(A > 0.0) || !(B > 0.0) || !std::isfinite(A) || !std::isfinite(B)) {
    std::ostringstream msg;
    msg << "hertz_shape: relative curvatures must be positive and finite, got A = " << A
        << " 1/m, B = " << B << " 1/m";
    throw std::domain_error(msg.str());
  }
}

void require_positive_modulus(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    std::ostringstream msg;
    msg << what << " must be positive and finite, got " << value << " Pa";
    throw std::invalid_argument(msg.str());
  }
}

void require_poisson_ratio(double nu, const char* what) {
  if (!(nu >= 0.0 && nu < 0.5)) {
    std::ostringstream msg;
    msg << what << " must lie in [0, 0.5), got " << nu;
    throw std::invalid_argument(msg.str());
  }
}

// K(e) and E(e) at parameter p = e^2 = 1 - k^2 by the arithmetic-geometric
// mean in T's own arithmetic (Gauss): K = pi / (2 M(1, k)),
// E = K (1 - sum_n 2^(n-1) c_n^2), c_0^2 = p, c_(n+1) = (a_n - b_n)/2.
// Slower than the tabulated-derivative path, but every derivative of any
// order follows exactly: used for the parameter-derivative scalars (Dual),
// whose mixed second derivatives the chain-rule shortcut would miss.
template <class T> void elliptic_by_agm(const T& k_squared, const T& p, T& K, T& E) {
  using std::sqrt;
  T a = T(1.0), b = sqrt(k_squared);
  T sum = 0.5 * p;
  double weight = 0.5;
  for (int n = 0; n < 60; ++n) {
    const T c = 0.5 * (a - b);
    const T a_next = 0.5 * (a + b);
    b = sqrt(a * b);
    a = a_next;
    weight *= 2.0;
    sum += weight * c * c;
    // Converged in value; two more rounds let the derivatives settle too.
    if (std::abs(value_of(c)) < 1e-17 * value_of(a) && n > 2) {
      if (n > 60) break;
      for (int extra = 0; extra < 2; ++extra) {
        const T c2 = 0.5 * (a - b);
        const T a2 = 0.5 * (a + b);
        b = sqrt(a * b);
        a = a2;
        weight *= 2.0;
        sum += weight * c2 * c2;
      }
      break;
    }
  }
  K = kPi / (2.0 * a);
  E = K * (1.0 - sum);
}

// ln rho(x) in T's arithmetic: rho = (E / k^2 - K) / (K - E), x = ln k^2.
template <class T> T log_curvature_ratio(const T& x) {
  using std::exp;
  using std::log;
  const T k_squared = exp(x);
  const T p = 1.0 - k_squared;
  T K, E;
  elliptic_by_agm(k_squared, p, K, E);
  return log((E / k_squared - K) / (K - E));
}

}  // namespace

ElasticPair combine_materials(double young1_Pa, double poisson1, double young2_Pa,
                              double poisson2) {
  require_positive_modulus(young1_Pa, "combine_materials: Young's modulus of body 1");
  require_positive_modulus(young2_Pa, "combine_materials: Young's modulus of body 2");
  require_poisson_ratio(poisson1, "combine_materials: Poisson ratio of body 1");
  require_poisson_ratio(poisson2, "combine_materials: Poisson ratio of body 2");

  // E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)
  const double compliance = (1.0 - poisson1 * poisson1) / young1_Pa +
                            (1.0 - poisson2 * poisson2) / young2_Pa;
  // G_i = E_i / (2 (1 + nu_i)),  2/G = 1/G1 + 1/G2,  nu = (G/2)(nu1/G1 + nu2/G2)
  const double shear1 = young1_Pa / (2.0 * (1.0 + poisson1));
  const double shear2 = young2_Pa / (2.0 * (1.0 + poisson2));
  const double shear = 2.0 / (1.0 / shear1 + 1.0 / shear2);
  const double poisson = 0.5 * shear * (poisson1 / shear1 + poisson2 / shear2);
  return ElasticPair{1.0 / compliance, shear, poisson};
}

// K(k) with dK/dk = E/(k(1-k^2)) - K/k = k (K - D)/(1 - k^2), D = (K-E)/k^2;
// the second form has no cancellation as k -> 0 (limit pi k/4 + 9 pi k^3/32).
template <class T> T elliptic_K(const T& k) {
  const double modulus = value_of(k);
  if (!(std::abs(modulus) < 1.0)) {
    std::ostringstream msg;
    msg << "elliptic_K: modulus must satisfy |k| < 1, got " << modulus;
    throw std::domain_error(msg.str());
  }
  const double p = modulus * modulus;
  const EllipticAtParameter I = elliptic_at_parameter(p, 1.0 - p);
  return with_chain_rule(I.K, 2.0 * modulus * I.dK_dp, k);  // dK/dk = 2k dK/dp
}

// E(k) with dE/dk = (E - K)/k = -k D (limit -pi k/4 - 3 pi k^3/32).
template <class T> T elliptic_E(const T& k) {
  const double modulus = value_of(k);
  if (!(std::abs(modulus) <= 1.0)) {
    std::ostringstream msg;
    msg << "elliptic_E: modulus must satisfy |k| <= 1, got " << modulus;
    throw std::domain_error(msg.str());
  }
  if (std::abs(modulus) == 1.0) {
    // E(1) = 1 with an infinite slope; only the value is meaningful.
    return with_chain_rule(1.0, std::copysign(std::numeric_limits<double>::infinity(),
                                              modulus),
                           k);
  }
  const double p = modulus * modulus;
  const EllipticAtParameter I = elliptic_at_parameter(p, 1.0 - p);
  return with_chain_rule(I.E, 2.0 * modulus * I.dE_dp, k);  // dE/dk = 2k dE/dp
}

template <class T> HertzShape<T> hertz_shape(const T& A_per_m, const T& B_per_m,
                                             double effective_modulus_Pa) {
  using std::log;
  using std::pow;
  using std::sqrt;
  require_positive_curvatures(value_of(A_per_m), value_of(B_per_m));
  require_positive_modulus(effective_modulus_Pa, "hertz_shape: effective modulus E*");

  // The major axis lies along the smaller curvature: along x (a) when A < B.
  const bool major_axis_along_x = value_of(A_per_m) < value_of(B_per_m);
  const T ratio = major_axis_along_x ? T(B_per_m / A_per_m) : T(A_per_m / B_per_m);

  // Root x0 = ln(k^2) in double, then the implicit function theorem for the
  // derivatives: x = x0 + (ln rho - ln rho(x0)) / (d ln rho/dx). The value of
  // the correction is exactly zero; AdScalar picks up dx = d(ln rho)/slope.
  const double x0 = solve_log_k_squared(value_of(ratio));
  const CurvatureRatioModel at_root = curvature_ratio_model(x0);
  T K, E, k_squared;
  if constexpr (IsDual<T>::value) {
    // Parameter-derivative scalars need exact second derivatives: two
    // chord steps from the double root (each adds one exact order: the
    // error after n steps is O(eps^(n+1)) in the derivative directions),
    // then K, E by the AGM in T. Dual3 (third derivatives) takes three.
    using std::exp;
    constexpr int chord_steps = DualDepth<T>::value > 2 ? DualDepth<T>::value : 2;
    T x = T(x0);
    for (int step = 0; step < chord_steps; ++step)
      x = x - (log_curvature_ratio(x) - log(ratio)) / at_root.slope;
    k_squared = exp(x);
    elliptic_by_agm(k_squared, T(1.0 - k_squared), K, E);
  } else {
    const T log_k_squared = x0 + (log(ratio) - log(value_of(ratio))) / at_root.slope;
    // K(e), E(e) and k^2 as functions of x (dp/dx = -k^2, dk^2/dx = k^2).
    const EllipticAtParameter& I = at_root.integrals;
    const double k2 = at_root.k_squared;
    K = with_chain_rule(I.K, -k2 * I.dK_dp, log_k_squared);
    E = with_chain_rule(I.E, -k2 * I.dE_dp, log_k_squared);
    k_squared = with_chain_rule(k2, k2, log_k_squared);
  }
  const T k = sqrt(k_squared);

  const T curvature_sum = A_per_m + B_per_m;  // A + B
  const double Estar = effective_modulus_Pa;

  HertzShape<T> shape;
  // K_H = (2 pi/3) E* sqrt(E) / (k sqrt(A+B) K^(3/2))
  shape.stiffness = (2.0 * kPi / 3.0) * Estar * sqrt(E) / (k * sqrt(curvature_sum) * K * sqrt(K));
  // major semi-axis m_ax = [3 F E / (2 pi k^2 (A+B) E*)]^(1/3)
  const T major_per_force_13 = pow(3.0 * E / (2.0 * kPi * k_squared * curvature_sum * Estar),
                                   1.0 / 3.0);
  const T minor_per_force_13 = k * major_per_force_13;
  // delta = (A+B) k^2 m_ax^2 K / E, i.e. F^(2/3) times this constant
  // (equal to K_H^(-2/3): the same law F = K_H delta^(3/2)).
  shape.approach_per_force_23 =
      curvature_sum * k_squared * major_per_force_13 * major_per_force_13 * K / E;

  if (major_axis_along_x) {
    shape.semi_axis_a_per_force_13 = major_per_force_13;
    shape.semi_axis_b_per_force_13 = minor_per_force_13;
    shape.a_over_b = 1.0 / k;
  } else {
    shape.semi_axis_a_per_force_13 = minor_per_force_13;
    shape.semi_axis_b_per_force_13 = major_per_force_13;
    shape.a_over_b = k;
  }
  return shape;
}

template HertzShape<double> hertz_shape(const double&, const double&, double);
template HertzShape<AdScalar> hertz_shape(const AdScalar&, const AdScalar&, double);
template HertzShape<ParamDual> hertz_shape(const ParamDual&, const ParamDual&, double);
template HertzShape<ParamAdScalar> hertz_shape(const ParamAdScalar&, const ParamAdScalar&,
                                               double);
template HertzShape<Dual3> hertz_shape(const Dual3&, const Dual3&, double);
template double elliptic_K(const double&);
template AdScalar elliptic_K(const AdScalar&);
template double elliptic_E(const double&);
template AdScalar elliptic_E(const AdScalar&);

}  // namespace railstab
