#pragma once
#include <CLI/CLI.hpp>

namespace railstab {
// `railstab contact-geometry SCENE [--contact NAME] [--out DIR]`
void register_contact_geometry_command(CLI::App& app);
}  // namespace railstab
