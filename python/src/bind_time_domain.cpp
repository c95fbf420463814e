// simulate and verify: the nonlinear model in time, as the commands run it
// (src/cli/simulate_command.cpp, verify_command.cpp), without the GIL. The
// run's summary (with the error estimate) is the command's JSON; the
// channels are the command's CSV columns, written at 17 significant digits
// (read back, the same doubles) and parsed by the Python layer.
#include "arguments.hpp"
#include "bindings.hpp"
#include "model_warnings.hpp"
#include "progress_relay.hpp"

#include <railstab/check/run_check.hpp>
#include <railstab/integrate/error_estimate.hpp>
#include <railstab/integrate/integrator.hpp>
#include <railstab/integrate/work_precision.hpp>
#include <railstab/io/output_files.hpp>
#include <railstab/io/ride_files.hpp>
#include <railstab/report/simulation_report.hpp>
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

py::dict simulate(const std::string& scene, const std::vector<std::string>& settings,
                  std::optional<double> speed, std::optional<double> arc_length,
                  std::optional<double> t_end, const std::vector<std::string>& offsets,
                  std::optional<std::string> mode, std::optional<double> mode_amplitude,
                  const std::string& integrator, std::optional<double> rtol,
                  std::optional<double> atol, bool estimate_error, bool stop_on_lift_off,
                  py::object progress) {
  check_in("t_end", t_end, flag_ranges::t_end_s);
  check_in("rtol", rtol, flag_ranges::relative_tolerance);
  check_in("atol", atol, flag_ranges::absolute_tolerance);
  check_in("mode_amplitude", mode_amplitude, flag_ranges::amplitude_m);
  SceneOverrides overrides = scene_overrides(settings, speed, arc_length, offsets);
  overrides.t_end_s = t_end;
  overrides.apply_track_irregularities = true;  // as `simulate`
  std::optional<IntegratorVariant> variant;
  if (!integrator.empty()) {
    try {
      variant = parse_integrator_variant(integrator);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("integrator: " + std::string(e.what()));
    }
  }
  ProgressRelay relay(progress);
  std::string summary, trajectory_csv, roll_csv, forces_csv, accelerations_csv;
  std::vector<std::string> warning_texts;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release no_gil;
    const PreparedScene s = prepare_scene(scene, overrides);
    warnings = model_warnings(s);
    IntegrationOptions opt = integration_options_for(s.spec.simulation);
    if (variant) {
      opt.kind = variant->kind;
      opt.order = variant->order;
    }
    opt.relative_tolerance = rtol.value_or(s.spec.simulation.relative_tolerance);
    opt.absolute_tolerance = atol.value_or(s.spec.simulation.absolute_tolerance);
    opt.stop_on_lift_off = stop_on_lift_off;
    opt.progress = relay.times();
    RunStart start;
    for (const OffsetSetting& o : overrides.offsets) start.offset_settings.push_back(o.text);
    Eigen::VectorXd x0;
    if (const std::optional<ModeStart> m = mode_start(s, mode, mode_amplitude, !offsets.empty())) {
      x0 = m->state;
      start.on_mode = true;
      start.mode_name = m->mode_name;
      start.eigenvalue = m->eigenvalue;
      start.leading_wheelset = m->leading_wheelset;
      start.amplitude_m = m->amplitude_m;
    } else {
      x0 = perturbed_initial_state(s);
    }
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
    std::ostringstream t, r, f, a;
    write_trajectory_csv(t, s.model, s.speed_m_per_s, traj, kRoundTripDigits);
    write_absolute_roll_csv(r, s.model, s.speed_m_per_s, traj, kRoundTripDigits);
    write_wheel_forces_csv(f, s.model, ride, kRoundTripDigits);
    write_accelerations_csv(a, ride, kRoundTripDigits);
    trajectory_csv = t.str();
    roll_csv = r.str();
    forces_csv = f.str();
    accelerations_csv = a.str();
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
      std::ostringstream text;
      text << "mode '" << m->mode_name << "', " << m->leading_wheelset << " lateral "
           << m->amplitude_m << " m";
      options.initial_state_description = text.str();
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

}  // namespace

void bind_time_domain(py::module_& m) {
  using py::arg;
  m.def("simulate", &simulate, arg("scene"), arg("settings"), arg("speed"), arg("arc_length"),
        arg("t_end"), arg("offsets"), arg("mode"), arg("mode_amplitude"), arg("integrator"),
        arg("rtol"), arg("atol"), arg("estimate_error"), arg("stop_on_lift_off"), arg("progress"));
  m.def("verify", &verify, arg("scene"), arg("settings"), arg("speed"), arg("arc_length"),
        arg("amplitude"), arg("periods"), arg("settle_periods"), arg("any_mode"),
        arg("scene_offsets"), arg("offsets"), arg("mode"), arg("mode_amplitude"));
}

}  // namespace railstab::python
