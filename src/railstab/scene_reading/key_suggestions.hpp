#pragma once
// "unknown key (did you mean 'mass_kg'?)": the key or choice a user most
// likely meant, for the table reader's messages. Internal to scene_reading/.
#include <string>
#include <string_view>
#include <vector>

namespace railstab::scene_reading {

// " (did you mean 'candidate'?)" for the closest candidate (the same stem
// before the unit suffix, else the nearest within a small edit distance),
// or "" if nothing fits.
std::string did_you_mean(std::string_view name, const std::vector<std::string_view>& candidates);

}  // namespace railstab::scene_reading
