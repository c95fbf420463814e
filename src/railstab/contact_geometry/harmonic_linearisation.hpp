#pragma once
// Harmonic (describing-function) linearisation of a function f(y) for a
// sinusoidal motion about a centre c with amplitude A,
//   y(theta) = c + A sin(theta),
//   f(y(theta)) ~ f0 + N(A) A sin(theta)   (the bias and first sine harmonic):
//   gain  N(A) = 1/(pi A) integral_0^{2 pi} f(c + A sin th) sin th dth,
//   bias  f0   = 1/(2 pi) integral_0^{2 pi} f(c + A sin th) dth.
// The gain is the slope of the straight line that carries the same
// fundamental harmonic as f over the cycle (for f = k (y - c) + b: N = k at
// every A; f = k y + c3 y^3 about 0: N = k + 3/4 c3 A^2). Equivalently, by
// parts, N(A) = 1/pi integral f'(c + A sin th) cos^2 th dth: the local slope
// averaged over the cycle with the weight 2 cos^2 th / (2 pi), so
// N(A) -> f'(c) as A -> 0 where f is C1. A part of f even about c adds to
// the bias only, not to N.
//
// Quadrature. f(c + A sin th) depends on th through sin th, which takes every
// value of [-1, 1] once on [-pi/2, pi/2] and again on [pi/2, 3 pi/2], so
//   N(A) = 2/(pi A) integral_{-pi/2}^{pi/2} f(c + A sin th) sin th dth,
//   f0   = 1/pi     integral_{-pi/2}^{pi/2} f(c + A sin th) dth.
// [-pi/2, pi/2] is split at the angles th_k = asin((y_k - c) / A) where y
// crosses a breakpoint y_k of f (a table node, a kink of a saturation), and
// each piece is integrated by Gauss-Legendre with kGaussNodesPerPiece nodes.
// Where f is smooth (analytic) between its breakpoints, so is the integrand
// on each piece, and the rule converges exponentially: for a piecewise cubic
// (a Hermite-interpolated table row) or a polynomial of degree d <= 15 in
// y, the integrand is a polynomial in sin th of degree d + 1 on a piece;
// f - f(c) is integrated (no cancellation of a large constant);
// measured error < 1e-13 relative for the tests' cubic, saturation and
// dead zone (tests/contact_geometry/test_harmonic_linearisation.cpp). A
// kink or jump of f that is not given as a breakpoint costs accuracy: the
// piece's error is then O(h^2) (kink) or O(h) (jump) in the piece length h.
#include <functional>
#include <vector>

namespace railstab {

inline constexpr int kGaussNodesPerPiece = 16;

struct HarmonicLinearisation {
  double bias = 0;  // f0: the mean of f over the cycle
  double gain = 0;  // N(A): the first sine harmonic's amplitude / A
};

// f over y = c + A sin(theta); breakpoints_y: where f is not smooth (any
// order; those outside [c - A, c + A] are ignored). Throws
// std::invalid_argument unless A > 0 and finite, and c finite.
HarmonicLinearisation harmonic_linearisation(const std::function<double(double)>& f,
                                             double centre, double amplitude,
                                             const std::vector<double>& breakpoints_y = {});

}  // namespace railstab
