#pragma once
// Numeric command-line flags: each is checked against a stated finite range
// while parsing, so nan, inf, 1e20 or a negative band never reach an
// analysis. The message names the flag (CLI11 prefixes "--flag: "), the bad
// value and the range, e.g.
//   --hunting-band: expected a finite number in (0, 1000] Hz, got -1
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace railstab {

struct FlagRange {
  double low, high;
  bool low_open, high_open;  // excluded end points
  std::string unit;          // "m/s", "Hz", "" for dimensionless
};

// "(0, 1000] Hz"
std::string range_text(const FlagRange& range);

// Validator for a double flag (or each element of a list flag).
CLI::Validator finite_in(const FlagRange& range);

// The ranges used by the commands (named so the README and tests share them).
namespace flag_ranges {
// Above the fastest wheel-rail vehicles (~160 m/s), below where the model's
// creepage and contact time scales make no sense.
inline const FlagRange speed_m_per_s{0.0, 300.0, true, false, "m/s"};
inline const FlagRange speed_step_m_per_s{0.01, 300.0, false, false, "m/s"};
inline const FlagRange arc_length_m{-1e6, 1e6, false, false, "m"};
inline const FlagRange frequency_hz{0.0, 1000.0, true, false, "Hz"};
inline const FlagRange list_frequency_hz{0.0, 1e5, true, false, "Hz"};
inline const FlagRange t_end_s{0.0, 1e5, true, false, "s"};
inline const FlagRange relative_tolerance{1e-14, 1.0, false, false, ""};
inline const FlagRange absolute_tolerance{1e-20, 1.0, false, false, "(state units)"};
inline const FlagRange cpu_budget_s{0.0, 86400.0, true, false, "s"};
// Below 1 um the response drowns in integration error; above 10 mm it
// reaches the flange clearance.
inline const FlagRange amplitude_m{1e-6, 0.01, false, false, "m"};
// A wheelset's lateral amplitude for the quasi-linear contact: up to the
// widest contact table a scene may have (the scene's table range is checked
// after reading it).
inline const FlagRange wheelset_amplitude_m{0.0, 0.05, true, false, "m"};
// A periodic orbit's lateral amplitude limit: up to beyond flange contact.
inline const FlagRange orbit_amplitude_m{0.0, 0.05, true, false, "m"};
inline const FlagRange periods{0.0, 1000.0, true, false, "periods"};
inline const FlagRange settle_periods{0.0, 1000.0, false, true, "periods"};
// simulate --ramp-rate: a deceleration above 10 m/s^2 (1 g) is no ramp a
// vehicle runs; --hunting-threshold: the leading wheelset's peak-to-peak
// lateral motion below which the hunting counts as gone.
inline const FlagRange ramp_rate_m_per_s2{0.0, 10.0, true, false, "m/s^2"};
inline const FlagRange hunting_threshold_m{1e-7, 0.02, false, false, "m"};
// A damping-ratio limit: a positive fraction of critical damping.
inline const FlagRange damping_ratio{0.0, 1.0, true, true, ""};
}  // namespace flag_ranges

// A speed grid's size, bounded so a typo (--to 1e9, --step 1e-9) stops with
// a message instead of filling memory.
inline constexpr double kMaxSpeedGridPoints = 10000.0;

// How the caller's interface names the grid: the flags, or the Python
// module's keywords (from_, to, step).
struct SpeedGridNames {
  std::string from = "--from", to = "--to", step = "--step";
};

// Throws std::invalid_argument naming the flags: --from must lie below --to,
// and (to - from) / step + 1 at most kMaxSpeedGridPoints.
void check_speed_grid(double from_m_per_s, double to_m_per_s, double step_m_per_s,
                      const SpeedGridNames& names = {});

// A FROM:TO:STEP-style flag value split at ':' ("a:" gives two fields, the
// last empty, so a trailing colon is not silently dropped).
std::vector<std::string> colon_fields(const std::string& text);

// One field as a number (std::stod over the whole field): not_a_number
// where it does not start with one, trailing_text where text follows it, ok
// with `value` set (possibly not finite: the caller states the range).
enum class FieldNumber { not_a_number, trailing_text, ok };
FieldNumber read_field_number(const std::string& field, double& value);

}  // namespace railstab
