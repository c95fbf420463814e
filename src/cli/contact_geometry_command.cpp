#include "cli/contact_geometry_command.hpp"

#include <railstab/contact_geometry/contact_geometry_summary.hpp>
#include <railstab/contact_geometry/contact_table_file.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/contact_geometry/profile_contact_geometry.hpp>
#include "cli/numeric_flags.hpp"
#include "cli/set_flag.hpp"
#include <railstab/io/file_names.hpp>
#include <railstab/io/output_set.hpp>
#include <railstab/setup/contact_tables.hpp>
#include <railstab/report/contact_geometry_report.hpp>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace railstab {
namespace {

struct ContactGeometryArgs {
  std::string scene;
  std::string contact;
  std::string out_dir = "out";
  bool plots = true;
  std::vector<SceneValueSetting> values;  // --set KEY=VALUE
  ContactGeometrySummaryOptions grid;     // --delta-r-*, --amplitude-*
};

// Points that could not be computed, on stderr (the files hold them too:
// empty CSV fields, the JSON's not_computed).
void print_not_computed(const std::vector<NotComputed>& points) {
  for (const NotComputed& n : points)
    std::cerr << "warning: " << n.what << " not computed at " << n.at_m * 1e3
              << " mm: " << n.reason << "\n";
}

void print_conicity_at_3mm(std::ostream& shown, double conicity) {
  if (std::isfinite(conicity))
    shown << "  equivalent conicity (EN 15302) at 3 mm: " << conicity << "\n";
  else
    shown << "  equivalent conicity (EN 15302) at 3 mm: not computed (see the warnings)\n";
}

void print_written(const std::vector<std::string>& written) {
  for (const std::string& f : written)
    if (f.ends_with(".csv") || f.ends_with(".json") || f.ends_with(".png"))
      std::cout << "wrote " << f << "\n";
}

// A contact read from a table file: the characteristic functions and the
// conicity from the table (no profiles to plot).
void run_table_contact_geometry(const ContactGeometryArgs& a, const ContactSpec& spec,
                                const std::string& scene_name) {
  const ProfileContactGeometry& g = *spec.profile_geometry;
  const TableContactGeometrySummary summary = summarise_table_contact_geometry(g, a.grid);
  OutputSet outputs(a.out_dir);
  write_table_contact_geometry_report(g, summary, a.scene, spec.name, outputs,
                                      file_stem(scene_name + "_" + spec.name));
  std::ostringstream shown;
  shown << std::setprecision(4) << scene_name << " / " << spec.name << ": contact table "
        << g.table_source << "\n"
        << "  characteristic functions from the table for lateral shifts up to "
        << summary.lateral_reach_m * 1e3 << " mm\n";
  print_conicity_at_3mm(shown, summary.equivalent_conicity_at_3mm);
  if (g.flange_contact_shift_m)
    shown << "  flange contact at a lateral shift of " << *g.flange_contact_shift_m * 1e3
          << " mm (from the table file)\n";
  const std::vector<std::string> written = outputs.commit();
  std::cout << shown.str();
  print_not_computed(summary.not_computed);
  print_written(written);
}

void run_contact_geometry(const ContactGeometryArgs& a) {
  if (a.plots) require_gnuplot();  // before the work, not after it
  // The scene loader's own contact reader (the same keys, checks and
  // messages as in a scene), for a whole scene or a file of contacts alone.
  const std::vector<ContactSpec> contacts = load_scene_contacts(a.scene, a.values);
  const ContactSpec& spec = chosen_profile_contact(contacts, a.scene, a.contact);
  const std::string scene_name = std::filesystem::path(a.scene).stem().string();
  if (!spec.profile_geometry->has_profiles()) return run_table_contact_geometry(a, spec, scene_name);
  const ProfileContactGeometry& geometry = *spec.profile_geometry;
  const ProfilePair& pair = geometry.pair;
  ContactGeometrySummary summary;
  try {
    summary = summarise_contact_geometry(geometry.pairs(), a.grid);
  } catch (const ContactGeometryError& e) {  // no contact with the wheelset centred
    throw SceneError(a.scene + ": contacts." + spec.name + ": " + e.what());
  }
  // All files or none (io/output_set.hpp), names made safe (io/file_names.hpp).
  OutputSet outputs(a.out_dir);
  const std::string stem = file_stem(scene_name + "_" + spec.name);
  write_contact_geometry_report(geometry.pairs(), summary, scene_name, a.scene, spec.name, outputs, stem,
                                a.plots);
  // The contact table itself, for a contact with geometry = "table"
  // (contact_geometry/contact_table_file.hpp); its format holds one wheel,
  // so an asymmetric wheelset has none.
  if (!geometry.asymmetric())
    outputs.write(stem + "_contact_table.csv", [&](std::ostream& out) {
      write_contact_table_file(out, geometry,
                               "railstab contact-geometry " + a.scene + ", contact " + spec.name +
                                   ": " + pair.wheel.source + " on " + pair.rail.source);
    });
  else
    outputs.replaces(stem + "_contact_table.csv");
  std::ostringstream shown;
  shown << std::setprecision(4) << scene_name << " / " << spec.name << ": "
        << pair.wheel.source << " on " << pair.rail.source;
  if (geometry.asymmetric())
    shown << " (left); right " << geometry.pair_for(-1).wheel.source << " on "
          << geometry.pair_for(-1).rail.source << ", r0 "
          << geometry.pair_for(-1).parameters.nominal_rolling_radius_m << " m";
  shown << "\n";
  print_conicity_at_3mm(shown, summary.equivalent_conicity_at_3mm);
  if (std::isfinite(summary.equilibrium.low_m) &&
      std::abs(summary.equilibrium.centre_m()) > 1e-6)
    shown << "  equilibrium (delta r = 0) at a lateral shift of "
          << summary.equilibrium.centre_m() * 1e3 << " mm\n";
  if (summary.flange.found)
    shown << "  flange contact at a lateral shift of " << summary.flange.lateral_shift_m * 1e3
          << " mm (contact angle " << summary.flange.tread_contact_angle_rad << " -> "
          << summary.flange.flange_contact_angle_rad << " rad)\n";
  else
    shown << "  no flange contact up to " << (a.grid.amplitude_max_m + kConicityDeltaRMargin_m) * 1e3
          << " mm lateral shift\n";
  if (geometry.asymmetric())
    shown << "  (no _contact_table.csv: the table file holds one wheel, and this wheelset is "
             "asymmetric)\n";
  const std::vector<std::string> written = outputs.commit();
  std::cout << shown.str();
  print_not_computed(summary.not_computed);
  print_written(written);
}

}  // namespace

void register_contact_geometry_command(CLI::App& app) {
  auto a = std::make_shared<ContactGeometryArgs>();
  CLI::App* cmd = app.add_subcommand(
      "contact-geometry",
      "wheel-rail contact geometry of a profile pair: characteristic functions (delta r, roll, "
      "contact angles, radii) over lateral shifts -10..10 mm, EN 15302 equivalent conicity, plots, "
      "and the contact table (<stem>_contact_table.csv) for geometry = \"table\"; of a table "
      "contact: its characteristic functions and conicity");
  cmd->add_option("scene", a->scene, "scene file (TOML) with a [contacts.NAME] table, geometry = "
                                     "\"profiles\" or \"table\"")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--contact", a->contact,
                  "name of the contact (default: the only one with geometry = \"profiles\" or "
                  "\"table\")");
  cmd->add_option("--out", a->out_dir, "output directory")->capture_default_str();
  cmd->add_flag("!--no-plots", a->plots, "do not run gnuplot (CSV and JSON only)");
  add_set_flag(cmd, a->values);
  // The grids (EN 15302 leaves them to the user; defaults as before).
  const FlagRange half_range{1e-4, 0.03, false, false, "m"}, step{1e-6, 1e-3, false, false, "m"},
      amplitude{1e-5, 0.02, false, false, "m"};
  cmd->add_option("--delta-r-half-range-m", a->grid.lateral_range_m,
                  "characteristic functions (delta r ...) for lateral shifts -R..R")
      ->check(finite_in(half_range))
      ->capture_default_str();
  cmd->add_option("--delta-r-step-m", a->grid.lateral_step_m,
                  "step of the lateral shifts of the characteristic functions")
      ->check(finite_in(step))
      ->capture_default_str();
  cmd->add_option("--conicity-delta-r-step-m", a->grid.conicity_delta_r_step_m,
                  "step of the delta r function the conicity integrates (sampled over "
                  "+-(largest amplitude + 4 mm))")
      ->check(finite_in(step))
      ->capture_default_str();
  cmd->add_option("--amplitude-min-m", a->grid.amplitude_min_m, "smallest conicity amplitude")
      ->check(finite_in(amplitude))
      ->capture_default_str();
  cmd->add_option("--amplitude-max-m", a->grid.amplitude_max_m, "largest conicity amplitude")
      ->check(finite_in(amplitude))
      ->capture_default_str();
  cmd->add_option("--amplitude-step-m", a->grid.amplitude_step_m, "step of the conicity amplitudes")
      ->check(finite_in(amplitude))
      ->capture_default_str();
  cmd->callback([a] {
    try {
      check_summary_options(a->grid);
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError(std::string("--") + e.what());
    }
    run_contact_geometry(*a);
  });
}

}  // namespace railstab
