#pragma once
// CSV fields per RFC 4180, and numbers that refuse to be non-finite.
//
// A text field (a body, state or mode name) is written bare when it holds
// only printable ASCII other than ',' and '"'; otherwise it is enclosed in
// double quotes with each '"' doubled, which RFC 4180 parsers read back
// unchanged (commas, quotes, tabs and line breaks included). A header
// row may then span several physical lines; csv_physical_lines() says how
// many, for tools that skip lines (gnuplot's `skip`).
#include <cmath>
#include <ostream>
#include <string>
#include <string_view>

namespace railstab {

std::string csv_field(std::string_view text);

// The number with `precision` significant digits; throws std::runtime_error
// naming `what` (e.g. "wheelset1.y_m at t = 0.5 s") if it is NaN or infinite,
// so a non-finite value never reaches a file.
std::string csv_number(double value, std::string_view what, int precision = 10);

[[noreturn]] void throw_non_finite(double value, std::string_view what);

// Streams `value` at the stream's precision; if it is not finite, throws
// naming describe() (called only then, so hot loops build no strings).
template <class Describe>
void put_csv_number(std::ostream& out, double value, const Describe& describe) {
  if (!std::isfinite(value)) throw_non_finite(value, describe());
  out << value;
}

// Number of line breaks in `text` plus one.
int csv_physical_lines(std::string_view text);

}  // namespace railstab
