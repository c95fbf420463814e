#include <railstab/report/contact_geometry_report.hpp>

#include <railstab/contact_geometry/wheelset_pose.hpp>
#include <railstab/io/json_writer.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/io/output_set.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace railstab {
namespace {

// A CSV field; refuses non-finite numbers.
struct Csv {
  std::ostream& out;
  bool first = true;
  Csv& operator<<(double v) {
    if (!std::isfinite(v)) throw std::runtime_error("non-finite value in a contact-geometry CSV");
    out << (first ? "" : ",") << v;
    first = false;
    return *this;
  }
  Csv& empty() {
    out << (first ? "" : ",");
    first = false;
    return *this;
  }
  void end() {
    out << '\n';
    first = true;
  }
};

void write_contact(Csv& c, const ContactPoint* p) {
  if (p) c << p->contact_angle_rad << p->rolling_radius_m << p->rail_y_m << p->wheel_u_m << p->vertical_gap_m;
  else c.empty().empty().empty().empty().empty();
}

// The "equivalent_conicity" array of the JSON: one object per amplitude.
// wavelength_m is null where the conicity is 0 (no restoring: infinite).
void write_conicity_points(JsonWriter& j, const std::vector<ConicityPoint>& points) {
  j.key("equivalent_conicity").begin_array();
  for (const ConicityPoint& c : points) {
    j.begin_object().field("amplitude_m", c.amplitude_m);
    if (std::isfinite(c.wavelength_m)) j.field("wavelength_m", c.wavelength_m);
    else j.key("wavelength_m").null();
    j.field("equivalent_conicity", c.equivalent_conicity)
        .field("lower_turning_point_m", c.lower_turning_point_m)
        .field("upper_turning_point_m", c.upper_turning_point_m)
        .end_object();
  }
  j.end_array();
}

// The conicity CSV: one row per amplitude of the grid; a point that could
// not be computed has empty fields (its reason is in the JSON), a conicity
// of 0 an empty wavelength.
template <class Summary>
void write_conicity_csv(std::ostream& out, const Summary& s) {
  out << std::setprecision(10)
      << "amplitude_m,wavelength_m,equivalent_conicity,lower_turning_point_m,"
         "upper_turning_point_m\n";
  struct Row {
    double amplitude;
    const ConicityPoint* point;
  };
  std::vector<Row> rows;
  for (const ConicityPoint& p : s.conicity) rows.push_back({p.amplitude_m, &p});
  for (const NotComputed& n : s.not_computed)
    if (n.what == "equivalent conicity" && n.at_m > 0.0) {
      bool listed = false;
      for (const Row& r : rows) listed |= std::abs(r.amplitude - n.at_m) < 1e-12;
      if (!listed) rows.push_back({n.at_m, nullptr});
    }
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.amplitude < b.amplitude; });
  Csv c{out};
  for (const Row& r : rows) {
    c << r.amplitude;
    if (!r.point) {
      c.empty().empty().empty().empty();
    } else {
      if (std::isfinite(r.point->wavelength_m)) c << r.point->wavelength_m;
      else c.empty();
      c << r.point->equivalent_conicity << r.point->lower_turning_point_m
        << r.point->upper_turning_point_m;
    }
    c.end();
  }
}

// The JSON's equilibrium and the points not computed.
template <class Summary>
void write_equilibrium_and_failures(JsonWriter& j, const Summary& s) {
  if (std::isfinite(s.equilibrium.low_m)) {
    j.field("equilibrium_lateral_m", s.equilibrium.centre_m())
        .field("equilibrium_zero_delta_r_from_m", s.equilibrium.low_m)
        .field("equilibrium_zero_delta_r_to_m", s.equilibrium.high_m);
  }
  j.key("not_computed").begin_array();
  for (const NotComputed& n : s.not_computed)
    j.begin_object()
        .field("what", n.what)
        .field("at_m", n.at_m)
        .field("reason", n.reason)
        .end_object();
  j.end_array();
}

const char* kLateralShiftDefinition =
    "EN 15302: lateral displacement of the wheelset relative to the track, y = y_centre + "
    "r0_mean sin(roll) (the midpoint of the tape circles' lowest points); the CSV's "
    "wheelset_centre_y_m is the wheelset centre's";

}  // namespace

void write_contact_geometry_report(const WheelsetProfilePairs& pairs,
                                   const ContactGeometrySummary& s,
                                   const std::string& scene_name, const std::string& scene_file,
                                   const std::string& contact_name, OutputSet& outputs,
                                   const std::string& stem, bool plots) {
  const ProfilePair& pair = pairs.left;
  const bool asymmetric = &pairs.left != &pairs.right;
  struct {
    std::string characteristic_csv, conicity_csv, json;
  } files;
  files.characteristic_csv = stem + "_characteristic.csv";
  files.conicity_csv = stem + "_conicity.csv";
  files.json = stem + ".json";
  const std::string profiles_dat = stem + "_profiles.dat";
  const std::string png_profiles = stem + "_profiles.png";
  const std::string png_delta_r = stem + "_delta_r.png";
  const std::string png_conicity = stem + "_conicity.png";
  const std::string script = stem + "_plots.gp";
  // A run without plots removes an earlier run's plots of these names, so
  // old plots never sit beside new data.
  for (const std::string& f : {profiles_dat, png_profiles, png_delta_r, png_conicity, script})
    outputs.replaces(f);

  outputs.write(files.characteristic_csv, [&](std::ostream& out) {
    out << std::setprecision(10);
    out << "y_m,delta_r_m,roll_rad,vertical_m,contact_angle_left_rad,contact_angle_right_rad,"
           "rolling_radius_left_m,rolling_radius_right_m,contact_y_rail_left_m,"
           "contact_y_rail_right_m,contact_u_wheel_left_m,contact_u_wheel_right_m,"
           "contacts_left,contacts_right,"
           "second_contact_angle_left_rad,second_rolling_radius_left_m,"
           "second_contact_y_rail_left_m,second_contact_u_wheel_left_m,second_gap_left_m,"
           "second_contact_angle_right_rad,second_rolling_radius_right_m,"
           "second_contact_y_rail_right_m,second_contact_u_wheel_right_m,second_gap_right_m,"
           "wheelset_centre_y_m\n";
    Csv c{out};
    for (const CharacteristicRow& row : s.rows) {
      const RigidContactSolution& r = row.solution;
      if (!row.computed()) {  // a shift without rigid contact: y alone (reason in the JSON)
        c << r.lateral_m;
        for (int k = 0; k < 24; ++k) c.empty();
        c.end();
        continue;
      }
      const ContactPoint &l = r.left.front(), &rr = r.right.front();
      c << r.lateral_m << row.delta_r_m() << r.roll_rad << r.vertical_m << l.contact_angle_rad
        << rr.contact_angle_rad << l.rolling_radius_m << rr.rolling_radius_m << l.rail_y_m
        << rr.rail_y_m << l.wheel_u_m << rr.wheel_u_m << double(r.contacts_left())
        << double(r.contacts_right());
      write_contact(c, r.left.size() > 1 ? &r.left[1] : nullptr);
      write_contact(c, r.right.size() > 1 ? &r.right[1] : nullptr);
      c << r.centre_lateral_m;
      c.end();
    }
  });
  outputs.write(files.conicity_csv, [&](std::ostream& out) { write_conicity_csv(out, s); });
  outputs.write(files.json, [&](std::ostream& out) {
    JsonWriter j(out);
    const ProfilePairParameters& p = pair.parameters;
    j.begin_object()
        .field("scene_file", scene_file)
        .field("contact", contact_name)
        .field("wheel_profile", pair.wheel.source)
        .field("rail_profile", pair.rail.source)
        .field("asymmetric_wheelset", asymmetric);
    if (asymmetric)
      j.field("right_wheel_profile", pairs.right.wheel.source)
          .field("right_rail_profile", pairs.right.rail.source)
          .field("right_nominal_rolling_radius_m",
                 pairs.right.parameters.nominal_rolling_radius_m);
    j
        .field("track_gauge_m", p.track_gauge_m)
        .field("gauge_measuring_height_m", p.gauge_measuring_height_m)
        .field("flange_back_distance_m", p.flange_back_distance_m)
        .field("nominal_rolling_radius_m", p.nominal_rolling_radius_m)
        .field("rail_inclination_rad", p.rail_inclination_rad)
        .field("tape_circle_from_flange_back_m", p.tape_circle_from_flange_back_m)
        .field("rail_gauge_point_y_m", pair.gauge_point_y_m)
        .field("half_contact_distance_m", s.half_contact_distance_m)
        .field("klingel_rolling_radius_m", s.nominal_rolling_radius_m)
        .field("lateral_shift", kLateralShiftDefinition)
        .field("method", "EN 15302: integration of the Klingel motion y'' = -delta_r(y)/(2 e0 r0) "
                         "over the rigid-contact delta_r function (yaw neglected) from a turning "
                         "point; amplitude = half the peak-to-peak motion about the equilibrium; "
                         "tan(gamma_e) = r0 e0 (2 pi / lambda)^2; conicity 0 where the motion "
                         "stays on a stretch of zero delta_r")
        .field("reference_amplitude_m", kConicityReferenceAmplitude_m);
    if (std::isfinite(s.equivalent_conicity_at_3mm))
      j.field("equivalent_conicity_at_reference_amplitude", s.equivalent_conicity_at_3mm);
    else
      j.key("equivalent_conicity_at_reference_amplitude").null();
    j.field("flange_contact_found", s.flange.found);
    if (s.flange.found) j.field("flange_contact_shift_m", s.flange.lateral_shift_m);
    write_equilibrium_and_failures(j, s);
    write_conicity_points(j, s.conicity);
    j.end_object();
  });

  if (!plots) return;

  // Plot data: the left rail and the centred left wheel in the track frame
  // (mm), and one line per lateral shift from the rail contact point to the
  // wheel point that touches it (drawn on the centred wheel).
  outputs.write(profiles_dat, [&](std::ostream& out) {
    out << std::setprecision(8) << "# left rail (track frame, mm)\n";
    for (size_t i = 0; i < pair.rail.y_m.size(); ++i)
      out << (pair.rail_offset_y_m + pair.rail.y_m[i]) * 1e3 << ' '
          << (pair.rail.z_m[i] - pair.rail_top_z_m) * 1e3 << '\n';
    out << "\n\n# centred left wheel (rigid contact at y = 0)\n";
    const RigidContactSolution centred = solve_rigid_contact(pair, 0.0);
    const double lift = centred.vertical_m;  // wheel height in the rail frame offset
    const WheelPoseOf<double> pose =
        wheel_pose_in_rail_frame<double>(pair, +1, 0.0, lift, centred.roll_rad);
    auto wheel_point = [&](double u, double& yT, double& zT) {
      const double c = std::cos(pose.roll_rad), sn = std::sin(pose.roll_rad);
      const double zw = pair.wheel_z(u);
      yT = pair.rail_offset_y_m + pose.lateral_m + u * c - zw * sn;
      zT = pose.vertical_m + u * sn + zw * c - pair.rail_top_z_m;
    };
    for (size_t i = 0; i < pair.wheel.y_m.size(); ++i) {
      double yT, zT;
      wheel_point(pair.wheel.y_m[i], yT, zT);
      out << yT * 1e3 << ' ' << zT * 1e3 << '\n';
    }
    out << "\n\n# contact-point lines, every 0.5 mm of shift\n";
    for (const CharacteristicRow& row : s.rows) {
      if (!row.computed()) continue;
      const double y = row.solution.lateral_m;
      if (std::abs(std::remainder(y, 5e-4)) > 1e-9) continue;
      for (const ContactPoint& cp : row.solution.left) {
        if (cp.vertical_gap_m > kSecondContactGapTolerance_m) continue;
        double yT, zT;
        wheel_point(cp.wheel_u_m, yT, zT);
        out << (pair.rail_offset_y_m + cp.rail_y_m) * 1e3 << ' '
            << (cp.rail_z_m - pair.rail_top_z_m) * 1e3 << '\n'
            << yT * 1e3 << ' ' << zT * 1e3 << "\n\n";
      }
    }
  });
  // Names and titles as gnuplot string literals (a quote in a scene or
  // contact name cannot end the string and run commands); gnuplot runs in
  // the staging folder, where these files are.
  const std::string title = scene_name + " / " + contact_name;
  auto text = [](const std::string& t) { return gnuplot_text(t); };
  auto path = [](const std::string& f) { return gnuplot_path(f); };
  std::ostringstream conicity_at_3mm;
  conicity_at_3mm << s.equivalent_conicity_at_3mm;
  outputs.write(script, [&](std::ostream& gp) {
    gp << "set terminal pngcairo size 1000,620 font 'Sans,10' noenhanced\nset grid\n"
       << "set output " << path(png_profiles) << "\n"
       << "set title " << text(title + ": left wheel (centred) on its rail; lines join the rail "
                               "and wheel contact points for shifts -10..10 mm (every 0.5 mm)")
       << "\nset xlabel 'y, track frame [mm]'\nset ylabel 'z [mm]'\nset size ratio -1\n"
       << "plot " << path(profiles_dat) << " index 0 with lines lw 2 title 'rail', "
       << path(profiles_dat) << " index 1 with lines lw 2 title 'wheel', " << path(profiles_dat)
       << " index 2 with lines lc rgb 'gray40' title 'contact points'\n"
       << "set size noratio\nset datafile separator ','\n"
       << "set output " << path(png_delta_r) << "\n"
       << "set title " << text(title + ": rolling-radius difference (rigid contact)") << "\n"
       << "set xlabel 'lateral shift y [mm]'\nset ylabel 'delta r = r_left - r_right [mm]'\n"
       << "plot " << path(files.characteristic_csv)
       << " skip 1 using ($1*1e3):($2*1e3) with lines lw 2 title 'delta r'\n"
       << "set output " << path(png_conicity) << "\n"
       << "set title "
       << text(title + ": equivalent conicity (EN 15302, Klingel integration); at 3 mm: " +
               conicity_at_3mm.str())
       << "\nset xlabel 'amplitude [mm]'\nset ylabel 'equivalent conicity tan(gamma_e)'\n"
       << "plot " << path(files.conicity_csv)
       << " skip 1 using ($1*1e3):3 with linespoints lw 2 title 'equivalent conicity'\n"
       << "unset output\n";
  });
  const std::vector<std::string> pngs = {png_profiles, png_delta_r, png_conicity};
  for (const std::string& f : pngs) outputs.add(f);
  run_gnuplot(script, outputs.staging_dir(), pngs);
}

void write_table_contact_geometry_report(const ProfileContactGeometry& g,
                                         const TableContactGeometrySummary& s,
                                         const std::string& scene_file,
                                         const std::string& contact_name, OutputSet& outputs,
                                         const std::string& stem) {
  outputs.write(stem + "_characteristic.csv", [&](std::ostream& out) {
    out << std::setprecision(10);
    out << "y_m,delta_r_m,roll_rad,contact_angle_left_rad,contact_angle_right_rad,"
           "rolling_radius_left_m,rolling_radius_right_m,contact_y_rail_left_m,"
           "contact_y_rail_right_m,contact_u_wheel_left_m,contact_u_wheel_right_m,slot_left,"
           "slot_right,wheelset_centre_y_m\n";
    Csv c{out};
    for (const TableRigidRow& r : s.rows) {
      c << r.lateral_m << r.delta_r_m() << r.roll_rad << r.left.contact_angle_rad
        << r.right.contact_angle_rad << r.left.rolling_radius_m << r.right.rolling_radius_m
        << r.left.rail_y_m << r.right.rail_y_m << r.left.wheel_u_m << r.right.wheel_u_m
        << double(r.left.slot) << double(r.right.slot) << r.centre_lateral_m;
      c.end();
    }
  });
  outputs.write(stem + "_conicity.csv", [&](std::ostream& out) { write_conicity_csv(out, s); });
  outputs.write(stem + ".json", [&](std::ostream& out) {
    JsonWriter j(out);
    j.begin_object()
        .field("scene_file", scene_file)
        .field("contact", contact_name)
        .field("contact_table", g.table_source)
        .field("nominal_rolling_radius_m", g.pair.parameters.nominal_rolling_radius_m)
        .field("half_contact_distance_m", s.half_contact_distance_m)
        .field("lateral_reach_m", s.lateral_reach_m)
        .field("lateral_shift", kLateralShiftDefinition)
        .field("method", "EN 15302: integration of the Klingel motion y'' = -delta_r(y)/(2 e0 r0) "
                         "over the rigid-contact delta_r function evaluated on the contact table "
                         "(yaw neglected) from a turning point; amplitude = half the "
                         "peak-to-peak motion about the equilibrium; "
                         "tan(gamma_e) = r0 e0 (2 pi / lambda)^2")
        .field("reference_amplitude_m", kConicityReferenceAmplitude_m);
    if (std::isfinite(s.equivalent_conicity_at_3mm))
      j.field("equivalent_conicity_at_reference_amplitude", s.equivalent_conicity_at_3mm);
    j.field("flange_contact_found", g.flange_contact_shift_m.has_value());
    if (g.flange_contact_shift_m) j.field("flange_contact_shift_m", *g.flange_contact_shift_m);
    write_equilibrium_and_failures(j, s);
    write_conicity_points(j, s.conicity);
    j.end_object();
  });
}

}  // namespace railstab
