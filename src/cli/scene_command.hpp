#pragma once
// The skeleton every command that reads a scene is built on: its shared
// flags (the scene, --set, --speed, --arc-length, --out, --no-plots) declared
// once, and the sequence prepare (read, override, build, first equilibrium)
// -> warn (the model check's warnings on stderr) -> analyse -> commit (the
// staged outputs moved into --out all at once) -> list what was written.
#include <railstab/io/output_set.hpp>
#include <railstab/setup/prepare_scene.hpp>

#include <CLI/CLI.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace railstab {

// A command's arguments derive from this.
struct SceneCommandArgs {
  std::string scene;
  SceneOverrides overrides;  // --set, --speed, --arc-length
  std::string out_dir = "out";
  bool plots = true;         // !--no-plots
};

// Which of the optional shared flags a command takes, and their help where
// it says something of the command's own.
struct SceneFlags {
  bool speed = false;
  bool arc_length = false;
  bool plots = false;
  std::string speed_help = "speed V in m/s (overrides the scene)";
  std::string arc_length_help =
      "arc length (m) of the scene's reference point, e.g. inside an arc for steady curving";
  std::string plots_help = "do not run gnuplot";
};

// The scene positional (an existing file), --set, --out and, as `which`
// says, --speed, --arc-length and --no-plots, each with its range check.
void add_scene_flags(CLI::App* cmd, SceneCommandArgs& a, const SceneFlags& which);

// Read the scene with the overrides, build the model and its static
// equilibrium; print the model check's warnings to stderr.
PreparedScene prepare_command_scene(const SceneCommandArgs& a);

// "wrote <file>" for every file of a committed output set, on `out`.
void list_written(const std::vector<std::string>& files, std::ostream& out);

}  // namespace railstab
