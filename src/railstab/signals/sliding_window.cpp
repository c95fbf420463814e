#include <railstab/signals/sliding_window.hpp>

#include <cmath>
#include <stdexcept>

namespace railstab {

namespace {

template <class Reduce>
std::vector<WindowValue> sliding(const std::vector<double>& s, const std::vector<double>& x, double length,
                                 double step, Reduce reduce) {
  if (s.size() != x.size() || !(length > 0.0) || !(step > 0.0))
    throw std::invalid_argument("sliding window: expected equal sizes and a positive length and step");
  for (size_t i = 1; i < s.size(); ++i)
    if (!(s[i] > s[i - 1])) throw std::invalid_argument("sliding window: the distances must increase");
  std::vector<WindowValue> windows;
  if (s.empty()) return windows;
  size_t first = 0;
  for (int j = 0;; ++j) {
    const double a = s.front() + j * step, b = a + length;
    if (b > s.back() + 1e-9 * length) break;
    while (first < s.size() && s[first] < a) ++first;
    double sum = 0.0;
    int n = 0;
    for (size_t i = first; i < s.size() && s[i] < b; ++i, ++n) sum += reduce(x[i]);
    if (n == 0) continue;
    windows.push_back({a, b, sum / n, n});
  }
  return windows;
}

}  // namespace

std::vector<WindowValue> sliding_rms(const std::vector<double>& s, const std::vector<double>& x, double length,
                                     double step) {
  std::vector<WindowValue> w = sliding(s, x, length, step, [](double v) { return v * v; });
  for (WindowValue& v : w) v.value = std::sqrt(v.value);
  return w;
}

std::vector<WindowValue> sliding_mean(const std::vector<double>& s, const std::vector<double>& x, double length,
                                      double step) {
  return sliding(s, x, length, step, [](double v) { return v; });
}

}  // namespace railstab
