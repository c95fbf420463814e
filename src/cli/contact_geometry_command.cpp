#include "cli/contact_geometry_command.hpp"

#include <railstab/contact_geometry/contact_geometry_summary.hpp>
#include <railstab/contact_geometry/contact_table_file.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/contact_geometry/profile_contact_geometry.hpp>
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
};

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
  const TableContactGeometrySummary summary = summarise_table_contact_geometry(g);
  OutputSet outputs(a.out_dir);
  write_table_contact_geometry_report(g, summary, a.scene, spec.name, outputs,
                                      file_stem(scene_name + "_" + spec.name));
  std::ostringstream shown;
  shown << std::setprecision(4) << scene_name << " / " << spec.name << ": contact table "
        << g.table_source << "\n"
        << "  characteristic functions from the table for lateral shifts up to "
        << summary.lateral_reach_m * 1e3 << " mm\n";
  if (std::isfinite(summary.equivalent_conicity_at_3mm))
    shown << "  equivalent conicity (EN 15302) at 3 mm: " << summary.equivalent_conicity_at_3mm
          << "\n";
  else
    shown << "  equivalent conicity (EN 15302) at 3 mm: not computed (the motion leaves the "
             "table's lateral range)\n";
  if (g.flange_contact_shift_m)
    shown << "  flange contact at a lateral shift of " << *g.flange_contact_shift_m * 1e3
          << " mm (from the table file)\n";
  const std::vector<std::string> written = outputs.commit();
  std::cout << shown.str();
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
  const ProfilePair& pair = spec.profile_geometry->pair;
  const ContactGeometrySummary summary = summarise_contact_geometry(pair);
  // All files or none (io/output_set.hpp), names made safe (io/file_names.hpp).
  OutputSet outputs(a.out_dir);
  const std::string stem = file_stem(scene_name + "_" + spec.name);
  write_contact_geometry_report(pair, summary, scene_name, a.scene, spec.name, outputs, stem,
                                a.plots);
  // The contact table itself, for a contact with geometry = "table"
  // (contact_geometry/contact_table_file.hpp).
  outputs.write(stem + "_contact_table.csv", [&](std::ostream& out) {
    write_contact_table_file(out, *spec.profile_geometry,
                             "railstab contact-geometry " + a.scene + ", contact " + spec.name +
                                 ": " + pair.wheel.source + " on " + pair.rail.source);
  });
  std::ostringstream shown;
  shown << std::setprecision(4) << scene_name << " / " << spec.name << ": "
        << pair.wheel.source << " on " << pair.rail.source << "\n"
        << "  equivalent conicity (EN 15302) at 3 mm: " << summary.equivalent_conicity_at_3mm
        << "\n";
  if (summary.flange.found)
    shown << "  flange contact at a lateral shift of " << summary.flange.lateral_shift_m * 1e3
          << " mm (contact angle " << summary.flange.tread_contact_angle_rad << " -> "
          << summary.flange.flange_contact_angle_rad << " rad)\n";
  else
    shown << "  no flange contact up to 14 mm lateral shift\n";
  const std::vector<std::string> written = outputs.commit();
  std::cout << shown.str();
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
  cmd->callback([a] { run_contact_geometry(*a); });
}

}  // namespace railstab
