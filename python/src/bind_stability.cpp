// critical_speed, eigen, equilibrium, curving and sensitivity: each prepares
// the scene and calls the library as its command does (src/cli/
// stability_commands.cpp, curving_command.cpp, sensitivity_command.cpp),
// without the GIL; the command's writers render the JSON
// (written_files.hpp); the numbers behind it come back as numpy arrays at
// full precision.
#include "arguments.hpp"
#include "bindings.hpp"
#include "numpy_arrays.hpp"
#include "model_warnings.hpp"
#include "progress_relay.hpp"
#include "written_files.hpp"

#include <railstab/curving/curving_request.hpp>
#include <railstab/curving/steady_curving.hpp>
#include <railstab/io/file_names.hpp>
#include <railstab/nonlinear/hopf_assessment.hpp>
#include <railstab/report/curving_report.hpp>
#include <railstab/report/eigen_report.hpp>
#include <railstab/report/equilibrium_report.hpp>
#include <railstab/report/run_conditions.hpp>
#include <railstab/report/sensitivity_report.hpp>
#include <railstab/report/stability_report.hpp>
#include <railstab/sensitivity/sensitivity_run.hpp>
#include <railstab/setup/build_model.hpp>
#include <railstab/stability/point_mode_shapes.hpp>
#include <railstab/stability/quasi_linear_critical_speed.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <pybind11/stl.h>

#include <charconv>
#include <optional>
#include <string>

namespace py = pybind11;

namespace railstab::python {

namespace {

// The eigen-analysis over the grid as the eigenvalue CSV's columns, one row
// per (speed, mode): speed, mode_track (the same mode across speeds),
// eigenvalue (complex), frequency, damping ratio, neutral, residual, name.
py::dict eigenvalue_table(const CriticalSpeedResult& r) {
  std::vector<double> speed, frequency, damping, residual;
  std::vector<std::complex<double>> eigenvalue;
  std::vector<int> track;
  std::vector<bool> neutral;
  py::list names;
  for (std::size_t i = 0; i < r.grid.size(); ++i)
    for (std::size_t j = 0; j < r.grid[i].modes.size(); ++j) {
      const ModeReport& m = r.grid[i].modes[j];
      speed.push_back(r.grid[i].speed_m_per_s);
      track.push_back(r.mode_tracks[i][j]);
      eigenvalue.push_back(m.eigenvalue);
      frequency.push_back(m.frequency_hz);
      damping.push_back(m.damping_ratio);
      neutral.push_back(m.neutral);
      residual.push_back(m.residual);
      names.append(m.name);
    }
  py::array_t<bool> neutral_array(py::ssize_t(neutral.size()));
  for (std::size_t k = 0; k < neutral.size(); ++k) neutral_array.mutable_at(k) = neutral[k];
  py::dict t;
  t["speed_m_per_s"] = array_of(speed);
  t["mode_track"] = array_of(track);
  t["eigenvalue_per_s"] = array_of(eigenvalue);
  t["frequency_Hz"] = array_of(frequency);
  t["damping_ratio"] = array_of(damping);
  t["neutral"] = neutral_array;
  t["residual"] = array_of(residual);
  t["name"] = names;
  return t;
}

// The sensitivity analysis's options from the Python keywords (the messages
// name `keys_name` and from_/to).
SensitivityRunOptions sensitivity_options(std::vector<std::string> keys, double from, double to,
                                          double step, double hunting_band,
                                          std::function<void(const std::string&)> progress,
                                          const std::string& keys_name) {
  SensitivityRunOptions o;
  o.keys = std::move(keys);
  o.from_m_per_s = from;
  o.to_m_per_s = to;
  o.grid_step_m_per_s = step;
  o.hunting_band_hz = hunting_band;
  o.progress = std::move(progress);
  o.keys_name = keys_name;
  o.range_name = "from_/to";
  return o;
}

py::dict gradient_of(const CriticalSpeedSensitivities& s) {
  py::dict g;
  for (const ParameterSensitivity& p : s.parameters) g[py::str(p.key)] = p.critical_speed_derivative;
  return g;
}

py::dict critical_speed(const std::string& scene, const std::vector<std::string>& settings,
                        std::optional<double> arc_length, double from, double to, double step,
                        const std::string& solver, double hunting_band,
                        std::optional<double> min_damping_ratio,
                        std::optional<std::vector<std::string>> gradient,
                        std::optional<double> amplitude, py::object progress) {
  check_speed_grid(from, to, step);
  check_in("hunting_band", hunting_band, flag_ranges::frequency_hz);
  check_in("min_damping_ratio", min_damping_ratio, flag_ranges::damping_ratio);
  check_in("amplitude", amplitude, flag_ranges::wheelset_amplitude_m);
  if (gradient && amplitude)
    throw std::invalid_argument("gradient and amplitude: the gradient is of the linear model's "
                                "critical speed; give one of them");
  const SceneOverrides overrides = scene_overrides(settings, std::nullopt, arc_length);
  CriticalSpeedOptions opt;
  opt.from_m_per_s = from;
  opt.to_m_per_s = to;
  opt.grid_step_m_per_s = step;
  opt.stability.solver = solver_named(solver);
  opt.stability.max_frequency_hz = hunting_band;
  if (min_damping_ratio) opt.min_damping_ratio = *min_damping_ratio;
  if (gradient && (solver != "auto" || min_damping_ratio))
    throw std::invalid_argument(
        "gradient: the derivative comes from the sensitivity analysis's own search (solver "
        "'auto', no damping-ratio limit); call without solver and min_damping_ratio");
  ProgressRelay relay(progress);
  opt.progress = relay.lines();
  std::optional<PreparedScene> s;
  CriticalSpeedResult r;
  std::optional<SensitivityRun> sensitivity;
  HopfAssessment hopf;
  std::optional<QuasiLinearCriticalSpeed> quasi_linear;
  WrittenFiles files;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release no_gil;
    s.emplace(prepare_scene(scene, overrides));
    warnings = model_warnings(*s);
    if (gradient) {
      // The sensitivity command's search (to 1e-6 m/s) and derivative: the
      // result is that search, so value and gradient belong together.
      sensitivity.emplace(run_sensitivity(
          *s, sensitivity_options(*gradient, from, to, step, hunting_band, opt.progress, "gradient key")));
      r = sensitivity->search;
    } else if (amplitude) {
      // critical-speed --amplitude A: the profile contacts replaced by their
      // harmonic linearisation at A (stability/quasi_linear_critical_speed.hpp).
      const QuasiLinearModelBuilder builder(s->model, s->equilibrium.state);
      const QuasiLinearModel q = [&] {
        try {
          return builder.at(*amplitude);
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument("amplitude: " + std::string(e.what()));
        }
      }();
      quasi_linear.emplace();
      quasi_linear->amplitude_m = *amplitude;
      quasi_linear->wheelsets = q.wheelsets;
      quasi_linear->has_profile_contact = q.has_profile_contact;
      quasi_linear->result = find_critical_speed(q.model, s->equilibrium.state, s->speed_m_per_s, opt);
      r = quasi_linear->result;
    } else {
      r = find_critical_speed(s->model, s->equilibrium.state, s->speed_m_per_s, opt);
    }
    // The quasi-linear report has no Hopf assessment (as the command's).
    if (!quasi_linear) hopf = assess_hopf(s->model, r);
    const std::string solver_used = r.grid.empty() ? solver : eigen_solver_name(r.grid.front().solver_used);
    const std::string stem = steady_state_file_stem(scene, s->model) + (quasi_linear ? "_quasi_linear" : "");
    files = write_and_read([&](OutputSet& outputs) {
      write_stability_results(s->model, r, outputs, stem, solver_used, false, hunting_band,
                              quasi_linear ? nullptr : &hopf,
                              quasi_linear ? &*quasi_linear : nullptr);
    });
  }
  relay.rethrow();
  py::dict out;
  out["json"] = files.ending_with("_critical_speed.json");
  out["eigenvalues"] = eigenvalue_table(r);
  if (sensitivity) out["gradient"] = gradient_of(sensitivity->sensitivities);
  out["model_warnings"] = py::cast(warnings);
  return out;
}

py::dict eigen(const std::string& scene, const std::vector<std::string>& settings,
               std::optional<double> speed, std::optional<double> arc_length,
               const std::string& solver, double hunting_band) {
  check_in("hunting_band", hunting_band, flag_ranges::frequency_hz);
  const SceneOverrides overrides = scene_overrides(settings, speed, arc_length);
  StabilityOptions o;
  o.solver = solver_named(solver);
  o.max_frequency_hz = hunting_band;
  std::optional<PreparedScene> s;
  std::optional<StabilityPoint> p;
  WrittenFiles files;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release no_gil;
    s.emplace(prepare_scene(scene, overrides));
    warnings = model_warnings(*s);
    SpeedStability stability(s->model, s->equilibrium.state, s->speed_m_per_s, o);
    p.emplace(stability.at(s->speed_m_per_s));
    files = write_and_read([&](OutputSet& outputs) {
      write_eigen_json(s->model, *p, full_mode_shapes(s->model, *p), outputs,
                       steady_state_file_stem(scene, s->model));
    });
  }
  const std::size_t n = p->modes.size();
  std::vector<std::complex<double>> eigenvalues;
  std::vector<double> frequency, damping;
  py::list names;
  Eigen::MatrixXcd vectors(p->linear.states(), Eigen::Index(n));
  for (std::size_t k = 0; k < n; ++k) {
    const ModeReport& m = p->modes[k];
    eigenvalues.push_back(m.eigenvalue);
    frequency.push_back(m.frequency_hz);
    damping.push_back(m.damping_ratio);
    names.append(m.name);
    if (m.vector.size() == vectors.rows()) vectors.col(Eigen::Index(k)) = m.vector;
    else vectors.col(Eigen::Index(k)).setConstant(std::complex<double>(NAN, NAN));
  }
  py::dict out;
  out["json"] = files.ending_with(".json");
  out["eigenvalues"] = array_of(eigenvalues);
  out["frequency_Hz"] = array_of(frequency);
  out["damping_ratio"] = array_of(damping);
  out["mode_names"] = names;
  out["eigenvectors"] = array_of(vectors);
  out["state_names"] = py::cast(p->linear.state_names);
  if (p->linear.A.size() > 0) out["state_matrix"] = array_of(p->linear.A);
  out["model_warnings"] = py::cast(warnings);
  return out;
}

py::dict equilibrium(const std::string& scene, const std::vector<std::string>& settings,
                     std::optional<double> speed, std::optional<double> arc_length) {
  const SceneOverrides overrides = scene_overrides(settings, speed, arc_length);
  std::optional<PreparedScene> s;
  WrittenFiles files;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release no_gil;
    s.emplace(prepare_scene(scene, overrides));
    warnings = model_warnings(*s);
    files = write_and_read([&](OutputSet& outputs) {
      write_equilibrium_results(*s, outputs, steady_state_file_stem(scene, s->model));
    });
  }
  py::dict out;
  out["json"] = files.ending_with(".json");
  out["state"] = array_of(std::vector<double>(s->equilibrium.state.data(),
                                              s->equilibrium.state.data() + s->equilibrium.state.size()));
  out["model_warnings"] = py::cast(warnings);
  return out;
}

// `railstab curving`: a value or (from, to, step) of cant deficiency and of
// radius, each an empty list when not given; the same checks and sweep as
// the command (curving_request.hpp), its messages naming these arguments.
py::dict curving(const std::string& scene, const std::vector<std::string>& settings,
                 std::optional<double> arc_length, const std::vector<double>& cant_deficiency,
                 const std::vector<double>& radius) {
  CurvingRequestNames names;
  names.cant_deficiency = "cant_deficiency";
  names.radius = "radius";
  names.range = "(from, to, step)";
  names.from = "from", names.to = "to", names.step = "step";
  names.one_cant_deficiency = "cant_deficiency=H";
  names.one_radius = "radius=R";
  // As Python writes them: each number's shortest round-trip digits.
  auto shown = [](const std::vector<double>& fields) {
    std::string out = fields.size() == 1 ? "" : "(";
    for (std::size_t k = 0; k < fields.size(); ++k) {
      char digits[32];
      const auto end = std::to_chars(digits, digits + sizeof digits, fields[k]).ptr;
      out += (k ? ", " : "") + std::string(digits, end);
    }
    return fields.size() == 1 ? out : out + ")";
  };
  const std::vector<double> deficiencies =
      cant_deficiency.empty()
          ? std::vector<double>{}
          : curving_values(cant_deficiency, CurvingQuantity::cant_deficiency, shown(cant_deficiency), names);
  const std::vector<double> radii =
      radius.empty() ? std::vector<double>{}
                     : curving_values(radius, CurvingQuantity::radius, shown(radius), names);
  check_curving_request(deficiencies, radii, names);
  const SceneOverrides overrides = scene_overrides(settings, std::nullopt, arc_length);
  WrittenFiles files;
  {
    py::gil_scoped_release no_gil;
    const SceneSpec spec = load_scene_with_overrides(scene, overrides);
    const Model model = build_model(spec);
    const CurvingSweepPlan plan = plan_curving_sweep(model, spec.speed_m_per_s, deficiencies, radii, names);
    const CurvingSweep sweep = sweep_steady_curving(model, plan.kind, plan.values, plan.fixed,
                                                    spec.assessment.prudhomme_factor);
    files = write_and_read([&](OutputSet& outputs) {
      (void)write_curving_results(model, sweep, plan.kind, outputs, scene_file_stem(scene));
    });
  }
  // The command prints no model warnings before a sweep: none here either.
  return files_by_key(files, {{"json", "_curving.json"}, {"csv", "_curving.csv"}}, {});
}

py::dict sensitivity(const std::string& scene, const std::vector<std::string>& settings,
                     std::vector<std::string> keys, double from, double to, double step,
                     double hunting_band, py::object progress) {
  check_speed_grid(from, to, step);
  check_in("hunting_band", hunting_band, flag_ranges::frequency_hz);
  const SceneOverrides overrides = scene_overrides(settings, std::nullopt, std::nullopt);
  ProgressRelay relay(progress);
  const SensitivityRunOptions o =
      sensitivity_options(std::move(keys), from, to, step, hunting_band, relay.lines(), "key");
  std::optional<SensitivityRun> run;
  WrittenFiles files;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release no_gil;
    const PreparedScene s = prepare_scene(scene, overrides);
    warnings = model_warnings(s);
    run.emplace(run_sensitivity(s, o));
    // The command's context: the scene path as given, 20 bars (the plot's,
    // unused without plots).
    SensitivityReportContext c{s.spec.name, scene, run->mode.name, run->mode.frequency_hz, 20};
    files = write_and_read([&](OutputSet& outputs) {
      write_sensitivity_results(run->sensitivities, c, outputs, scene_file_stem(scene), false);
    });
  }
  relay.rethrow();
  py::dict out;
  out["json"] = files.ending_with(".json");
  out["gradient"] = gradient_of(run->sensitivities);
  out["model_warnings"] = py::cast(warnings);
  return out;
}

}  // namespace

void bind_stability(py::module_& m) {
  using py::arg;
  m.def("critical_speed", &critical_speed, arg("scene"), arg("settings"), arg("arc_length"),
        arg("from_"), arg("to"), arg("step"), arg("solver"), arg("hunting_band"),
        arg("min_damping_ratio"), arg("gradient"), arg("amplitude"), arg("progress"));
  m.def("eigen", &eigen, arg("scene"), arg("settings"), arg("speed"), arg("arc_length"),
        arg("solver"), arg("hunting_band"));
  m.def("equilibrium", &equilibrium, arg("scene"), arg("settings"), arg("speed"), arg("arc_length"));
  m.def("curving", &curving, arg("scene"), arg("settings"), arg("arc_length"),
        arg("cant_deficiency"), arg("radius"));
  m.def("sensitivity", &sensitivity, arg("scene"), arg("settings"), arg("keys"), arg("from_"),
        arg("to"), arg("step"), arg("hunting_band"), arg("progress"));
}

}  // namespace railstab::python
