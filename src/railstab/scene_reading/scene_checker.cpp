#include <railstab/scene_reading/scene_checker.hpp>

#include <railstab/scene/physical_ranges.hpp>
#include <railstab/scene_reading/coordinate_keys.hpp>
#include <railstab/scene_reading/scene_messages.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>
#include <utility>

namespace railstab {
namespace scene_reading {
namespace {

std::string contact_path(const ContactSpec& contact) {
  return child_path("contacts", contact.name);
}
std::string body_path(size_t index) { return indexed_path("bodies", index); }

// validate_scene, one check per function. Element messages use the key path
// of the [[elements]] table the element came from (mirroring makes two).
class SceneChecker {
 public:
  SceneChecker(const SceneSpec& scene, std::vector<std::string> element_paths)
      : scene_(scene),
        source_(scene.source_path.empty() ? "<scene>" : scene.source_path),
        element_paths_(std::move(element_paths)) {}

  void check_all() const {
    check_scene_numbers();
    check_simulation();
    check_track();
    check_contact_names();
    for (const ContactSpec& contact : scene_.contacts) check_contact(contact);
    check_body_names();
    for (size_t i = 0; i < scene_.bodies.size(); ++i) check_body(i);
    for (size_t i = 0; i < scene_.elements.size(); ++i) check_element(i);
    check_speed_for_creep_forces();
    check_bodies_on_track();
  }

  // The checks of check_all that read a replaced value, in its order.
  void check_replaced(const ReplacedSceneValues& replaced) const {
    if (replaced.reference_arc_length) check_scene_numbers();
    if (replaced.t_end) check_simulation();
    if (replaced.speed) check_speed_for_creep_forces();
    if (replaced.reference_arc_length) check_bodies_on_track();
  }

 private:
  [[noreturn]] void fail(std::string_view path, std::string_view expected,
                         std::string_view found) const {
    fail_expectation(source_, path, expected, found);
  }
  // Every number in its physical range (scene/physical_ranges.hpp).
  void require_in(std::string_view path, double value, const PhysicalRange& range) const {
    if (!range.contains(value)) fail(path, range_text(range), format_number(value));
  }
  void require_each_in(std::string_view path, const Eigen::Vector3d& values,
                       const PhysicalRange& range) const {
    for (Eigen::Index i = 0; i < 3; ++i)
      require_in(indexed_path(path, size_t(i)), values(i), range);
  }
  void check_name(std::string_view path, const std::string& name) const {
    if (const std::optional<std::string> problem = name_problem(name))
      fail(path, name_expectation(), *problem);
  }

  void check_scene_numbers() const {
    namespace r = physical_ranges;
    check_name("scene.name", scene_.name);
    require_in("scene.gravity_m_per_s2", scene_.gravity_m_per_s2, r::gravity_m_per_s2);
    for (const BodySpec& body : scene_.bodies) {
      const ContactSpec* contact = body.is_wheelset ? find_contact(body.contact) : nullptr;
      if (contact && contact->normal == NormalForceKind::hertz) {
        require_in("scene.gravity_m_per_s2", scene_.gravity_m_per_s2,
                   r::gravity_with_hertz_contact_m_per_s2);
        break;
      }
    }
    require_in("scene.reference_arc_length_m", scene_.reference_arc_length_m, r::arc_length_m);
    require_in("assessment.prudhomme_factor", scene_.assessment.prudhomme_factor,
               r::prudhomme_factor);
  }

  void check_simulation() const {
    namespace r = physical_ranges;
    const SimulationSpec& simulation = scene_.simulation;
    require_in("simulation.t_end_s", simulation.t_end_s, r::t_end_s);
    require_in("simulation.output_interval_s", simulation.output_interval_s, r::output_interval_s);
    require_in("simulation.relative_tolerance", simulation.relative_tolerance,
               r::relative_tolerance);
    require_in("simulation.absolute_tolerance", simulation.absolute_tolerance,
               r::absolute_tolerance);
    // The integrator would refuse the run later (integrate/integrator.hpp);
    // say it here, with the keys, before any model is built.
    const double outputs = std::ceil(simulation.t_end_s / simulation.output_interval_s - 1e-9);
    if (!(outputs <= r::kMaxOutputs))
      fail("simulation.output_interval_s",
           "at most " + format_number(r::kMaxOutputs) +
               " stored outputs (t_end_s / output_interval_s; lengthen output_interval_s or "
               "shorten t_end_s)",
           "t_end_s = " + format_number(simulation.t_end_s) + " s / output_interval_s = " +
               format_number(simulation.output_interval_s) + " s = " + format_number(outputs) +
               " outputs");
  }

  void check_cant(std::string_view path, double cant_m) const {
    const double distance = scene_.track.rail_contact_distance_m;
    if (!(std::abs(cant_m) < distance))
      fail(path, "|cant| < rail_contact_distance_m = " + format_number(distance) + " m",
           format_number(cant_m));
  }

  void check_track() const {
    namespace r = physical_ranges;
    const TrackSpec& track = scene_.track;
    require_in("track.rail_contact_distance_m", track.rail_contact_distance_m,
               r::rail_contact_distance_m);
    require_in("track.start_x_m", track.start_x_m, r::track_position_m);
    require_in("track.start_y_m", track.start_y_m, r::track_position_m);
    require_in("track.start_z_m", track.start_z_m, r::track_position_m);
    require_in("track.start_heading_rad", track.start_heading_rad, r::heading_rad);
    require_in("track.start_curvature_per_m", track.start_curvature_per_m, r::curvature_per_m);
    check_cant("track.start_cant_m", track.start_cant_m);
    if (track.segments.empty())
      fail("track.segments", "at least one segment [[track.segments]]", "none");
    for (size_t i = 0; i < track.segments.size(); ++i) {
      const std::string path = indexed_path("track.segments", i);
      require_in(child_path(path, "length_m"), track.segments[i].length_m, r::segment_length_m);
      check_cant(child_path(path, "end_cant_m"), track.segments[i].end_cant_m);
      require_in(child_path(path, "end_curvature_per_m"), track.segments[i].end_curvature_per_m,
                 r::curvature_per_m);
    }
  }

  void check_contact_names() const {
    for (size_t i = 0; i < scene_.contacts.size(); ++i) {
      const std::string& name = scene_.contacts[i].name;
      if (name.empty()) fail(indexed_path("contacts", i), "a named contact", "an empty name");
      if (const std::optional<std::string> problem = name_problem(name))
        fail(indexed_path("contacts", i), "a contact name of 1 to " +
             std::to_string(physical_ranges::kMaxNameBytes) + " bytes without control characters",
             *problem);
      for (size_t j = 0; j < i; ++j)
        if (scene_.contacts[j].name == name)
          fail(contact_path(scene_.contacts[i]), "a unique contact name", quoted(name) + " twice");
    }
  }

  void check_contact(const ContactSpec& contact) const {
    const std::string path = contact_path(contact);
    auto at = [&](std::string_view key) { return child_path(path, key); };
    namespace r = physical_ranges;
    if (contact.geometry == ContactGeometryKind::knife_edge_cone)
      require_in(at("cone_angle_rad"), contact.cone_angle_rad, r::cone_angle_rad);
    if (contact.geometry == ContactGeometryKind::linear_conicity)
      require_in(at("conicity"), contact.conicity, r::conicity);
    if (!uses_contact_table(contact.geometry)) {
      require_in(at("half_contact_distance_m"), contact.half_contact_distance_m,
                 r::half_contact_distance_m);
      check_contact_distances(at("half_contact_distance_m"), contact.half_contact_distance_m);
    }
    require_in(at("nominal_rolling_radius_m"), contact.nominal_rolling_radius_m,
               r::rolling_radius_m);
    require_in(at("flange_clearance_m"), contact.flange_clearance_m, r::flange_clearance_m);
    require_in(at("normal_damping_N_s_per_m"), contact.normal_damping_N_s_per_m,
               r::damping_N_s_per_m);
    require_in(at("rail_head_transverse_radius_m"), contact.rail_head_transverse_radius_m,
               r::rail_head_radius_m);
    require_in(at("wheel_young_modulus_Pa"), contact.wheel_young_modulus_Pa, r::young_modulus_Pa);
    require_in(at("rail_young_modulus_Pa"), contact.rail_young_modulus_Pa, r::young_modulus_Pa);
    check_poisson_ratio(at("wheel_poisson_ratio"), contact.wheel_poisson_ratio);
    check_poisson_ratio(at("rail_poisson_ratio"), contact.rail_poisson_ratio);
    if (contact.normal == NormalForceKind::prescribed)
      require_in(at("prescribed_wheel_load_N"), contact.prescribed_wheel_load_N, r::wheel_load_N);
    if (contact.normal == NormalForceKind::prescribed && contact.normal_damping_N_s_per_m != 0.0)
      fail(at("normal_damping_N_s_per_m"), "0 with normal = 'prescribed' (the damper acts on "
           "the Hertz penetration rate; a prescribed load has none)",
           format_number(contact.normal_damping_N_s_per_m));
    if (contact.tangential == TangentialForceKind::constant) {
      require_in(at("f11_N"), contact.f11_N, r::creep_coefficient_N);
      require_in(at("f22_N"), contact.f22_N, r::creep_coefficient_N);
      require_in(at("f33_N_m2"), contact.f33_N_m2, r::creep_coefficient_N_m2);
      require_in(at("f23_N_m"), contact.f23_N_m, r::creep_coefficient_N_m);
    }
  }

  // e0 (the contact's half distance between the wheel contact points) and D
  // (the track's distance between the rail contact points, which sets the
  // cant angle asin(cant / D)) describe the same points: they must agree.
  // 5 % admits rounding (1435 mm gauge: 2 e0 = 1.5 m, D = 1.5 m or 1.505 m).
  void check_contact_distances(std::string_view path, double e0) const {
    const double D = scene_.track.rail_contact_distance_m;
    if (!(std::abs(2.0 * e0 - D) <= 0.05 * D))
      fail(path,
           "half of track.rail_contact_distance_m = " + format_number(D) +
               " m within 5 % (both are the distance between the contact points; the cant "
               "angle uses D, the contact geometry 2 e0)",
           format_number(e0) + " m (2 e0 = " + format_number(2.0 * e0) + " m)");
  }

  void check_poisson_ratio(std::string_view path, double ratio) const {
    if (!(ratio >= 0 && ratio < 0.5))
      fail(path, "a Poisson ratio in [0, 0.5)", format_number(ratio));
  }

  void check_body_names() const {
    for (size_t i = 0; i < scene_.bodies.size(); ++i) {
      const std::string path = child_path(body_path(i), "name");
      const std::string& name = scene_.bodies[i].name;
      if (name.empty()) fail(path, "a non-empty name", "''");
      check_name(path, name);
      if (name == kTrackBodyName)
        fail(path, "a name other than 'track' (reserved: elements use it for the track frame)",
             quoted(name));
      for (size_t j = 0; j < i; ++j)
        if (scene_.bodies[j].name == name)
          fail(path, "a unique body name", quoted(name) + ", already the name of " + body_path(j));
    }
    if (scene_.bodies.empty()) fail("bodies", "at least one body [[bodies]]", "none");
  }

  void check_body(size_t index) const {
    const BodySpec& body = scene_.bodies[index];
    const std::string path = body_path(index);
    namespace r = physical_ranges;
    require_in(child_path(path, "mass_kg"), body.mass_kg, r::mass_kg);
    require_each_in(child_path(path, "inertia_kg_m2"), body.inertia_kg_m2, r::inertia_kg_m2);
    check_inertia(child_path(path, "inertia_kg_m2"), body);
    require_each_in(child_path(path, "position_m"), body.position_m, r::coordinate_m);
    require_in(child_path(path, "track_offset_m"), body.track_offset_m, r::track_offset_m);
    for (int c = 0; c < kCoordinatesPerBody; ++c) {
      const bool angle = c >= 3;
      require_in(child_path(child_path(path, "initial_offset"), kOffsetKeys[c].key),
                 body.initial_offset[c], angle ? r::offset_rad : r::offset_m);
      require_in(child_path(child_path(path, "initial_rate"), kRateKeys[c].key),
                 body.initial_rate[c], angle ? r::rate_rad_per_s : r::rate_m_per_s);
    }
    for (size_t p = 0; p < body.measure_points.size(); ++p) {
      const std::string point = indexed_path(child_path(path, "measure_points"), p);
      check_name(child_path(point, "name"), body.measure_points[p].name);
      require_each_in(child_path(point, "position_m"), body.measure_points[p].position_m,
                      r::measure_point_m);
    }
    if (body.is_wheelset) {
      check_wheelset_contact(child_path(path, "contact"), body);
      check_wheelset_position(child_path(path, "position_m"), body);
    }
    else if (!body.contact.empty())
      fail(child_path(path, "contact"),
           "no contact on a rigid_body (only wheelsets touch the rails)", quoted(body.contact));
  }

  void check_inertia(std::string_view path, const BodySpec& body) const {
    const Eigen::Vector3d& J = body.inertia_kg_m2;
    if (!(J.array() > 0).all())
      fail(path, "positive principal moments Jx, Jy, Jz (kg m2)", format_vector(J));
    if (body.is_wheelset && std::abs(J.x() - J.z()) > 1e-9 * std::max(J.x(), J.z()))
      fail(path, "Jx = Jz (a wheelset must be axisymmetric; the model drops its spin angle)",
           "Jx = " + format_number(J.x()) + ", Jz = " + format_number(J.z()));
    const char* names[3] = {"Jx", "Jy", "Jz"};
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      if (J(i) + J(j) < J(k) * (1.0 - 1e-12))
        fail(path, "principal moments with Ji + Jj >= Jk for every pair",
             format_vector(J) + ", which is not a physical (positive-definite) inertia (" +
                 names[i] + " + " + names[j] + " = " + format_number(J(i) + J(j)) + " < " +
                 names[k] + " = " + format_number(J(k)) + ")");
    }
  }

  // A wheelset's nominal position is on the rails: its centre within the
  // flange clearance of the track centre and at its rolling radius above
  // the rail plane (10 %). A wheelset placed at y = -1 m failed deep in the
  // model ("relative curvatures must be positive") or found no equilibrium.
  void check_wheelset_position(const std::string& path, const BodySpec& wheelset) const {
    const ContactSpec* contact = find_contact(wheelset.contact);
    if (!contact) return;
    const double y = wheelset.position_m.y(), z = wheelset.position_m.z();
    const double clearance = contact->flange_clearance_m, r0 = contact->nominal_rolling_radius_m;
    if (!(std::abs(y) <= clearance))
      fail(indexed_path(path, 1),
           "a wheelset's nominal lateral position within the flange clearance of the track "
           "centre, [-" + format_number(clearance) + ", " + format_number(clearance) +
               "] m (contacts." + contact->name + ".flange_clearance_m)",
           format_number(y));
    if (!(std::abs(z - r0) <= 0.1 * r0))
      fail(indexed_path(path, 2),
           "a wheelset's axle height at its rolling radius above the rail plane, " +
               format_number(r0) + " m within 10 % (contacts." + contact->name +
               ".nominal_rolling_radius_m)",
           format_number(z));
  }

  void check_wheelset_contact(std::string_view path, const BodySpec& wheelset) const {
    if (wheelset.contact.empty())
      fail(path, "the name of a [contacts.<name>] table for a wheelset", "nothing");
    if (!find_contact(wheelset.contact)) {
      std::vector<std::string> names;
      for (const ContactSpec& contact : scene_.contacts) names.push_back(contact.name);
      throw scene_error(source_, path,
                        "unknown contact " + quoted(wheelset.contact) +
                            " (contacts: " + comma_separated(names) + ")");
    }
  }

  void check_element(size_t index) const {
    const ElementEnds& element = ends_of(scene_.elements[index]);
    const std::string path =
        index < element_paths_.size() ? element_paths_[index] : indexed_path("elements", index);
    if (element.name.empty()) fail(child_path(path, "name"), "a non-empty name", "''");
    // (+ 6: a mirrored element's "_right"; the file's name was checked by the reader.)
    if (const std::optional<std::string> problem =
            name_problem(element.name, physical_ranges::kMaxNameBytes + 6))
      fail(child_path(path, "name"), name_expectation(), *problem);
    if (element.body1_name != kTrackBodyName && !has_body(element.body1_name))
      throw unknown_body(child_path(path, "body1"), element.body1_name, "; or 'track'");
    if (element.body2_name == kTrackBodyName)
      fail(child_path(path, "body2"), "a body (only body1 may be 'track')",
           quoted(element.body2_name));
    if (!has_body(element.body2_name))
      throw unknown_body(child_path(path, "body2"), element.body2_name, "");
    if (element.body1_name == element.body2_name)
      fail(child_path(path, "body2"), "a body other than body1",
           quoted(element.body2_name) + " for both");
  }

  SceneError unknown_body(std::string_view path, const std::string& name,
                          std::string_view alternatives) const {
    std::vector<std::string> names;
    for (const BodySpec& body : scene_.bodies) names.push_back(body.name);
    return scene_error(source_, path,
                       "unknown body " + quoted(name) + " (bodies: " + comma_separated(names) +
                           std::string(alternatives) + ")");
  }

  // Creepages are divided by the speed: creep forces need V > 0.
  void check_speed_for_creep_forces() const {
    const char* path = "scene.speed_m_per_s";
    for (const BodySpec& body : scene_.bodies) {
      const ContactSpec* contact = body.is_wheelset ? find_contact(body.contact) : nullptr;
      if (contact && contact->tangential != TangentialForceKind::none &&
          !(scene_.speed_m_per_s >= physical_ranges::kMinimumCreepSpeed_m_per_s))
        fail(path,
             "at least kMinimumCreepSpeed_m_per_s = " +
                 format_number(physical_ranges::kMinimumCreepSpeed_m_per_s) +
                 " m/s when creep forces are on (creepages are divided by the speed; below it "
                 "the steady-state creep laws do not hold, docs/scene_format.md)",
             format_number(scene_.speed_m_per_s));
    }
    require_in(path, scene_.speed_m_per_s, physical_ranges::speed_m_per_s);
  }

  // Each body's own track frame starts at reference + offset: it must be on the track.
  void check_bodies_on_track() const {
    double track_length_m = 0.0;
    for (const TrackSegmentSpec& segment : scene_.track.segments)
      track_length_m += segment.length_m;
    for (size_t i = 0; i < scene_.bodies.size(); ++i) {
      const double offset = scene_.bodies[i].track_offset_m;
      const double arc_length = scene_.reference_arc_length_m + offset;
      if (!(arc_length >= 0 && arc_length <= track_length_m))
        fail(child_path(body_path(i), "track_offset_m"),
             "the body's track position at t = 0 (reference_arc_length_m + track_offset_m) "
             "inside the track [0, " +
                 format_number(track_length_m) + "] m",
             format_number(scene_.reference_arc_length_m) + (offset < 0 ? " - " : " + ") +
                 format_number(std::abs(offset)) + " = " + format_number(arc_length) + " m");
    }
  }

  const ContactSpec* find_contact(const std::string& name) const {
    for (const ContactSpec& contact : scene_.contacts)
      if (contact.name == name) return &contact;
    return nullptr;
  }

  bool has_body(const std::string& name) const {
    return std::any_of(scene_.bodies.begin(), scene_.bodies.end(),
                       [&](const BodySpec& body) { return body.name == name; });
  }

  const SceneSpec& scene_;
  std::string source_;
  std::vector<std::string> element_paths_;
};

}  // namespace

void check_scene_as_read(const SceneSpec& scene, std::vector<std::string> element_paths) {
  SceneChecker(scene, std::move(element_paths)).check_all();
}

}  // namespace scene_reading

void validate_scene(const SceneSpec& scene) {
  using namespace scene_reading;
  std::vector<std::string> element_paths;
  for (size_t i = 0; i < scene.elements.size(); ++i)
    element_paths.push_back(ends_of(scene.elements[i]).name.empty()
                                ? indexed_path("elements", i)
                                : "elements[" + quoted(ends_of(scene.elements[i]).name) + "]");
  SceneChecker(scene, std::move(element_paths)).check_all();
}

void validate_replaced_values(const SceneSpec& scene, const ReplacedSceneValues& replaced) {
  scene_reading::SceneChecker(scene, {}).check_replaced(replaced);
}

}  // namespace railstab
