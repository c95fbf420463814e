#include <railstab/study/study_run.hpp>

#include <railstab/stability/verdict.hpp>
#include <railstab/setup/model_error_context.hpp>
#include <railstab/io/regular_file.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>

namespace railstab {

namespace {

StabilityOptions stability_options(const StudyAnalysis& a) {
  StabilityOptions o;
  o.solver = eigen_solver_from_name(a.solver);
  o.max_frequency_hz = a.hunting_band_hz;
  return o;
}

std::string values_text(const StudyDefinition& d, const std::vector<double>& values) {
  std::string s;
  for (size_t k = 0; k < values.size(); ++k)
    s += (k ? " " : "") + d.varied[k].key + "=" + number_text_exact(values[k]);
  return s;
}

}  // namespace

void complete_study_definition(StudyDefinition& d) {
  std::string bytes;
  try {
    bytes = read_regular_file(d.scene_path);
  } catch (const std::runtime_error& e) {
    throw SceneError(d.scene_path + ": scene file: " + e.what());
  }
  d.scene_hash = fnv1a64_hex(bytes);
  SceneOverrides fixed;
  fixed.values = d.fixed;
  d.scene_name = load_scene_with_overrides(d.scene_path, fixed).name;
  for (const VariedKey& v : d.varied)
    for (const double value : {v.from, v.to}) {
      std::vector<SceneValueSetting> s = d.fixed;
      for (SceneValueSetting& linked : varied_settings(v, value)) s.push_back(std::move(linked));
      scene_text_with_values(bytes, d.scene_path, s);
    }
}

StudyPoint run_study_point(const StudyDefinition& d, std::size_t index) {
  StudyPoint p;
  p.index = index;
  p.values = d.values_of(index);
  try {
    SceneOverrides overrides;
    overrides.values = d.fixed;
    for (size_t k = 0; k < d.varied.size(); ++k)
      for (SceneValueSetting& s : varied_settings(d.varied[k], p.values[k]))
        overrides.values.push_back(std::move(s));
    const PreparedScene s = prepare_scene(d.scene_path, overrides);
    CriticalSpeedOptions opt;
    opt.from_m_per_s = d.analysis.from_m_per_s;
    opt.to_m_per_s = d.analysis.to_m_per_s;
    opt.grid_step_m_per_s = d.analysis.grid_step_m_per_s;
    opt.stability = stability_options(d.analysis);
    opt.mode_shapes_at_critical = false;  // a study record holds the speed and mode name only
    const CriticalSpeedResult r = find_critical_speed(s.model, s.equilibrium.state, s.speed_m_per_s, opt);
    p.status = verdict_key(stability_verdict(r));
    p.critical_speed_found = r.critical_speed_found;
    if (r.critical_speed_found) {
      p.critical_speed_m_per_s = r.critical_speed_m_per_s;
      const StabilityPoint& at = r.at_critical;
      if (at.least_stable >= 0) {
        p.frequency_hz = at.modes[size_t(at.least_stable)].frequency_hz;
        p.mode = at.modes[size_t(at.least_stable)].name;
      }
    }
    if (r.partial) p.message = r.partial_reason;
    // A critical speed that is not a Hopf crossing is said in the row.
    if (r.critical_speed_found && r.loss.kind != LossOfStabilityKind::oscillatory_crossing)
      p.message = "loss of stability: " + describe_loss_of_stability(r.loss) +
                  (p.message.empty() ? "" : "; " + p.message);
  } catch (const std::exception& e) {
    p = StudyPoint{index, p.values, "error", false, 0.0, 0.0, "", without_function_name(e.what())};
  }
  return p;
}

std::vector<StudyPoint> run_study(const StudyDefinition& d, const StudyRunOptions& options) {
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < d.combinations(); ++i)
    if (options.shard.holds(i)) todo.push_back(i);
  std::vector<StudyPoint> points(todo.size());
  std::atomic<std::size_t> next{0};
  std::mutex progress_mutex;
  std::size_t done = 0;
  const auto start = std::chrono::steady_clock::now();
  auto worker = [&] {
    for (std::size_t k; (k = next.fetch_add(1)) < todo.size();) {
      points[k] = run_study_point(d, todo[k]);
      if (!options.progress) continue;
      const StudyPoint& p = points[k];
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      char speed[64] = "";
      if (p.critical_speed_found) std::snprintf(speed, sizeof speed, ": %.2f m/s", p.critical_speed_m_per_s);
      std::lock_guard<std::mutex> lock(progress_mutex);
      ++done;
      char head[96];
      std::snprintf(head, sizeof head, "[%zu/%zu, %.1f s] #%zu ", done, todo.size(), elapsed, p.index);
      options.progress(head + values_text(d, p.values) + " -> " + p.status + speed +
                       (p.message.empty() ? "" : " (" + p.message + ")"));
    }
  };
  const unsigned jobs = std::max(1u, std::min<unsigned>(options.jobs, unsigned(std::max<std::size_t>(todo.size(), 1))));
  std::vector<std::thread> pool;
  std::exception_ptr failure;
  std::mutex failure_mutex;
  for (unsigned j = 1; j < jobs; ++j)
    pool.emplace_back([&] {
      try {
        worker();
      } catch (...) {  // the progress callback itself failed (stderr closed...)
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
      }
    });
  try {
    worker();
  } catch (...) {
    std::lock_guard<std::mutex> lock(failure_mutex);
    if (!failure) failure = std::current_exception();
  }
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  return points;
}

}  // namespace railstab
