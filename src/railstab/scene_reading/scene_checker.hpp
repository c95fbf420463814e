#pragma once
// The semantic checks of a scene: what a well-formed file can still get
// wrong (masses and every other number in its physical range, physical
// inertias, unique names, known bodies and contacts, wheelsets on the
// rails, speed > 0 with creep forces, every body on the track, ...). The
// table reader has already checked types and keys; this runs on the
// SceneSpec, so it also checks a scene built or changed in code.
//
// A run checks its scene once: load_scene_file / load_scene_text
// (scene_reading/load_scene.hpp) check what they read, and the set-up step
// (setup/prepare_scene.hpp) checks only the values a run replaces
// (--speed, --t-end, --arc-length) with validate_replaced_values.
#include <railstab/scene/scene_spec.hpp>
#include <railstab/scene_reading/scene_error.hpp>

#include <string>
#include <vector>

namespace railstab {

// Every check; throws the first failure as a SceneError. Elements are named
// elements['<name>'] (without the file at hand, an element's index no
// longer matches its [[elements]] table once mirroring made two of one).
void validate_scene(const SceneSpec& scene);

// The values of a checked scene that a run replaced.
struct ReplacedSceneValues {
  bool speed = false;                 // scene.speed_m_per_s
  bool t_end = false;                 // simulation.t_end_s
  bool reference_arc_length = false;  // scene.reference_arc_length_m
};

// The checks of validate_scene that read the replaced values, in the same
// order and with the same messages; the rest of the scene was checked when
// it was read and has not changed.
void validate_replaced_values(const SceneSpec& scene, const ReplacedSceneValues& replaced);

namespace scene_reading {

// Every check of a scene as read from a file: element i is named by
// element_paths[i], the key path of the table it came from ("elements[3]",
// "train.couplers[0]"; a mirrored table gives two elements the same path).
void check_scene_as_read(const SceneSpec& scene, std::vector<std::string> element_paths);

}  // namespace scene_reading
}  // namespace railstab
