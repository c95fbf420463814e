#include "cli/curving_command.hpp"

#include "cli/numeric_flags.hpp"
#include "cli/scene_command.hpp"
#include <railstab/curving/curving_request.hpp>
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

// VALUE or FROM:TO:STEP as text: the fields read as numbers here, the values
// and their checks are the library's (curving_request.hpp).
std::vector<double> parse_values(const std::string& text, CurvingQuantity q) {
  const std::vector<std::string> parts = colon_fields(text);
  auto fail = [&](const std::string& why) {
    throw std::invalid_argument(curving_value_message(q, text, why));
  };
  if (parts.size() != 1 && parts.size() != 3) fail("not one value or three fields");
  const char* what[] = {parts.size() == 1 ? "the value" : "FROM", "TO", "STEP"};
  std::vector<double> fields;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    double v = 0;
    const FieldNumber read = read_field_number(parts[k], v);
    if (read == FieldNumber::not_a_number) fail(std::string(what[k]) + " is not a number");
    if (read != FieldNumber::ok || !std::isfinite(v))
      fail(std::string(what[k]) + " is not a finite number");
    fields.push_back(v);
  }
  return curving_values(fields, q, text);
}

void run_curving(const CurvingArgs& a) {
  const std::vector<double> deficiencies =
      a.cant_deficiency.empty() ? std::vector<double>{}
                                : parse_values(a.cant_deficiency, CurvingQuantity::cant_deficiency);
  const std::vector<double> radii =
      a.radius.empty() ? std::vector<double>{} : parse_values(a.radius, CurvingQuantity::radius);
  check_curving_request(deficiencies, radii);  // before the scene is read

  const SceneSpec spec = load_scene_with_overrides(a.scene, a.overrides);
  const Model model = build_model(spec);
  const CurvingSweepPlan plan = plan_curving_sweep(model, spec.speed_m_per_s, deficiencies, radii);
  const CurvingCondition& scene = plan.scene;
  const bool radius_sweep = plan.kind == CurvingSweepKind::radius;
  const std::vector<double>& values = plan.values;
  std::cerr << "steady curving of " << model.name << ": " << values.size() << " condition(s), "
            << (radius_sweep ? "radius" : "cant deficiency") << " swept, cant "
            << scene.cant_m * 1e3 << " mm\n";
  const CurvingSweep sweep =
      sweep_steady_curving(model, plan.kind, values, plan.fixed, spec.assessment.prudhomme_factor);
  OutputSet outputs(a.out_dir);
  const std::string summary =
      write_curving_results(model, sweep, plan.kind, outputs, scene_file_stem(a.scene));
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
