#include <railstab/irregularity/irregularity_psd.hpp>

#include <cmath>

namespace railstab {

namespace {

// ERRI B176 parameters (docs/irregular_track.md).
constexpr double kErriOmegaC = 0.8246, kErriOmegaR = 0.0206, kErriOmegaS = 0.438;
struct ErriLevel {
  double A_a, A_v, A_g;  // m rad
};
constexpr ErriLevel kErriLow{2.119e-7, 4.032e-7, 5.32e-8};
constexpr ErriLevel kErriHigh{6.125e-7, 1.080e-6, 1.032e-7};

// FRA parameters: k, Omega_c, and per class A_v, A_a (cm^2 rad/m) and Omega_s.
constexpr double kFraK = 0.25, kFraOmegaC = 0.8245;
struct FraClass {
  double A_v_cm2, A_a_cm2, omega_s;
};
constexpr FraClass kFraClass4{0.5376, 0.3027, 1.1312};
constexpr FraClass kFraClass5{0.2095, 0.0762, 0.8209};
constexpr FraClass kFraClass6{0.0339, 0.0339, 0.4380};

bool is_erri(IrregularitySpectrum s) {
  return s == IrregularitySpectrum::erri_b176_low || s == IrregularitySpectrum::erri_b176_high;
}
const ErriLevel& erri(IrregularitySpectrum s) {
  return s == IrregularitySpectrum::erri_b176_low ? kErriLow : kErriHigh;
}
const FraClass& fra(IrregularitySpectrum s) {
  return s == IrregularitySpectrum::fra_class_4 ? kFraClass4
         : s == IrregularitySpectrum::fra_class_5 ? kFraClass5
                                                  : kFraClass6;
}

// Integral of 1 / (W^2 + p^2) dW from w1 to w2.
double atan_term(double p, double w1, double w2) { return (std::atan(w2 / p) - std::atan(w1 / p)) / p; }

// Integral of 1 / ((W^2 + a^2)(W^2 + c^2)): partial fractions.
double two_pole_integral(double a, double c, double w1, double w2) {
  return (atan_term(a, w1, w2) - atan_term(c, w1, w2)) / (c * c - a * a);
}

// Integral of W^2 / ((W^2 + r^2)(W^2 + c^2)(W^2 + s^2)): in u = W^2 the
// partial fractions sum_p alpha_p / (W^2 + p^2), alpha_p = -p^2 / prod (q^2 - p^2).
double three_pole_integral(double r, double c, double s, double w1, double w2) {
  const double p2[3] = {r * r, c * c, s * s};
  const double p[3] = {r, c, s};
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    double prod = 1.0;
    for (int j = 0; j < 3; ++j)
      if (j != i) prod *= p2[j] - p2[i];
    sum += -p2[i] / prod * atan_term(p[i], w1, w2);
  }
  return sum;
}

}  // namespace

double irregularity_psd_m2_per_rad_per_m(IrregularitySpectrum spectrum, IrregularityChannel channel,
                                         double w) {
  const double w2 = w * w;
  if (is_erri(spectrum)) {
    const ErriLevel& e = erri(spectrum);
    const double c2 = kErriOmegaC * kErriOmegaC;
    const double base = c2 / ((w2 + kErriOmegaR * kErriOmegaR) * (w2 + c2));
    const double high_pass = w2 / (w2 + kErriOmegaS * kErriOmegaS);
    switch (channel) {
      case IrregularityChannel::alignment: return e.A_a * base;
      case IrregularityChannel::level: return e.A_v * base;
      case IrregularityChannel::cross_level: return 4.0 * e.A_v * base * high_pass;
      case IrregularityChannel::gauge: return e.A_g * base * high_pass;
    }
  }
  const FraClass& f = fra(spectrum);
  const double c2 = kFraOmegaC * kFraOmegaC;
  switch (channel) {
    case IrregularityChannel::alignment: return kFraK * f.A_a_cm2 * 1e-4 * c2 / (w2 * (w2 + c2));
    case IrregularityChannel::level: return kFraK * f.A_v_cm2 * 1e-4 * c2 / (w2 * (w2 + c2));
    case IrregularityChannel::cross_level:
      return 4.0 * kFraK * f.A_v_cm2 * 1e-4 * c2 / ((w2 + c2) * (w2 + f.omega_s * f.omega_s));
    case IrregularityChannel::gauge: return 0.0;
  }
  return 0.0;
}

double irregularity_band_variance_m2(IrregularitySpectrum spectrum, IrregularityChannel channel,
                                     double w1, double w2) {
  if (is_erri(spectrum)) {
    const ErriLevel& e = erri(spectrum);
    const double c2 = kErriOmegaC * kErriOmegaC;
    const double two = c2 * two_pole_integral(kErriOmegaR, kErriOmegaC, w1, w2);
    const double three = c2 * three_pole_integral(kErriOmegaR, kErriOmegaC, kErriOmegaS, w1, w2);
    switch (channel) {
      case IrregularityChannel::alignment: return e.A_a * two;
      case IrregularityChannel::level: return e.A_v * two;
      case IrregularityChannel::cross_level: return 4.0 * e.A_v * three;
      case IrregularityChannel::gauge: return e.A_g * three;
    }
  }
  const FraClass& f = fra(spectrum);
  const double c = kFraOmegaC, c2 = c * c;
  // 1 / (W^2 (W^2 + c^2)) = (1/W^2 - 1/(W^2 + c^2)) / c^2.
  const double one_over_w2 = 1.0 / w1 - 1.0 / w2;
  const double low = c2 * (one_over_w2 - atan_term(c, w1, w2)) / c2;
  switch (channel) {
    case IrregularityChannel::alignment: return kFraK * f.A_a_cm2 * 1e-4 * low;
    case IrregularityChannel::level: return kFraK * f.A_v_cm2 * 1e-4 * low;
    case IrregularityChannel::cross_level:
      return 4.0 * kFraK * f.A_v_cm2 * 1e-4 * c2 * two_pole_integral(c, f.omega_s, w1, w2);
    case IrregularityChannel::gauge: return 0.0;
  }
  return 0.0;
}

}  // namespace railstab
