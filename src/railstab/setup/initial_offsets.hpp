#pragma once
// `--offset BODY.COORDINATE=VALUE`: a body's initial offset given on the
// command line instead of in the scene's initial_offset table, e.g.
//   --offset wheelset1.y_m=0.005     --offset bogie1.yaw_rad=0.002
// The coordinate keys are the initial_offset table's (x_m, y_m, z_m,
// roll_rad, pitch_rad, yaw_rad; scene_reading/coordinate_keys.hpp). BODY is
// a body's scene name; the name of a bogie frame (a rigid body joined by a
// force element to a wheelset, the rule of stability/mode_names.hpp) moves
// the frame and every wheelset joined to it by the same offset. Each
// setting replaces that coordinate's value in the scene's table (the other
// coordinates and bodies keep theirs), so a run with --offset is the run of
// the scene file with that line written in it.
#include <railstab/scene/scene_spec.hpp>

#include <string>
#include <vector>

namespace railstab {

struct OffsetSetting {
  std::string body;    // a body or bogie-frame name
  int coordinate = 0;  // 0..5: x, y, z, roll, pitch, yaw
  double value = 0.0;  // m or rad
  std::string text;    // as given, for messages
};

// Parses "wheelset1.y_m=0.005" (the body name may itself hold '.': the
// coordinate key is the text after the last '.'). Throws
// std::invalid_argument naming --offset, the text and what was expected.
OffsetSetting parse_offset_setting(const std::string& text);

// The bodies a setting moves (indices into spec.bodies): the named body, and
// for a bogie frame the wheelsets joined to it. Throws SceneError naming
// the file, --offset and the known body names when no body has that name.
std::vector<int> bodies_moved_by(const SceneSpec& spec, const OffsetSetting& setting);

// Writes the settings into the bodies' initial_offset, in order, after
// checking each value against the scene's range for an initial offset.
void apply_offset_settings(SceneSpec& spec, const std::vector<OffsetSetting>& settings);

}  // namespace railstab
