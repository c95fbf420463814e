#pragma once
#include <CLI/CLI.hpp>

namespace railstab {
// `railstab study` (critical speed over combinations of scene values, in
// parallel, optionally one shard of them) and `railstab merge` (the shards'
// records joined into the files of the whole study).
void register_study_commands(CLI::App& app);
}  // namespace railstab
