#include <railstab/scene_reading/load_scene.hpp>

#include <railstab/io/regular_file.hpp>
#include <railstab/io/sha256.hpp>
#include <railstab/scene_reading/scene_checker.hpp>
#include <railstab/scene_reading/scene_reader.hpp>

#include <stdexcept>
#include <utility>

namespace railstab {

namespace {
// Read and checked: the file's element tables name the elements in messages.
SceneSpec read_and_check(const std::string& toml_text, const std::string& source_name) {
  scene_reading::SceneAsRead read = scene_reading::read_scene_document(toml_text, source_name);
  scene_reading::check_scene_as_read(read.spec, std::move(read.element_paths));
  return std::move(read.spec);
}
}  // namespace

std::string read_scene_text(const std::string& path) {
  // A named pipe, a folder or a device is refused before anything is read
  // (io/regular_file.hpp): a FIFO used to hang here.
  try {
    return read_regular_file(path);
  } catch (const std::runtime_error& e) {
    throw SceneError(path + ": scene file: " + e.what());
  }
}

SceneSpec load_scene_file(const std::string& path) {
  const std::string bytes = read_scene_text(path);
  SceneSpec scene = read_and_check(bytes, path);
  scene.source_sha256 = sha256_hex(bytes);
  return scene;
}

SceneSpec load_scene_file(const std::string& path, const std::vector<SceneValueSetting>& settings) {
  if (settings.empty()) return load_scene_file(path);
  const std::string bytes = read_scene_text(path);
  const std::string changed = scene_text_with_values(bytes, path, settings);
  SceneSpec scene;
  try {
    scene = read_and_check(changed, path);
  } catch (const SceneError& e) {
    throw SceneError(std::string(e.what()) + settings_in_force(settings));
  }
  scene.source_sha256 = sha256_hex(bytes);
  return scene;
}

SceneSpec load_scene_text(const std::string& toml_text, const std::string& source_name) {
  return read_and_check(toml_text, source_name);
}

std::vector<ContactSpec> read_scene_contacts(const std::string& path,
                                             const std::vector<SceneValueSetting>& settings) {
  std::string text = read_scene_text(path);
  if (!settings.empty()) text = scene_text_with_values(text, path, settings);
  return scene_reading::read_contacts_document(text, path);
}

const IrregularitySpec& required_track_irregularities(const SceneSpec& spec, const std::string& path) {
  if (!spec.track.irregularities)
    throw SceneError(path + ": track.irregularities: expected a [track.irregularities] table "
                     "(psd = \"erri_b176_low\", ...: docs/irregular_track.md), got none: the track is perfect");
  return *spec.track.irregularities;
}

}  // namespace railstab
