#pragma once
// The root of a scalar function near a guess: a bracket grown from
// [guess - initial_half_width, guess + initial_half_width] (the side with
// the smaller |f| moved out by the bracket's width, at most `max_expansions`
// times), then the Illinois variant of regula falsi (the retained end's value
// halved when the same end is kept twice: superlinear and never slower than
// bisection; Dowell and Jarratt, BIT 11, 1971) to a bracket below 1e-14 or
// |f| below 1e-14. The rigid contact of a profile pair and of a contact table
// (the roll at which both wheels touch) share it.
#include <cmath>

namespace railstab {

struct BracketedRoot {
  double x = 0.0;
  bool bracketed = false;       // false: no sign change within the grown bracket
  double half_width = 0.0;      // of the last bracket tried (for the message)
};

template <class F>
BracketedRoot bracketed_root(F&& f, double guess, double initial_half_width = 1e-3,
                             int max_expansions = 12) {
  BracketedRoot r;
  double a = guess - initial_half_width, b = guess + initial_half_width;
  double fa = f(a), fb = f(b);
  for (int expand = 0; fa * fb > 0.0; ++expand) {
    if (expand > max_expansions) {
      r.half_width = b - guess;
      return r;
    }
    const double w = b - a;
    if (std::abs(fa) < std::abs(fb)) a -= w, fa = f(a);
    else b += w, fb = f(b);
  }
  int side = 0;
  double x = a;
  for (int it = 0; it < 100; ++it) {
    x = (a * fb - b * fa) / (fb - fa);
    if (!(x > a && x < b)) x = 0.5 * (a + b);
    const double fx = f(x);
    if (fx == 0.0 || b - a < 1e-14) break;
    if (fx * fb > 0.0) {
      b = x, fb = fx;
      if (side == -1) fa *= 0.5;
      side = -1;
    } else {
      a = x, fa = fx;
      if (side == +1) fb *= 0.5;
      side = +1;
    }
    if (std::abs(fx) < 1e-14) break;
  }
  r.x = x;
  r.bracketed = true;
  r.half_width = 0.5 * (b - a);
  return r;
}

}  // namespace railstab
