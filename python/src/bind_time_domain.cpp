// simulate, speed_ramp, verify and assess: the nonlinear model in time, as
// the commands run it (src/cli/simulate_command.cpp, verify_command.cpp,
// assess_command.cpp), without the GIL. The
// run's summary (with the error estimate) is the command's JSON; the
// channels are the command's CSV columns, written at 17 significant digits
// (read back, the same doubles) and parsed by the Python layer.
#include "arguments.hpp"
#include "cli/speed_ramp_run.hpp"
#include "bindings.hpp"
#include "model_warnings.hpp"
#include "progress_relay.hpp"

#include "written_files.hpp"

#include <railstab/assessment/assessment_run.hpp>
#include <railstab/check/run_check.hpp>
#include <railstab/integrate/error_estimate.hpp>
#include <railstab/integrate/integrator.hpp>
#include <railstab/integrate/work_precision.hpp>
#include <railstab/io/file_names.hpp>
#include <railstab/io/output_files.hpp>
#include <railstab/io/ride_files.hpp>
#include <railstab/nonlinear/speed_ramp.hpp>
#include <railstab/report/assessment_report.hpp>
#include <railstab/report/simulation_report.hpp>
#include <railstab/report/speed_ramp_report.hpp>
#include <railstab/report/verify_report.hpp>
#include <railstab/ride/ride_history.hpp>
#include <railstab/stability/mode_start.hpp>
#include <railstab/verify/verification.hpp>

#include <pybind11/stl.h>

#include <optional>
#include <sstream>

namespace py = pybind11;

namespace railstab::python {

namespace {

constexpr int kRoundTripDigits = 17;

// A start on a mode (mode + mode_amplitude), as the commands' --mode flags.
std::optional<ModeStart> mode_start(const PreparedScene& s, const std::optional<std::string>& mode,
                                    const std::optional<double>& amplitude, bool offsets_given) {
  if (!mode && !amplitude) return std::nullopt;
  if (mode && offsets_given)
    throw std::invalid_argument("mode and offset: give one of them (a start on a mode replaces "
                                "the initial offsets)");
  if (!amplitude)
    throw std::invalid_argument("mode " + *mode + ": expected mode_amplitude too (the leading "
                                "wheelset's lateral shift at the start, in m)");
  if (!mode) throw std::invalid_argument("mode_amplitude: expected mode='hunting' or a mode name too");
  return mode_start_state(s.model, s.speed_m_per_s, s.equilibrium.state, *mode, *amplitude);
}

// What simulate and speed_ramp take alike: the scene's integration options
// with the integrator and tolerances given, and the start (the scene's
// offsets with `offset`, or a mode), as the commands set them up.
struct RunArguments {
  std::vector<std::string> settings, offsets;
  std::optional<double> speed, arc_length, t_end;
  std::optional<std::string> mode;
  std::optional<double> mode_amplitude;
  std::string integrator;
  std::optional<double> rtol, atol;
};

struct TimeDomainRun {
  SceneOverrides overrides;
  std::optional<IntegratorVariant> variant;
};

// Checked before the analysis, with the GIL held.
TimeDomainRun checked_run(const RunArguments& a) {
  check_in("t_end", a.t_end, flag_ranges::t_end_s);
  check_in("rtol", a.rtol, flag_ranges::relative_tolerance);
  check_in("atol", a.atol, flag_ranges::absolute_tolerance);
  check_in("mode_amplitude", a.mode_amplitude, flag_ranges::amplitude_m);
  TimeDomainRun run;
  run.overrides = scene_overrides(a.settings, a.speed, a.arc_length, a.offsets);
  run.overrides.t_end_s = a.t_end;
  run.overrides.apply_track_irregularities = true;  // as the time-domain commands
  if (!a.integrator.empty()) {
    try {
      run.variant = parse_integrator_variant(a.integrator);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("integrator: " + std::string(e.what()));
    }
  }
  return run;
}

struct RunSetUp {
  IntegrationOptions options;
  Eigen::VectorXd x0;
  RunStart start;
};

RunSetUp set_up_run(const PreparedScene& s, const RunArguments& a, const TimeDomainRun& run) {
  RunSetUp u;
  u.options = integration_options_for(s.spec.simulation);
  if (run.variant) {
    u.options.kind = run.variant->kind;
    u.options.order = run.variant->order;
  }
  u.options.relative_tolerance = a.rtol.value_or(s.spec.simulation.relative_tolerance);
  u.options.absolute_tolerance = a.atol.value_or(s.spec.simulation.absolute_tolerance);
  for (const OffsetSetting& o : run.overrides.offsets) u.start.offset_settings.push_back(o.text);
  if (const std::optional<ModeStart> m = mode_start(s, a.mode, a.mode_amplitude, !a.offsets.empty())) {
    u.x0 = m->state;
    u.start.on_mode = true;
    u.start.mode_name = m->mode_name;
    u.start.eigenvalue = m->eigenvalue;
    u.start.leading_wheelset = m->leading_wheelset;
    u.start.amplitude_m = m->amplitude_m;
  } else {
    u.x0 = perturbed_initial_state(s);
  }
  return u;
}

py::dict simulate(const std::string& scene, const RunArguments& a, bool estimate_error,
                  bool stop_on_lift_off, py::object progress) {
  const TimeDomainRun run = checked_run(a);
  ProgressRelay relay(progress);
  std::string summary, trajectory_csv, roll_csv, forces_csv, accelerations_csv;
  std::vector<std::string> warning_texts;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release no_gil;
    const PreparedScene s = prepare_scene(scene, run.overrides);
    warnings = model_warnings(s);
    RunSetUp u = set_up_run(s, a, run);
    IntegrationOptions& opt = u.options;
    opt.stop_on_lift_off = stop_on_lift_off;
    opt.progress = relay.times();
    const Eigen::VectorXd& x0 = u.x0;
    const RunStart& start = u.start;
    const Trajectory traj = integrate(s.model, s.speed_m_per_s, x0, opt);
    for (const ModelWarning& w : check_run(s.model, traj)) warning_texts.push_back(w.message);
    std::optional<ErrorEstimate> error;
    if (estimate_error) {
      IntegrationOptions quiet = opt;
      quiet.progress = nullptr;  // the tight run's times would repeat the run's
      error = estimate_integration_error(s.model, s.speed_m_per_s, x0, quiet, traj);
    }
    const RideHistory ride =
        ride_history(s.model, s.speed_m_per_s, traj, s.spec.assessment.prudhomme_factor);
    summary = simulation_run_json(s.model, s.speed_m_per_s, opt, traj, error, start, &ride);
    std::ostringstream t, r, f, acc;
    write_trajectory_csv(t, s.model, s.speed_m_per_s, traj, kRoundTripDigits);
    write_absolute_roll_csv(r, s.model, s.speed_m_per_s, traj, kRoundTripDigits);
    write_wheel_forces_csv(f, s.model, ride, kRoundTripDigits);
    write_accelerations_csv(acc, ride, kRoundTripDigits);
    trajectory_csv = t.str();
    roll_csv = r.str();
    forces_csv = f.str();
    accelerations_csv = acc.str();
  }
  relay.rethrow();
  py::dict out;
  out["json"] = summary;
  out["trajectory_csv"] = trajectory_csv;
  out["absolute_roll_csv"] = roll_csv;
  out["wheel_forces_csv"] = forces_csv;
  out["accelerations_csv"] = accelerations_csv;
  out["warnings"] = py::cast(warning_texts);
  out["model_warnings"] = py::cast(warnings);
  return out;
}

// simulate --ramp-rate: from the run's speed, decelerate at each rate and
// report where the hunting dies away (nonlinear/speed_ramp.hpp), as
// src/cli/speed_ramp_run.cpp.
py::dict speed_ramp(const std::string& scene, const RunArguments& a,
                    const std::vector<double>& rates, std::optional<double> ramp_to,
                    double hunting_threshold, py::object progress) {
  if (rates.empty()) throw std::invalid_argument("rates: expected one ramp rate (m/s^2) or more");
  for (double rate : rates) check_in("rates", rate, flag_ranges::ramp_rate_m_per_s2);
  check_in("ramp_to", ramp_to, flag_ranges::speed_m_per_s);
  check_in("hunting_threshold", hunting_threshold, flag_ranges::hunting_threshold_m);
  const TimeDomainRun run = checked_run(a);
  ProgressRelay relay(progress);
  std::string json, envelope_csv;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release no_gil;
    const PreparedScene s = prepare_scene(scene, run.overrides);
    warnings = model_warnings(s);
    const RunSetUp u = set_up_run(s, a, run);
    const double V0 = s.speed_m_per_s;
    const double end = ramp_to.value_or(kDefaultRampEndSpeedShare * V0);
    if (!(end < V0)) {
      std::ostringstream msg;
      msg << "ramp_to " << end << ": expected a speed below the start speed " << V0 << " m/s";
      throw std::invalid_argument(msg.str());
    }
    std::vector<SpeedRampResult> ramps;
    for (double rate : rates) {
      SpeedRampOptions o;
      o.start_speed_m_per_s = V0;
      o.ramp_rate_m_per_s2 = rate;
      o.end_speed_m_per_s = end;
      o.amplitude_threshold_m = hunting_threshold;
      o.integration = u.options;
      o.integration.t_start_s = 0.0;
      o.integration.progress = relay.times();
      ramps.push_back(run_speed_ramp(s.model, u.x0, o));
    }
    json = speed_ramp_json(s.model, ramps, u.start);
    std::ostringstream csv;
    write_speed_ramp_envelope_csv(csv, ramps);
    envelope_csv = csv.str();
  }
  relay.rethrow();
  py::dict out;
  out["json"] = json;
  out["envelope_csv"] = envelope_csv;
  out["model_warnings"] = py::cast(warnings);
  return out;
}

py::dict verify(const std::string& scene, const std::vector<std::string>& settings,
                std::optional<double> speed, std::optional<double> arc_length, double amplitude,
                double periods, double settle_periods, bool any_mode, bool scene_offsets,
                const std::vector<std::string>& offsets, std::optional<std::string> mode,
                std::optional<double> mode_amplitude) {
  check_in("amplitude", amplitude, flag_ranges::amplitude_m);
  check_in("periods", periods, flag_ranges::periods);
  check_in("settle_periods", settle_periods, flag_ranges::settle_periods);
  check_in("mode_amplitude", mode_amplitude, flag_ranges::amplitude_m);
  if (!(settle_periods < periods)) {
    std::ostringstream msg;
    msg << "settle_periods " << settle_periods << " must be below periods " << periods
        << " (the fit window lies between them)";
    throw std::invalid_argument(msg.str());
  }
  if (scene_offsets && mode) throw std::invalid_argument("scene_offsets and mode: give one of them");
  SceneOverrides overrides = scene_overrides(settings, speed, arc_length, offsets);
  overrides.apply_track_irregularities = true;  // as `verify` (a time-domain command)
  std::string json;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release no_gil;
    const PreparedScene s = prepare_scene(scene, overrides);
    warnings = model_warnings(s);
    VerificationOptions options;
    options.amplitude_m = amplitude;
    options.periods = periods;
    options.settle_periods = settle_periods;
    options.lateral_modes_only = !any_mode;
    if (scene_offsets || !overrides.offsets.empty()) {
      options.initial_state = perturbed_initial_state(s);
      options.initial_state_description = "scene initial offsets";
      for (const OffsetSetting& o : overrides.offsets)
        options.initial_state_description += ", --offset " + o.text;
    }
    if (const std::optional<ModeStart> m = mode_start(s, mode, mode_amplitude, !offsets.empty())) {
      options.initial_state = m->state;
      options.initial_state_description = mode_start_description(*m);
    }
    const VerificationResult r =
        verify_least_stable_mode(s.model, s.speed_m_per_s, s.equilibrium.state, options);
    std::ostringstream out;
    write_verification_json(out, s.model, r);
    json = out.str();
  }
  py::dict out;
  out["json"] = json;
  out["model_warnings"] = py::cast(warnings);
  return out;
}

// `railstab assess`: EN 14363 running stability from one run
// (assessment/assessment_run.hpp), started from the scene's offsets (with
// `offsets`) or on a mode, as the command; no plots.
py::dict assess(const std::string& scene, const std::vector<std::string>& settings,
                std::optional<double> speed, std::optional<double> arc_length,
                std::optional<double> t_end, const std::vector<std::string>& offsets,
                std::optional<std::string> mode, std::optional<double> mode_amplitude,
                py::object progress) {
  check_in("t_end", t_end, flag_ranges::t_end_s);
  check_in("mode_amplitude", mode_amplitude, flag_ranges::amplitude_m);
  SceneOverrides overrides = scene_overrides(settings, speed, arc_length, offsets);
  overrides.t_end_s = t_end;
  overrides.apply_track_irregularities = true;  // as the time-domain commands
  ProgressRelay relay(progress);
  WrittenFiles files;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release no_gil;
    const PreparedScene s = prepare_scene(scene, overrides);
    warnings = model_warnings(s);
    std::string start = "the scene's initial offsets and rates";
    for (const OffsetSetting& o : overrides.offsets) start += ", --offset " + o.text;
    Eigen::VectorXd x0;
    if (const std::optional<ModeStart> m = mode_start(s, mode, mode_amplitude, !offsets.empty())) {
      x0 = m->state;
      start = mode_start_description(*m);
    } else {
      x0 = perturbed_initial_state(s);
    }
    const AssessmentRun run = run_running_stability_assessment(
        s.model, s.speed_m_per_s, x0, start, s.spec.simulation, s.spec.assessment, relay.times());
    files = write_and_read([&](OutputSet& outputs) {
      (void)write_assessment_report(s.model, run.assessment, s.spec.assessment, run.conditions,
                                    outputs, scene_file_stem(scene), false);
    });
  }
  relay.rethrow();
  return files_by_key(files, {{"json", "_assessment.json"}, {"windows_csv", "_assessment_windows.csv"}},
                      warnings);
}

}  // namespace

void bind_time_domain(py::module_& m) {
  using py::arg;
  m.def(
      "simulate",
      [](const std::string& scene, std::vector<std::string> settings, std::optional<double> speed,
         std::optional<double> arc_length, std::optional<double> t_end,
         std::vector<std::string> offsets, std::optional<std::string> mode,
         std::optional<double> mode_amplitude, std::string integrator, std::optional<double> rtol,
         std::optional<double> atol, bool estimate_error, bool stop_on_lift_off,
         py::object progress) {
        const RunArguments a{std::move(settings), std::move(offsets), speed, arc_length, t_end,
                             std::move(mode), mode_amplitude, std::move(integrator), rtol, atol};
        return simulate(scene, a, estimate_error, stop_on_lift_off, std::move(progress));
      },
      arg("scene"), arg("settings"), arg("speed"), arg("arc_length"), arg("t_end"),
      arg("offsets"), arg("mode"), arg("mode_amplitude"), arg("integrator"), arg("rtol"),
      arg("atol"), arg("estimate_error"), arg("stop_on_lift_off"), arg("progress"));
  m.def(
      "speed_ramp",
      [](const std::string& scene, std::vector<std::string> settings, std::optional<double> speed,
         std::optional<double> arc_length, std::vector<std::string> offsets,
         std::optional<std::string> mode, std::optional<double> mode_amplitude,
         std::string integrator, std::optional<double> rtol, std::optional<double> atol,
         const std::vector<double>& rates, std::optional<double> ramp_to,
         std::optional<double> hunting_threshold, py::object progress) {
        const RunArguments a{std::move(settings), std::move(offsets), speed, arc_length,
                             std::nullopt, std::move(mode), mode_amplitude,
                             std::move(integrator), rtol, atol};
        return speed_ramp(scene, a, rates, ramp_to,
                          hunting_threshold.value_or(kDefaultHuntingThreshold_m),
                          std::move(progress));
      },
      arg("scene"), arg("settings"), arg("speed"), arg("arc_length"), arg("offsets"), arg("mode"),
      arg("mode_amplitude"), arg("integrator"), arg("rtol"), arg("atol"), arg("rates"),
      arg("ramp_to"), arg("hunting_threshold"), arg("progress"));
  m.def("verify", &verify, arg("scene"), arg("settings"), arg("speed"), arg("arc_length"),
        arg("amplitude"), arg("periods"), arg("settle_periods"), arg("any_mode"),
        arg("scene_offsets"), arg("offsets"), arg("mode"), arg("mode_amplitude"));
  m.def("assess", &assess, arg("scene"), arg("settings"), arg("speed"), arg("arc_length"),
        arg("t_end"), arg("offsets"), arg("mode"), arg("mode_amplitude"), arg("progress"));
}

}  // namespace railstab::python
