#include "cli/curving_command.hpp"

#include "cli/numeric_flags.hpp"
#include "cli/scene_command.hpp"
#include <railstab/curving/steady_curving.hpp>
#include <railstab/io/file_names.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/report/curving_report.hpp>
#include <railstab/setup/build_model.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <cmath>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <vector>

namespace railstab {

namespace {

struct CurvingArgs : SceneCommandArgs {
  std::string cant_deficiency;  // VALUE or FROM:TO:STEP, metres
  std::string radius;           // VALUE or FROM:TO:STEP, metres
};

inline constexpr int kMaxCurvingPoints = 1000;

// What each flag accepts, said in its messages.
struct Quantity {
  const char* flag;
  double low, high;  // closed range of every value
  const char* range;
};
constexpr Quantity kCantDeficiency{"--cant-deficiency", -0.5, 0.5, "in [-0.5, 0.5] m"};
constexpr Quantity kRadius{"--radius", 10.0, 1e6, "in [10, 1e6] m"};

// VALUE or FROM:TO:STEP: the values FROM, FROM +- STEP, ... up to TO (within
// STEP / 1000). STEP > 0; the values run from FROM towards TO, downwards
// when TO < FROM (a radius sweep from wide to tight curves).
std::vector<double> parse_values(const std::string& text, const Quantity& q) {
  auto fail = [&](const std::string& why) {
    throw std::invalid_argument(std::string(q.flag) + ": expected a value or FROM:TO:STEP in metres, each " +
                                q.range + " (STEP > 0), got '" + text + "': " + why);
  };
  const std::vector<std::string> parts = colon_fields(text);
  if (parts.size() != 1 && parts.size() != 3) fail("not one value or three fields");
  auto number = [&](const std::string& p, const char* what) {
    double v = 0;
    const FieldNumber read = read_field_number(p, v);
    if (read == FieldNumber::not_a_number) fail(std::string(what) + " is not a number");
    if (read != FieldNumber::ok || !std::isfinite(v))
      fail(std::string(what) + " is not a finite number");
    return v;
  };
  auto in_range = [&](double v, const char* what) {
    if (!(v >= q.low && v <= q.high)) fail(std::string(what) + " is outside the range");
    return v;
  };
  if (parts.size() == 1) return {in_range(number(parts[0], "the value"), "the value")};
  const double from = in_range(number(parts[0], "FROM"), "FROM");
  const double to = in_range(number(parts[1], "TO"), "TO");
  const double step = number(parts[2], "STEP");
  if (!(step > 0.0)) fail("STEP is not positive");
  if (std::abs(to - from) / step + 1 > kMaxCurvingPoints)
    fail("more than " + std::to_string(kMaxCurvingPoints) + " values");
  const double direction = to >= from ? 1.0 : -1.0;
  std::vector<double> values;
  for (int i = 0;; ++i) {
    const double v = from + direction * i * step;
    if (direction * (v - to) > 1e-3 * step) break;
    values.push_back(v);
  }
  return values;
}

void run_curving(const CurvingArgs& a) {
  const std::vector<double> deficiencies =
      a.cant_deficiency.empty() ? std::vector<double>{} : parse_values(a.cant_deficiency, kCantDeficiency);
  const std::vector<double> radii = a.radius.empty() ? std::vector<double>{} : parse_values(a.radius, kRadius);
  if (deficiencies.size() > 1 && radii.size() > 1)
    throw std::invalid_argument(
        "--cant-deficiency and --radius: expected a range in one of them at most (the other one "
        "value), got two ranges");
  if (deficiencies.empty() && radii.empty())
    throw std::invalid_argument(
        "curving: expected --cant-deficiency FROM:TO:STEP (m, at the scene's radius or --radius R) "
        "or --radius FROM:TO:STEP (m, at the scene's cant deficiency or --cant-deficiency H)");

  const SceneSpec spec = load_scene_with_overrides(a.scene, a.overrides);
  const Model model = build_model(spec);
  const double D = model.track.spec().rail_contact_distance_m, g = model.gravity_m_per_s2;
  const CurvingCondition scene = condition_at_reference(model, spec.speed_m_per_s);
  const bool radius_sweep = radii.size() > 1 || deficiencies.empty();
  const CurvingSweepKind kind = radius_sweep ? CurvingSweepKind::radius : CurvingSweepKind::cant_deficiency;
  double fixed = 0.0;
  if (radius_sweep) {
    if (!deficiencies.empty()) {
      fixed = deficiencies.front();
    } else {
      if (scene.curvature_per_m == 0.0)
        throw std::invalid_argument(
            "--radius: the scene's reference point is on a straight, so it has no cant deficiency "
            "to keep: give --cant-deficiency H (m)");
      fixed = cant_deficiency_m(scene, D, g);
    }
  } else {
    if (!radii.empty()) {
      fixed = radii.front();
    } else {
      if (scene.curvature_per_m == 0.0)
        throw std::invalid_argument(
            "--cant-deficiency: the scene's reference point is on a straight: give --radius R (m)");
      fixed = 1.0 / std::abs(scene.curvature_per_m);
    }
  }
  const std::vector<double>& values = radius_sweep ? radii : deficiencies;
  // Every condition must have a positive speed: said before any solve, naming the flag.
  for (double v : values) {
    const double R = radius_sweep ? v : fixed, h_d = radius_sweep ? fixed : v;
    try {
      (void)speed_for_cant_deficiency(1.0 / R, scene.cant_m, h_d, D, g);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string(radius_sweep && deficiencies.empty() ? "--radius" : "--cant-deficiency") +
                                  ": " + e.what());
    }
  }
  std::cerr << "steady curving of " << model.name << ": " << values.size() << " condition(s), "
            << (radius_sweep ? "radius" : "cant deficiency") << " swept, cant "
            << scene.cant_m * 1e3 << " mm\n";
  const CurvingSweep sweep =
      sweep_steady_curving(model, kind, values, fixed, spec.assessment.prudhomme_factor);
  OutputSet outputs(a.out_dir);
  const std::string summary = write_curving_results(model, sweep, kind, outputs, scene_file_stem(a.scene));
  std::cout << summary;
  list_written(outputs.commit(), std::cout);
}

}  // namespace

void register_curving_command(CLI::App& app) {
  auto a = std::make_shared<CurvingArgs>();
  CLI::App* cmd = app.add_subcommand(
      "curving",
      "steady curving over cant deficiency or radius: wheel forces Y, Q, Y/Q, Sum Y, angle of "
      "attack, lateral shifts, flange contact per wheelset, to the flange-climbing limit");
  SceneFlags flags;
  flags.arc_length = true;
  flags.arc_length_help =
      "arc length (m) of the scene's reference point, where its radius and cant are taken "
      "(e.g. 2000 inside the thesis cases' arc)";
  add_scene_flags(cmd, *a, flags);
  cmd->add_option("--cant-deficiency", a->cant_deficiency,
                  "cant deficiency h_d = D V^2 / (g R) - h in m (negative: cant excess): one value "
                  "or FROM:TO:STEP; the speed follows from it");
  cmd->add_option("--radius", a->radius,
                  "curve radius in m: one value or FROM:TO:STEP (default: the scene's at its "
                  "reference point); the turn and the cant are the scene's");
  cmd->callback([a] { run_curving(*a); });
}

}  // namespace railstab
