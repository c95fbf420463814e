#include "cli/track_command.hpp"

#include "cli/set_flag.hpp"

#include <railstab/io/file_names.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/irregularity/irregularity_check.hpp>
#include <railstab/report/irregularity_report.hpp>
#include <railstab/scene_reading/load_scene.hpp>

#include <iostream>
#include <memory>

namespace railstab {
namespace {

struct TrackArgs {
  std::string scene;
  std::string out_dir = "out";
  bool plots = true;
  std::vector<SceneValueSetting> values;  // --set KEY=VALUE
};

void run_track(const TrackArgs& a) {
  if (a.plots) require_gnuplot();
  const SceneSpec spec = load_scene_file(a.scene, a.values);
  const IrregularitySpec& wanted = required_track_irregularities(spec, a.scene);
  std::cerr << "synthesising " << wanted.length_m << " m of irregularities, " << wanted.components
            << " cosines per channel\n";
  const TrackIrregularities irregularities(wanted);
  const IrregularityCheck check = check_irregularities(irregularities);
  OutputSet outputs(a.out_dir);
  const std::string shown =
      write_irregularity_report(irregularities, check, spec.name, outputs, scene_file_stem(a.scene), a.plots);
  const std::vector<std::string> written = outputs.commit();
  std::cout << shown;
  for (const std::string& f : written)
    if (f.ends_with(".csv") || f.ends_with(".json") || f.ends_with(".png")) std::cout << "wrote " << f << "\n";
}

}  // namespace

void register_track_command(CLI::App& app) {
  auto a = std::make_shared<TrackArgs>();
  CLI::App* cmd = app.add_subcommand(
      "track", "the scene's track irregularities ([track.irregularities]): the channels as "
               "synthesised, their PSDs (Welch) against the target, rms, plots");
  cmd->add_option("scene", a->scene, "scene file (TOML) with a [track.irregularities] table")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", a->out_dir, "output directory")->capture_default_str();
  cmd->add_flag("!--no-plots", a->plots, "do not run gnuplot (CSV and JSON only)");
  add_set_flag(cmd, a->values);
  cmd->callback([a] { run_track(*a); });
}

}  // namespace railstab
