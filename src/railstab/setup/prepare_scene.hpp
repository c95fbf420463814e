#pragma once
// The first steps of every analysis: read the scene (checked once), apply
// overrides, build the profile contact tables, build the model (preloads
// solved in), solve the static/steady equilibrium at the run's speed.
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/model/model.hpp>
#include <railstab/scene/scene_spec.hpp>
#include <railstab/scene_reading/scene_set_values.hpp>
#include <railstab/setup/build_model.hpp>
#include <railstab/setup/initial_offsets.hpp>

#include <optional>
#include <string>

namespace railstab {

struct SceneOverrides {
  std::optional<double> speed_m_per_s;
  std::optional<double> t_end_s;
  // Where the reference point is at t = 0 (e.g. inside an arc for steady
  // curving); the scene's reference_arc_length_m otherwise.
  std::optional<double> reference_arc_length_m;
  // --set KEY=VALUE, applied to the file's document before it is read
  // (scene_reading/scene_set_values.hpp), in order.
  std::vector<SceneValueSetting> values;
  // --offset BODY.COORDINATE=VALUE (setup/initial_offsets.hpp): initial
  // offsets written into the bodies' initial_offset, in order.
  std::vector<OffsetSetting> offsets;
  // The time-domain commands (simulate, verify, assess) set this: a scene's
  // [track.irregularities] are then applied to the wheel-rail contact. Every
  // other analysis is of the design track (a steady state, a linearisation)
  // and refuses such a scene rather than silently leave them out.
  bool apply_track_irregularities = false;

  // The scene at speed V, nothing else overridden (the tests' usual run).
  static SceneOverrides at_speed(double speed_m_per_s) {
    SceneOverrides o;
    o.speed_m_per_s = speed_m_per_s;
    return o;
  }
};

struct PreparedScene {
  SceneSpec spec;
  Model model;
  double speed_m_per_s = 0.0;     // of this run: the override, or the scene's
  EquilibriumResult equilibrium;  // at t = 0 (steady rolling / curving at that speed)
};

PreparedScene prepare_scene(const std::string& path, const SceneOverrides& overrides);
// The first step alone: the scene file read with its --set values and
// checked (load_scene_file), its contact tables built, then the run's
// --speed, --t-end, --arc-length and --offset applied and checked (only the checks
// those values enter: the rest of the scene was checked when read).
SceneSpec load_scene_with_overrides(const std::string& path, const SceneOverrides& overrides);
// The same from a scene already read and checked (overrides applied by the
// caller); builds the contact tables it lacks. A scene with
// [track.irregularities] is refused unless apply_track_irregularities.
PreparedScene prepare_scene(SceneSpec spec, bool apply_track_irregularities = false);

// Equilibrium state plus the scene's initial offsets and rates.
Eigen::VectorXd perturbed_initial_state(const PreparedScene& scene);

}  // namespace railstab
