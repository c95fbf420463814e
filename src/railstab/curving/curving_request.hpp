#pragma once
// What a steady-curving run sweeps, from what the user asked for: one value
// or a range of cant deficiency and of radius, resolved against the scene
// (its radius and cant deficiency at the reference point where the user
// gave only the other) into the conditions sweep_steady_curving takes. The
// `curving` command and the Python module's `curving` share it, so both
// accept and refuse the same requests; each names its own flags or
// arguments in the messages (CurvingRequestNames).
#include <railstab/curving/steady_curving.hpp>
#include <railstab/model/model.hpp>

#include <string>
#include <vector>

namespace railstab {

// How the messages name the two quantities and a range: the command line's
// "--cant-deficiency", "--radius", "FROM:TO:STEP" or Python's
// "cant_deficiency", "radius", "(from, to, step)".
struct CurvingRequestNames {
  std::string cant_deficiency = "--cant-deficiency";
  std::string radius = "--radius";
  std::string range = "FROM:TO:STEP";
  std::string from = "FROM", to = "TO", step = "STEP";
  // One value of each, as a message asks for it.
  std::string one_cant_deficiency = "--cant-deficiency H", one_radius = "--radius R";
};

enum class CurvingQuantity { cant_deficiency, radius };
inline constexpr int kMaxCurvingPoints = 1000;

// One value or a range, each value in its quantity's closed range
// (cant deficiency [-0.5, 0.5] m, radius [10, 1e6] m): `fields` holds one
// value or FROM, TO, STEP (STEP > 0), and the values run from FROM towards
// TO (downwards when TO < FROM: a radius sweep from wide to tight curves) up
// to TO within STEP / 1000, at most kMaxCurvingPoints of them. `shown` is the
// request as the user wrote it, repeated in the message. Throws
// std::invalid_argument naming the quantity, what it expects and why.
std::vector<double> curving_values(const std::vector<double>& fields, CurvingQuantity quantity,
                                   const std::string& shown, const CurvingRequestNames& names = {});

// The message of a bad value of `quantity` (also for a field that is not a
// number, which only the command line's text can hold).
std::string curving_value_message(CurvingQuantity quantity, const std::string& shown,
                                  const std::string& why, const CurvingRequestNames& names = {});

// The sweep: its kind, values (m) and the fixed other quantity (m), and the
// scene's own condition at its reference point.
struct CurvingSweepPlan {
  CurvingSweepKind kind = CurvingSweepKind::cant_deficiency;
  std::vector<double> values;
  double fixed = 0.0;
  CurvingCondition scene;
};

// The request's combination, before any scene is read: a range in one of
// the two at most, and at least one of them given. Throws
// std::invalid_argument naming both.
void check_curving_request(const std::vector<double>& cant_deficiencies_m,
                           const std::vector<double>& radii_m, const CurvingRequestNames& names = {});

// From the requested cant deficiencies and radii (each empty, one value or
// a range's values), checked by check_curving_request; an empty one takes
// the scene's value at its reference point (a straight there has neither:
// refused); every condition must need a positive speed. Throws
// std::invalid_argument naming the quantity and what was expected.
CurvingSweepPlan plan_curving_sweep(const Model& model, double scene_speed_m_per_s,
                                    const std::vector<double>& cant_deficiencies_m,
                                    const std::vector<double>& radii_m,
                                    const CurvingRequestNames& names = {});

}  // namespace railstab
