#include <railstab/report/run_conditions.hpp>

#include <railstab/contact_geometry/profile_contact_geometry.hpp>
#include <railstab/core/version.hpp>
#include <railstab/curving/steady_curving.hpp>
#include <railstab/io/file_names.hpp>
#include <railstab/report/markdown_text.hpp>

#include <cmath>
#include <sstream>
#include <type_traits>
#include <variant>

namespace railstab {

namespace {

// "shen_hedrick_elkins (friction_coefficient 0.4, kalker_reduction_factor 1)"
std::string creep_law_description(const CreepLawSpec& law) {
  return std::visit(
      [](auto l) {  // a copy: for_each_parameter hands out references
        std::ostringstream s;
        s << std::decay_t<decltype(l)>::kName;
        const char* sep = " (";
        l.for_each_parameter([&](const std::string& key, int, double& value) {
          s << sep << key << " " << value;
          sep = ", ";
        });
        if (std::string(sep) == ", ") s << ")";
        return s.str();
      },
      law);
}

std::string contact_description(const ModelContact& c) {
  const ContactSpec& spec = c.spec;
  std::ostringstream s;
  s.precision(6);
  s << spec.name << ": " << contact_geometry_name(spec.geometry);
  if (uses_contact_table(spec.geometry) && spec.profile_geometry &&
      !spec.profile_geometry->has_profiles())
    s << " " << spec.profile_geometry->table_source;
  else if (uses_contact_table(spec.geometry) && spec.profile_geometry)
    s << " " << spec.profile_geometry->pair.wheel.source << " on "
      << spec.profile_geometry->pair.rail.source;
  else if (spec.geometry == ContactGeometryKind::knife_edge_cone)
    s << " gamma " << c.cone_angle_rad << " rad";
  else
    s << " lambda " << c.conicity;
  s << ", r0 " << spec.nominal_rolling_radius_m << " m, normal "
    << normal_force_name(spec.normal) << ", creep law "
    << creep_law_description(c.creep_law);
  return s.str();
}

}  // namespace

double RunConditions::cant_deficiency_m(double speed_m_per_s) const {
  return railstab::cant_deficiency_m(CurvingCondition{curvature_per_m, cant_m, speed_m_per_s},
                                     rail_contact_distance_m, gravity_m_per_s2);
}

std::string RunConditions::track_description() const {
  std::ostringstream s;
  s.precision(6);
  if (tangent) {
    s << "tangent (reference point at arc length " << reference_arc_length_m << " m)";
    return s.str();
  }
  if (curvature_per_m != 0.0)
    s << "arc R = " << 1.0 / std::abs(curvature_per_m) << " m ("
      << (curvature_per_m > 0.0 ? "left" : "right") << ")";
  else
    s << "straight";
  s << ", cant " << cant_m * 1e3 << " mm, reference point at arc length "
    << reference_arc_length_m << " m";
  return s.str();
}

namespace {
// Every body's track frame on straight, uncanted track at t = 0.
bool all_bodies_on_tangent(const Model& model) {
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const TrackGeometryPoint g = model.track.geometry_at(model.arc_length_of(int(b), 0.0, 0.0));
    if (g.curvature_per_m != 0.0 || g.cant_m != 0.0) return false;
  }
  const TrackGeometryPoint ref = model.track.geometry_at(model.reference_arc_length_m);
  return ref.curvature_per_m == 0.0 && ref.cant_m == 0.0;
}
}  // namespace

RunConditions run_conditions(const Model& model) {
  RunConditions c;
  c.scene_path = model.source_path;
  c.scene_sha256 = model.source_sha256;  // taken when the file was read (empty from text)
  c.version = railstab_version();
  c.reference_arc_length_m = model.reference_arc_length_m;
  c.rail_contact_distance_m = model.track.spec().rail_contact_distance_m;
  c.gravity_m_per_s2 = model.gravity_m_per_s2;
  const TrackGeometryPoint ref = model.track.geometry_at(model.reference_arc_length_m);
  c.curvature_per_m = ref.curvature_per_m;
  c.cant_m = ref.cant_m;
  c.tangent = all_bodies_on_tangent(model);
  for (const ModelContact& contact : model.contacts) c.contacts.push_back(contact_description(contact));
  return c;
}

namespace {
// "" on the tangent, "_arc<s>m" (whole metres) otherwise.
std::string arc_tag(bool tangent, double reference_arc_length_m) {
  if (tangent) return "";
  return "_arc" + std::to_string(std::lround(reference_arc_length_m)) + "m";
}
}  // namespace

std::string run_file_tag(const RunConditions& c) {
  return arc_tag(c.tangent, c.reference_arc_length_m);
}

// Not through run_conditions(): naming needs no hash of the scene file.
std::string steady_state_file_stem(const std::string& scene_path, const Model& model) {
  return scene_file_stem(scene_path) + arc_tag(all_bodies_on_tangent(model), model.reference_arc_length_m);
}

void write_conditions_json(JsonWriter& j, const RunConditions& c,
                           const std::vector<double>& speeds) {
  j.key("conditions").begin_object();
  j.field("scene_file", c.scene_path);
  if (c.scene_sha256.empty()) j.key("scene_sha256").null();
  else j.field("scene_sha256", c.scene_sha256);
  j.field("railstab_version", c.version)
      .field("track", c.track_description())
      .field("tangent", c.tangent)
      .field("reference_arc_length_m", c.reference_arc_length_m)
      .field("curvature_per_m", c.curvature_per_m)
      .field("cant_m", c.cant_m);
  if (c.curvature_per_m != 0.0) j.field("radius_m", 1.0 / std::abs(c.curvature_per_m));
  else j.key("radius_m").null();
  j.key("contacts").begin_array();
  for (const std::string& s : c.contacts) j.value(s);
  j.end_array();
  if (!speeds.empty()) {
    j.key("cant_deficiency_by_speed").begin_array();
    for (double v : speeds)
      j.begin_object().field("speed_m_per_s", v).field("cant_deficiency_m", c.cant_deficiency_m(v)).end_object();
    j.end_array();
  }
  j.end_object();
}

std::string conditions_markdown(const RunConditions& c) {
  std::ostringstream s;
  s << "- track: " << md_text(c.track_description()) << "\n";
  for (const std::string& contact : c.contacts) s << "- contact " << md_text(contact) << "\n";
  s << "- scene file `" << md_text(c.scene_path) << "`, SHA-256 "
    << (c.scene_sha256.empty() ? std::string("(not a file)") : "`" + c.scene_sha256 + "`") << "\n"
    << "- railstab " << c.version << "\n";
  return s.str();
}

}  // namespace railstab
