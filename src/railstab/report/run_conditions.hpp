#pragma once
// What a report states about where and how it was computed: the scene file
// (path, SHA-256), railstab's version, the track at the reference point
// (tangent, or radius, turn and cant; the cant deficiency at each speed),
// and each contact model. One description for the Markdown and the JSON of
// every steady-state analysis, and the file-name tag that keeps a curve
// run's files apart from the tangent run's.
#include <railstab/io/json_writer.hpp>
#include <railstab/model/model.hpp>

#include <string>
#include <vector>

namespace railstab {

struct RunConditions {
  std::string scene_path;
  // Model::source_sha256: the scene file's hash, taken from the bytes read
  // when the scene was read; empty for a scene from text or built in code.
  std::string scene_sha256;
  std::string version;
  double reference_arc_length_m = 0.0;
  // Every body's track frame on straight, uncanted track at t = 0.
  bool tangent = true;
  // At the reference point.
  double curvature_per_m = 0.0;  // > 0 turns left
  double cant_m = 0.0;           // > 0 raises the right rail
  double rail_contact_distance_m = 1.5;
  double gravity_m_per_s2 = 9.81;
  std::vector<std::string> contacts;  // one line per contact model

  // Cant deficiency at speed V: the cant that would balance V^2 kappa,
  // V^2 |kappa| D / g, minus the cant on the curve's outer rail (m); 0 on
  // the tangent, -|cant| on a canted straight. Negative: cant excess. The
  // curving formula (curving/steady_curving.hpp), so the two agree.
  double cant_deficiency_m(double speed_m_per_s) const;
  // "tangent" or "arc R = 1000 m (left), cant 50 mm, at arc length 2000 m".
  std::string track_description() const;
};

RunConditions run_conditions(const Model& model);

// "" on the tangent, "_arc2000m" (the reference arc length, whole metres)
// otherwise: appended to the file stem of steady-state analyses.
std::string run_file_tag(const RunConditions& conditions);

// The scene file's stem (io/file_names.hpp, scene_file_stem) plus
// run_file_tag: the stem of equilibrium, eigen, critical-speed, modes,
// bifurcation, check and verify outputs.
std::string steady_state_file_stem(const std::string& scene_path, const Model& model);

// "conditions": {...} into an open JSON object; with `speeds`, the cant
// deficiency at each.
void write_conditions_json(JsonWriter& j, const RunConditions& c,
                           const std::vector<double>& speeds = {});

// Markdown lines (a bullet list) for a report's head.
std::string conditions_markdown(const RunConditions& c);

}  // namespace railstab
