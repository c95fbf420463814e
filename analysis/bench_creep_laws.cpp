// Cost of one creep-law evaluation: linear Kalker, Shen-Hedrick-Elkins and
// Polach, in double and in AdScalar (16 directions, 3 seeded). Each figure
// is the median over 15 repeats of (process CPU time of 2^16 evaluations on
// 256 varied inputs) / 2^16, in ns per evaluation.
//   build/bench_creep_laws
#include "cpu_timing.hpp"
#include <railstab/contact/creep/linear_kalker_creep.hpp>
#include <railstab/contact/creep/polach_creep.hpp>
#include <railstab/contact/creep/shen_hedrick_elkins_creep.hpp>
#include <railstab/contact/kalker.hpp>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <vector>

using namespace railstab;

namespace {

using bench::cpu_seconds;

std::vector<CreepInput<double>> inputs() {
  const CreepCoefficients<double> f = kalker_coefficients(6e-3, 4e-3, 8.4e10, 0.25);
  std::vector<CreepInput<double>> out;
  for (int i = 0; i < 256; ++i) {
    const double s = 1e-5 * (1.0 + (i % 16)) * (i % 3 == 0 ? 100.0 : 1.0);
    CreepInput<double> in;
    in.creep_x = (i % 2 ? s : -0.5 * s);
    in.creep_y = (i % 5 ? 0.7 * s : -s);
    in.creep_spin_per_m = 0.01 * (i % 7 - 3);
    in.normal_force_N = 8e4;
    in.semi_axis_a_m = 6e-3;
    in.semi_axis_b_m = 4e-3;
    in.f11_N = f.f11_N;
    in.f22_N = f.f22_N;
    in.f23_N_m = f.f23_N_m;
    in.f33_N_m2 = f.f33_N_m2;
    in.speed_m_per_s = 30.0;
    out.push_back(in);
  }
  return out;
}

CreepInput<AdScalar> to_ad(const CreepInput<double>& in) {
  const auto c = [](double x) { return constant<AdScalar>(x); };
  CreepInput<AdScalar> o;
  o.creep_x = AdScalar(in.creep_x, AdDerivatives::Unit(0));
  o.creep_y = AdScalar(in.creep_y, AdDerivatives::Unit(1));
  o.creep_spin_per_m = AdScalar(in.creep_spin_per_m, AdDerivatives::Unit(2));
  o.normal_force_N = c(in.normal_force_N);
  o.semi_axis_a_m = c(in.semi_axis_a_m);
  o.semi_axis_b_m = c(in.semi_axis_b_m);
  o.f11_N = c(in.f11_N);
  o.f22_N = c(in.f22_N);
  o.f23_N_m = c(in.f23_N_m);
  o.f33_N_m2 = c(in.f33_N_m2);
  o.speed_m_per_s = c(in.speed_m_per_s);
  return o;
}

double sink = 0.0;  // keeps the evaluations alive

template <class Law, class Input>
double ns_per_evaluation(const Law& law, const std::vector<Input>& in) {
  constexpr int kEvaluations = 1 << 16, kRepeats = 15;
  std::vector<double> samples;
  for (int r = 0; r < kRepeats; ++r) {
    double acc = 0.0;
    const double t0 = cpu_seconds();
    for (int i = 0; i < kEvaluations; ++i) {
      const auto f = law.forces(in[i & 255]);
      acc += value_of(f.force_x_N) + value_of(f.force_y_N) + value_of(f.spin_moment_N_m);
    }
    samples.push_back((cpu_seconds() - t0) / kEvaluations * 1e9);
    sink += acc;
  }
  std::nth_element(samples.begin(), samples.begin() + kRepeats / 2, samples.end());
  return samples[kRepeats / 2];
}

}  // namespace

int main() {
  const std::vector<CreepInput<double>> in = inputs();
  std::vector<CreepInput<AdScalar>> in_ad;
  for (const auto& x : in) in_ad.push_back(to_ad(x));
  const LinearKalkerCreep<double> linear;
  const ShenHedrickElkinsCreep<double> she;
  const PolachCreep<double> polach;
  const double lin_d = ns_per_evaluation(linear, in), lin_ad = ns_per_evaluation(linear, in_ad);
  const double she_d = ns_per_evaluation(she, in), she_ad = ns_per_evaluation(she, in_ad);
  const double pol_d = ns_per_evaluation(polach, in), pol_ad = ns_per_evaluation(polach, in_ad);
  std::printf("creep law evaluation, ns (median of 15 x 65536, CPU time)\n");
  std::printf("%-24s %10s %10s %12s %12s\n", "law", "double", "AdScalar", "x linear(d)", "x linear(AD)");
  std::printf("%-24s %10.1f %10.1f %12.2f %12.2f\n", "linear Kalker", lin_d, lin_ad, 1.0, 1.0);
  std::printf("%-24s %10.1f %10.1f %12.2f %12.2f\n", "Shen-Hedrick-Elkins", she_d, she_ad,
              she_d / lin_d, she_ad / lin_ad);
  std::printf("%-24s %10.1f %10.1f %12.2f %12.2f\n", "Polach (2005 dry)", pol_d, pol_ad,
              pol_d / lin_d, pol_ad / lin_ad);
  std::printf("(checksum %.6e)\n", sink);
  return 0;
}
