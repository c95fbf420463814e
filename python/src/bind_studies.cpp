// load_scene, contact_geometry, track, study and bifurcation, as their
// commands run them (src/cli/contact_geometry_command.cpp,
// track_command.cpp, study_command.cpp, bifurcation_command.cpp), without
// the GIL; JSON and tables from the commands' own writers
// (written_files.hpp).
#include "arguments.hpp"
#include "bindings.hpp"
#include "model_warnings.hpp"
#include "progress_relay.hpp"
#include "written_files.hpp"

#include <railstab/check/model_check.hpp>
#include <railstab/contact_geometry/contact_geometry_summary.hpp>
#include <railstab/contact_geometry/contact_table_file.hpp>
#include <railstab/contact_geometry/rigid_contact.hpp>
#include <railstab/scene_reading/scene_error.hpp>
#include <railstab/io/file_names.hpp>
#include <railstab/irregularity/irregularity_check.hpp>
#include <railstab/nonlinear/bifurcation_analysis.hpp>
#include <railstab/report/bifurcation_report.hpp>
#include <railstab/report/contact_geometry_report.hpp>
#include <railstab/report/irregularity_report.hpp>
#include <railstab/report/model_check_report.hpp>
#include <railstab/report/run_conditions.hpp>
#include <railstab/report/study_report.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/sensitivity/parameter_derivative.hpp>
#include <railstab/setup/contact_tables.hpp>
#include <railstab/study/study_run.hpp>

#include <pybind11/stl.h>

#include <filesystem>
#include <optional>
#include <sstream>

namespace py = pybind11;

namespace railstab::python {

namespace {

// The scene read and checked with its overrides (no model, no equilibrium):
// what a script needs to know of it before an analysis.
py::dict load_scene(const std::string& scene, const std::vector<std::string>& settings) {
  const SceneOverrides overrides = scene_overrides(settings, std::nullopt, std::nullopt);
  std::optional<SceneSpec> spec;
  std::vector<std::string> keys;
  std::vector<double> values;
  {
    py::gil_scoped_release no_gil;
    spec.emplace(load_scene_with_overrides(scene, overrides));
    keys = parameter_keys(*spec);
    for (const std::string& k : keys) values.push_back(parameter_value(*spec, k));
  }
  py::dict out;
  out["name"] = spec->name;
  out["source_path"] = spec->source_path;
  out["speed_m_per_s"] = spec->speed_m_per_s;
  py::list bodies;
  for (const BodySpec& b : spec->bodies) bodies.append(b.name);
  out["bodies"] = bodies;
  py::dict parameters;
  for (std::size_t i = 0; i < keys.size(); ++i) parameters[py::str(keys[i])] = values[i];
  out["parameters"] = parameters;
  return out;
}

// `railstab check`: the model checks before a run. The command fails after
// writing its report when a check is an error; here the report is returned
// and its "errors" say so.
py::dict check(const std::string& scene, const std::vector<std::string>& settings,
               std::optional<double> speed, std::optional<double> arc_length,
               bool natural_frequencies) {
  const SceneOverrides overrides = scene_overrides(settings, speed, arc_length);
  std::string json;
  {
    py::gil_scoped_release no_gil;
    const SceneSpec spec = load_scene_with_overrides(scene, overrides);
    ModelCheckOptions options;
    options.natural_frequencies = natural_frequencies;
    const ModelCheckReport r = check_scene(spec, options);
    std::ostringstream out;
    write_model_check_json(out, r);
    json = out.str();
  }
  py::dict out;
  out["json"] = json;
  return out;
}

py::dict contact_geometry(const std::string& scene, const std::vector<std::string>& settings,
                          const std::string& contact) {
  const SceneOverrides overrides = scene_overrides(settings, std::nullopt, std::nullopt);
  WrittenFiles files;
  {
    py::gil_scoped_release no_gil;
    const std::vector<ContactSpec> contacts = load_scene_contacts(scene, overrides.values);
    const ContactSpec& spec = chosen_profile_contact(contacts, scene, contact, "contact");
    const std::string scene_name = std::filesystem::path(scene).stem().string();
    const std::string stem = file_stem(scene_name + "_" + spec.name);
    if (!spec.profile_geometry->has_profiles()) {
      const ProfileContactGeometry& g = *spec.profile_geometry;
      const TableContactGeometrySummary summary = summarise_table_contact_geometry(g);
      files = write_and_read([&](OutputSet& outputs) {
        write_table_contact_geometry_report(g, summary, scene, spec.name, outputs, stem);
      });
    } else {
      // As the command: each wheel's own pair (an asymmetric wheelset).
      const WheelsetProfilePairs pairs = spec.profile_geometry->pairs();
      ContactGeometrySummary summary;
      try {
        summary = summarise_contact_geometry(pairs);
      } catch (const ContactGeometryError& e) {  // no contact with the wheelset centred
        throw SceneError(scene + ": contacts." + spec.name + ": " + e.what());
      }
      files = write_and_read([&](OutputSet& outputs) {
        write_contact_geometry_report(pairs, summary, scene_name, scene, spec.name, outputs, stem, false);
      });
    }
  }
  py::dict out;
  out["json"] = files.ending_with(".json");
  out["characteristic_csv"] = files.ending_with("_characteristic.csv");
  out["conicity_csv"] = files.ending_with("_conicity.csv");
  return out;
}

// `railstab track`: the scene's [track.irregularities] synthesised, their
// PSDs against the target and rms (no plots).
py::dict track(const std::string& scene, const std::vector<std::string>& settings) {
  const SceneOverrides overrides = scene_overrides(settings, std::nullopt, std::nullopt);
  WrittenFiles files;
  {
    py::gil_scoped_release no_gil;
    const SceneSpec spec = load_scene_file(scene, overrides.values);
    const TrackIrregularities irregularities(required_track_irregularities(spec, scene));
    const IrregularityCheck check = check_irregularities(irregularities);
    files = write_and_read([&](OutputSet& outputs) {
      (void)write_irregularity_report(irregularities, check, spec.name, outputs, scene_file_stem(scene),
                                      false);
    });
  }
  return files_by_key(files,
                      {{"json", "_irregularities.json"},
                       {"channels_csv", "_irregularities.csv"},
                       {"psd_csv", "_irregularity_psd.csv"}},
                      {});
}

py::dict study(const std::string& scene, const std::vector<std::string>& settings,
               const std::vector<std::string>& vary, double from, double to, double step,
               const std::string& solver, double hunting_band, unsigned jobs, py::object progress) {
  StudyDefinition d;
  d.scene_path = scene;
  d.fixed = scene_overrides(settings, std::nullopt, std::nullopt).values;
  for (const std::string& text : vary) {
    try {
      d.varied.push_back(parse_varied_key(text));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("vary: " + std::string(e.what()));
    }
  }
  check_in("hunting_band", hunting_band, flag_ranges::frequency_hz);
  solver_named(solver);
  if (jobs < 1 || jobs > 1024) throw std::invalid_argument("jobs: expected 1 to 1024 threads, got " + std::to_string(jobs));
  d.analysis.from_m_per_s = from;
  d.analysis.to_m_per_s = to;
  d.analysis.grid_step_m_per_s = step;
  d.analysis.solver = solver;
  d.analysis.hunting_band_hz = hunting_band;
  check_study_definition(d);
  check_speed_grid(from, to, step);
  ProgressRelay relay(progress);
  WrittenFiles files;
  {
    py::gil_scoped_release no_gil;
    complete_study_definition(d);
    StudyRunOptions options;
    options.jobs = jobs;
    options.progress = relay.lines();
    const std::vector<StudyPoint> points = run_study(d, options);
    files = write_and_read([&](OutputSet& outputs) {
      write_study_results(d, StudyShard{}, points, outputs, scene_file_stem(d.scene_path), false);
    });
  }
  relay.rethrow();
  py::dict out;
  out["json"] = files.ending_with("_study.json");
  out["csv"] = files.ending_with("_study.csv");
  return out;
}

py::dict bifurcation(const std::string& scene, const std::vector<std::string>& settings,
                     std::optional<double> arc_length, double from, double to, double step,
                     std::optional<double> cycle_speed, const std::string& cycle_direction,
                     bool hopf_branch, bool stop_at_fold, double max_amplitude,
                     int max_orbits, const std::string& solver, double hunting_band,
                     py::object progress) {
  check_speed_grid(from, to, step);
  check_in("cycle_speed", cycle_speed, flag_ranges::speed_m_per_s);
  check_in("max_amplitude", max_amplitude, flag_ranges::orbit_amplitude_m);
  check_in("hunting_band", hunting_band, flag_ranges::frequency_hz);
  if (max_orbits < 2 || max_orbits > 10000)
    throw std::invalid_argument("max_orbits: expected 2 to 10000, got " + std::to_string(max_orbits));
  BifurcationOptions o;
  o.cycle_speed_step_m_per_s = cycle_speed_step_for(cycle_direction, "cycle_direction");
  o.linear.from_m_per_s = from;
  o.linear.to_m_per_s = to;
  o.linear.grid_step_m_per_s = step;
  o.max_amplitude_m = max_amplitude;
  o.from_hopf = hopf_branch;
  if (cycle_speed) o.cycle_speed_m_per_s = *cycle_speed;
  if (o.cycle_speed_m_per_s > 0.0 && !(o.cycle_speed_m_per_s >= from && o.cycle_speed_m_per_s <= to)) {
    std::ostringstream msg;
    msg << "cycle_speed " << o.cycle_speed_m_per_s << " m/s must lie between from_ " << from
        << " and to " << to << " m/s";
    throw std::invalid_argument(msg.str());
  }
  o.linear.stability.solver = solver_named(solver);
  o.linear.stability.max_frequency_hz = hunting_band;
  o.continuation.max_orbits = max_orbits;
  o.continuation.stop_at_first_fold = stop_at_fold;
  const SceneOverrides overrides = scene_overrides(settings, std::nullopt, arc_length);
  ProgressRelay relay(progress);
  o.progress = relay.lines();
  WrittenFiles files;
  std::vector<std::string> warnings;
  {
    py::gil_scoped_release no_gil;
    const PreparedScene s = prepare_scene(scene, overrides);
    warnings = model_warnings(s);
    // Without a cycle speed only profile contact starts a time-domain
    // branch by default (analyse_bifurcation).
    if (!starts_a_branch(s.model, o))
      throw std::invalid_argument(
          "hopf_branch=False leaves no branch to compute: give cycle_speed as well (the default "
          "time-domain start is for profile contact, and the scene has none)");
    const BifurcationResult r = analyse_bifurcation(s.model, s.equilibrium.state, s.speed_m_per_s, o);
    BifurcationRunInfo info;
    info.eigen_solver = solver;
    info.hunting_band_hz = hunting_band;
    files = write_and_read([&](OutputSet& outputs) {
      write_bifurcation_results(s.model, r, info, outputs, steady_state_file_stem(scene, s.model), false);
    });
  }
  relay.rethrow();
  return files_by_key(files, {{"json", "_bifurcation.json"}, {"csv", "_bifurcation_branches.csv"}},
                      warnings);
}

}  // namespace

void bind_studies(py::module_& m) {
  using py::arg;
  m.def("load_scene", &load_scene, arg("scene"), arg("settings"));
  m.def("check", &check, arg("scene"), arg("settings"), arg("speed"), arg("arc_length"),
        arg("natural_frequencies"));
  m.def("contact_geometry", &contact_geometry, arg("scene"), arg("settings"), arg("contact"));
  m.def("track", &track, arg("scene"), arg("settings"));
  m.def("study", &study, arg("scene"), arg("settings"), arg("vary"), arg("from_"), arg("to"),
        arg("step"), arg("solver"), arg("hunting_band"), arg("jobs"), arg("progress"));
  m.def("bifurcation", &bifurcation, arg("scene"), arg("settings"), arg("arc_length"),
        arg("from_"), arg("to"), arg("step"), arg("cycle_speed"), arg("cycle_direction"), arg("hopf_branch"),
        arg("stop_at_fold"),
        arg("max_amplitude"), arg("max_orbits"), arg("solver"), arg("hunting_band"),
        arg("progress"));
}

}  // namespace railstab::python
