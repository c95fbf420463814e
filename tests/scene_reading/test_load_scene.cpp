// Scene files (scene_reading/load_scene.hpp): a minimal valid scene parses to
// the expected values, each class of mistake gives a SceneError naming the
// file, the key path and what was expected, every shipped case file loads,
// the scene carries the SHA-256 of the bytes read, and profile contacts are
// only recorded (their tables are the set-up step's).
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include <railstab/io/sha256.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/scene_reading/scene_checker.hpp>
#include <railstab/setup/build_model.hpp>

using namespace railstab;

namespace {

const std::string kSource = "cases/minimal.toml";

// Two wheelsets and a bogie frame on a tangent-clothoid-arc track; mirrored
// primary springs, one unmirrored spring from the track.
const std::string kMinimalScene = R"toml(
[scene]
name = "minimal"
speed_m_per_s = 20.0
reference_arc_length_m = 600.0

[track]
start_heading_rad = 0.25
[[track.segments]]
type = "tangent"
length_m = 1000.0
[[track.segments]]
type = "clothoid"
length_m = 200.0
end_radius_m = 1000.0
turn = "left"
end_cant_m = 0.05
[[track.segments]]
type = "arc"
length_m = 3000.0

[contacts.cone]
geometry = "knife_edge_cone"
normal = "hertz"
tangential = "kalker_hertz"
cone_angle_rad = 0.12

[[bodies]]
name = "wheelset1"
type = "wheelset"
mass_kg = 1500
inertia_kg_m2 = [799.35, 93.75, 799.35]
position_m = [0.0, 0.0, 0.45]
contact = "cone"
initial_offset = { y_m = 0.001, yaw_rad = 0.002 }
initial_rate = { roll_rad_per_s = 0.3 }

[[bodies]]
name = "wheelset2"
type = "wheelset"
mass_kg = 1500.0
inertia_kg_m2 = [799.35, 93.75, 799.35]
track_offset_m = -3.0
position_m = [0.0, 0.0, 0.45]
contact = "cone"

[[bodies]]
name = "bogie1"
type = "rigid_body"
mass_kg = 3020.0
inertia_kg_m2 = [2130.912, 4063.712, 4063.712]
track_offset_m = -1.5
position_m = [0.0, 0.0, 1.0575]
free = ["yaw", "y"]

[[elements]]
name = "primary_ws1"
type = "spring_damper_3d"
body1 = "wheelset1"
body2 = "bogie1"
point1_m = [0.0, 1.0, 0.0]
point2_m = [1.5, 1.0, -0.6075]
stiffness_N_per_m = [3.9e7, 7.85e6, 9.75e5]
damping_N_s_per_m = [0.0, 0.0, 1.08e4]
mirror_lateral = true

[[elements]]
name = "anchor"
type = "spring_damper_3d"
body1 = "track"
body2 = "bogie1"
point1_m = [0.0, 0.0, 0.5]
point2_m = [0.0, 0.0, 0.0]
stiffness_N_per_m = [1.0, 2.0, 3.0]
damping_N_s_per_m = [0.0, 0.0, 0.0]
actuator_force_N = [0.0, 5.0, 0.0]

[[elements]]
name = "yaw_damper"
type = "rotational_spring_damper"
body1 = "wheelset2"
body2 = "bogie1"
stiffness_N_m_per_rad = [0.0, 0.0, 1.0e5]
damping_N_m_s_per_rad = [0.0, 0.0, 2.0e4]

[simulation]
t_end_s = 5.0
)toml";

// `text` with the first occurrence of `original` (which must occur) replaced.
std::string replaced(std::string text, const std::string& original,
                     const std::string& replacement) {
  const size_t at = text.find(original);
  if (at == std::string::npos) throw std::logic_error("test text not found: " + original);
  return text.replace(at, original.size(), replacement);
}

std::string minimal_with(const std::string& original, const std::string& replacement) {
  return replaced(kMinimalScene, original, replacement);
}

// Parses `text`, expecting a SceneError whose message contains every fragment.
void expect_scene_error(const std::string& text, const std::vector<std::string>& fragments) {
  try {
    load_scene_text(text, kSource);
    ADD_FAILURE() << "expected a SceneError, the scene parsed";
  } catch (const SceneError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind(kSource + ": ", 0), 0u) << message;
    for (const std::string& fragment : fragments)
      EXPECT_NE(message.find(fragment), std::string::npos)
          << "message lacks \"" << fragment << "\": " << message;
  }
}

const ElementSpec& element_named(const SceneSpec& scene, const std::string& name) {
  for (const ElementSpec& element : scene.elements)
    if (ends_of(element).name == name) return element;
  throw std::logic_error("no element " + name);
}
template <class Element>
const Element& element_named(const SceneSpec& scene, const std::string& name) {
  const Element* e = std::get_if<Element>(&element_named(scene, name));
  if (!e) throw std::logic_error(name + " is not a " + Element::kType);
  return *e;
}

}  // namespace

// --- A valid scene -------------------------------------------------------------

TEST(SceneLoader, MinimalSceneParsesToExpectedValues) {
  const SceneSpec scene = load_scene_text(kMinimalScene, kSource);
  EXPECT_EQ(scene.name, "minimal");
  EXPECT_EQ(scene.source_path, kSource);
  EXPECT_DOUBLE_EQ(scene.speed_m_per_s, 20.0);
  EXPECT_DOUBLE_EQ(scene.gravity_m_per_s2, 9.81);  // default
  EXPECT_DOUBLE_EQ(scene.reference_arc_length_m, 600.0);
  EXPECT_EQ(scene.preload, PreloadMode::balance_gravity_at_nominal);  // default

  EXPECT_DOUBLE_EQ(scene.track.start_heading_rad, 0.25);
  EXPECT_DOUBLE_EQ(scene.track.rail_contact_distance_m, 1.5);  // default
  ASSERT_EQ(scene.track.segments.size(), 3u);
  EXPECT_EQ(scene.track.segments[1].kind, TrackSegmentKind::clothoid);
  EXPECT_DOUBLE_EQ(scene.track.segments[1].end_curvature_per_m, 1.0 / 1000.0);  // left: > 0
  EXPECT_DOUBLE_EQ(scene.track.segments[0].end_cant_m, 0.0);
  EXPECT_DOUBLE_EQ(scene.track.segments[1].end_cant_m, 0.05);
  EXPECT_EQ(scene.track.segments[2].kind, TrackSegmentKind::arc);
  EXPECT_DOUBLE_EQ(scene.track.segments[2].end_cant_m, 0.05);  // keeps its start cant
  EXPECT_DOUBLE_EQ(scene.track.segments[2].end_curvature_per_m, 1.0 / 1000.0);

  ASSERT_EQ(scene.contacts.size(), 1u);
  const ContactSpec& contact = scene.contacts[0];
  EXPECT_EQ(contact.name, "cone");
  EXPECT_EQ(contact.geometry, ContactGeometryKind::knife_edge_cone);
  EXPECT_DOUBLE_EQ(contact.cone_angle_rad, 0.12);
  EXPECT_DOUBLE_EQ(contact.rail_head_transverse_radius_m, 0.30);  // default (ERRATA 8)
  EXPECT_TRUE(contact.spin_creepage);

  ASSERT_EQ(scene.bodies.size(), 3u);
  const BodySpec& wheelset1 = scene.bodies[0];
  EXPECT_TRUE(wheelset1.is_wheelset);
  EXPECT_DOUBLE_EQ(wheelset1.mass_kg, 1500.0);  // an integer is accepted for a float
  EXPECT_DOUBLE_EQ(wheelset1.inertia_kg_m2.y(), 93.75);
  EXPECT_DOUBLE_EQ(wheelset1.track_offset_m, 0.0);  // default
  EXPECT_EQ(wheelset1.contact, "cone");
  EXPECT_EQ(wheelset1.free, (std::array<bool, 6>{true, true, true, true, true, true}));
  EXPECT_EQ(wheelset1.initial_offset, (std::array<double, 6>{0, 0.001, 0, 0, 0, 0.002}));
  EXPECT_EQ(wheelset1.initial_rate, (std::array<double, 6>{0, 0, 0, 0.3, 0, 0}));
  const BodySpec& bogie = scene.bodies[2];
  EXPECT_FALSE(bogie.is_wheelset);
  EXPECT_DOUBLE_EQ(bogie.track_offset_m, -1.5);
  EXPECT_DOUBLE_EQ(bogie.position_m.z(), 1.0575);
  EXPECT_EQ(bogie.free, (std::array<bool, 6>{false, true, false, false, false, true}));

  ASSERT_EQ(scene.elements.size(), 4u);  // mirrored pair + anchor + yaw damper
  using Spring = SpringDamper3d<double>;
  const Spring& left = element_named<Spring>(scene, "primary_ws1_left");
  const Spring& right = element_named<Spring>(scene, "primary_ws1_right");
  EXPECT_EQ(left.ends.point1_m, Eigen::Vector3d(0.0, 1.0, 0.0));
  EXPECT_EQ(left.ends.point2_m, Eigen::Vector3d(1.5, 1.0, -0.6075));
  EXPECT_EQ(right.ends.point1_m, Eigen::Vector3d(0.0, -1.0, 0.0));
  EXPECT_EQ(right.ends.point2_m, Eigen::Vector3d(1.5, -1.0, -0.6075));
  EXPECT_EQ(right.stiffness_N_per_m, Eigen::Vector3d(3.9e7, 7.85e6, 9.75e5));
  EXPECT_EQ(right.damping_N_s_per_m, Eigen::Vector3d(0.0, 0.0, 1.08e4));
  EXPECT_EQ(right.ends.body1_name, "wheelset1");
  EXPECT_EQ(right.ends.body2_name, "bogie1");
  const Spring& anchor = element_named<Spring>(scene, "anchor");
  EXPECT_EQ(anchor.ends.body1_name, kTrackBodyName);
  EXPECT_EQ(anchor.actuator_force_N, Eigen::Vector3d(0.0, 5.0, 0.0));
  using Bushing = RotationalSpringDamper<double>;
  const Bushing& yaw_damper = element_named<Bushing>(scene, "yaw_damper");
  EXPECT_EQ(yaw_damper.ends.point1_m, Eigen::Vector3d::Zero());  // default for rotational
  EXPECT_EQ(yaw_damper.damping_N_m_s_per_rad, Eigen::Vector3d(0.0, 0.0, 2.0e4));

  EXPECT_DOUBLE_EQ(scene.simulation.t_end_s, 5.0);
  EXPECT_DOUBLE_EQ(scene.simulation.output_interval_s, 0.01);  // default
}

TEST(SceneLoader, ClothoidTurningRightOrGivenByCurvature) {
  const SceneSpec right = load_scene_text(minimal_with("turn = \"left\"", "turn = \"right\""), kSource);
  EXPECT_DOUBLE_EQ(right.track.segments[1].end_curvature_per_m, -1.0 / 1000.0);
  const SceneSpec by_curvature = load_scene_text(
      minimal_with("end_radius_m = 1000.0\nturn = \"left\"", "end_curvature_per_m = 0.002"),
      kSource);
  EXPECT_DOUBLE_EQ(by_curvature.track.segments[1].end_curvature_per_m, 0.002);
}

TEST(SceneLoader, OptionalContactKeysForOtherModelsAreAccepted) {
  const SceneSpec scene = load_scene_text(
      minimal_with("cone_angle_rad = 0.12", "cone_angle_rad = 0.12\nconicity = 0.2\nf11_N = 1.0"),
      kSource);
  EXPECT_DOUBLE_EQ(scene.contacts[0].conicity, 0.2);
}

// --- Mistakes ----------------------------------------------------------------------

namespace {

// One mistake in the minimal scene: the first `original` replaced by
// `replacement`; the SceneError's message holds every fragment.
struct SceneMistake {
  const char* name;  // the test's name
  std::string original, replacement;
  std::vector<std::string> fragments;
  friend void PrintTo(const SceneMistake& m, std::ostream* os) { *os << m.name; }
};

const std::vector<SceneMistake> kSceneMistakes = {
    // Structure and types.
    {"MissingRequiredKey", "speed_m_per_s = 20.0\n", "",
     {"scene.speed_m_per_s", "expected a number (m/s)", "key is missing"}},
    {"WrongTypeStringForNumber", "mass_kg = 3020.0", "mass_kg = \"heavy\"",
     {"bodies[2].mass_kg", "expected a number (kg)", "got a string 'heavy'"}},
    {"WrongTypeArrayOfWrongLength", "inertia_kg_m2 = [2130.912, 4063.712, 4063.712]", "inertia_kg_m2 = [2130.912, 4063.712]",
     {"bodies[2].inertia_kg_m2", "expected an array of 3 numbers (kg m2)", "got an array of 2 elements"}},
    {"WrongTypeInsideArray", "point2_m = [1.5, 1.0, -0.6075]", "point2_m = [1.5, true, -0.6075]",
     {"elements[0].point2_m[1]", "expected a number (m)", "got true"}},
    {"NonFiniteLength", "length_m = 3000.0", "length_m = inf",
     {"track.segments[2].length_m", "expected a finite number (m)", "got inf"}},
    {"NonFiniteMass", "mass_kg = 3020.0", "mass_kg = nan",
     {"bodies[2].mass_kg", "expected a finite number (kg)"}},
    {"WrongUnitKeySuggestsTheKnownKey", "mass_kg = 3020.0", "mass_g = 3020000.0",
     {"bodies[2].mass_g", "unknown key", "did you mean 'mass_kg'?"}},
    {"MisspeltKeySuggestsTheKnownKey", "stiffness_N_per_m = [1.0", "stifness_N_per_m = [1.0",
     {"elements[1].stifness_N_per_m", "unknown key", "did you mean 'stiffness_N_per_m'?"}},
    {"MisspeltSectionSuggestsTheKnownSection", "[simulation]", "[simulaton]",
     {": simulaton: unknown key", "did you mean 'simulation'?"}},
    {"KeyOfAnotherElementTypeIsRejected", "actuator_force_N = [0.0, 5.0, 0.0]", "actuator_moment_N_m = [0.0, 5.0, 0.0]",
     {"elements[1].actuator_moment_N_m", "expected no actuator_moment_N_m on a spring_damper_3d"}},
    {"BadEnumString", "type = \"clothoid\"", "type = \"clothiod\"",
     {"track.segments[1].type", "expected one of 'tangent', 'clothoid', 'arc'", "got 'clothiod'", "did you mean 'clothoid'?"}},
    {"TomlSyntaxErrorReportsLineAndColumn",  // line 5 of kMinimalScene (it starts with a newline)
     "reference_arc_length_m = 600.0", "reference_arc_length_m = = 600.0",
     {"line 5, column", "expected valid TOML"}},
    {"UnknownFreeCoordinate", "free = [\"yaw\", \"y\"]", "free = [\"yaw\", \"lateral\"]",
     {"bodies[2].free[1]", "expected one of 'x', 'y', 'z', 'roll', 'pitch', 'yaw'", "got 'lateral'"}},
    {"DuplicateFreeCoordinate", "free = [\"yaw\", \"y\"]", "free = [\"yaw\", \"y\", \"yaw\"]",
     {"bodies[2].free[2]", "expected each coordinate at most once", "'yaw' a second time"}},
    {"ClothoidWithBothEndCurvatures", "end_radius_m = 1000.0", "end_radius_m = 1000.0\nend_curvature_per_m = 0.001",
     {"track.segments[1]:", "expected exactly one of end_radius_m", "got both"}},
    {"ClothoidWithNeitherEndCurvature", "end_radius_m = 1000.0\nturn = \"left\"", "",
     {"track.segments[1]:", "expected exactly one of end_radius_m", "got neither"}},
    {"TangentWhereTheTrackIsCurvedIsRejected", "type = \"arc\"", "type = \"tangent\"",
     {"track.segments[2].type", "a tangent needs start curvature 0", "where the curvature is 0.001 1/m"}},
    {"NegativeContactDamping", "cone_angle_rad = 0.12", "cone_angle_rad = 0.12\nnormal_damping_N_s_per_m = -1.0",
     {"contacts.cone.normal_damping_N_s_per_m", "expected a damping in [0, 1e+08] N s/m", "got -1"}},
    {"ContactDampingWithPrescribedNormalForce", "normal = \"hertz\"", "normal = \"prescribed\"\nprescribed_wheel_load_N = 5.0e4\n"
        "normal_damping_N_s_per_m = 1.0e4",
     {"contacts.cone.normal_damping_N_s_per_m", "0 with normal = 'prescribed'", "got 10000"}},
    {"PrescribedNormalForceNeedsTheWheelLoad", "normal = \"hertz\"", "normal = \"prescribed\"",
     {"contacts.cone.prescribed_wheel_load_N", "expected a number (N)", "required when normal = 'prescribed'"}},
    {"ConstantTangentialForceNeedsItsCoefficients", "tangential = \"kalker_hertz\"", "tangential = \"constant\"",
     {"contacts.cone.f11_N", "required when tangential = 'constant'"}},
    {"LinearConicityNeedsTheConicity", "geometry = \"knife_edge_cone\"", "geometry = \"linear_conicity\"",
     {"contacts.cone.conicity", "required when geometry = 'linear_conicity'"}},
    {"RigidBodyMustNotHaveContact", "free = [\"yaw\", \"y\"]", "free = [\"yaw\", \"y\"]\ncontact = \"cone\"",
     {"bodies[2].contact", "expected no contact on a rigid_body", "got a string 'cone'"}},
    // Semantic checks.
    {"NegativeMass", "mass_kg = 3020.0", "mass_kg = -3",
     {"bodies[2].mass_kg", "expected a mass in [0.1, 1e+06] kg", "got -3"}},
    {"NonPositiveDefiniteInertia", "inertia_kg_m2 = [2130.912, 4063.712, 4063.712]", "inertia_kg_m2 = [1.0, 1.0, 5.0]",
     {"bodies[2].inertia_kg_m2", "expected principal moments with Ji + Jj >= Jk", "not a physical (positive-definite) inertia"}},
    {"ZeroPrincipalMomentOfInertia", "inertia_kg_m2 = [2130.912, 4063.712, 4063.712]", "inertia_kg_m2 = [1.0, 0.0, 1.0]",
     {"bodies[2].inertia_kg_m2[1]", "expected a principal moment of inertia in [1e-04, 1e+08] kg m2", "got 0"}},
    {"NonAxisymmetricWheelset", "inertia_kg_m2 = [799.35, 93.75, 799.35]\ntrack_offset_m = -3.0", "inertia_kg_m2 = [799.35, 93.75, 850.0]\ntrack_offset_m = -3.0",
     {"bodies[1].inertia_kg_m2", "expected Jx = Jz", "the model drops its spin angle", "got Jx = 799.35, Jz = 850"}},
    {"UnknownBodyInElement", "body1 = \"wheelset2\"", "body1 = \"wheelset3\"",
     {"elements[2].body1", "unknown body 'wheelset3'", "(bodies: wheelset1, wheelset2, bogie1; or 'track')"}},
    {"ElementBodiesMustDiffer", "body1 = \"wheelset1\"", "body1 = \"bogie1\"",
     {"elements[0].body2", "expected a body other than body1"}},
    {"OnlyBody1MayBeTheTrack", "body2 = \"bogie1\"\npoint1_m = [0.0, 0.0, 0.5]", "body2 = \"track\"\npoint1_m = [0.0, 0.0, 0.5]",
     {"elements[1].body2", "only body1 may be 'track'"}},
    {"NegativeStiffness", "stiffness_N_per_m = [1.0, 2.0, 3.0]", "stiffness_N_per_m = [1.0, -2.0, 3.0]",
     {"elements[1].stiffness_N_per_m[1]", "expected a stiffness in [0, 1e+11] N/m", "got -2"}},
    {"ZeroSpeedWithCreepForces", "speed_m_per_s = 20.0", "speed_m_per_s = 0.0",
     {"scene.speed_m_per_s", "expected at least kMinimumCreepSpeed_m_per_s = 0.1 m/s when creep forces are on", "creepages are divided by the speed", "got 0"}},
    {"UnknownContact", "contact = \"cone\"\ninitial_offset", "contact = \"cylinder\"\ninitial_offset",
     {"bodies[0].contact", "unknown contact 'cylinder' (contacts: cone)"}},
    {"ReservedBodyName", "name = \"bogie1\"", "name = \"track\"",
     {"bodies[2].name", "expected a name other than 'track'"}},
    {"DuplicateBodyName", "name = \"wheelset2\"", "name = \"wheelset1\"",
     {"bodies[1].name", "expected a unique body name", "already the name of bodies[0]"}},
    {"ConeAngleOutOfRange", "cone_angle_rad = 0.12", "cone_angle_rad = 0.6",
     {"contacts.cone.cone_angle_rad", "expected a knife-edge cone angle in [0.01, 0.4] rad", "got 0.6"}},
    {"PoissonRatioOutOfRange", "cone_angle_rad = 0.12", "cone_angle_rad = 0.12\nwheel_poisson_ratio = 0.5",
     {"contacts.cone.wheel_poisson_ratio", "expected a Poisson ratio in [0, 0.5)"}},
    {"CantMustBeLessThanRailDistance", "end_cant_m = 0.05", "end_cant_m = 1.6",
     {"track.segments[1].end_cant_m", "expected |cant| < rail_contact_distance_m = 1.5 m", "got 1.6"}},
    {"BodiesMustStartOnTheTrack", "reference_arc_length_m = 600.0", "reference_arc_length_m = 2.0",
     {"bodies[1].track_offset_m", "inside the track [0, 4200] m", "got 2 - 3 = -1 m"}},
    {"SimulationTimesMustBePositive", "t_end_s = 5.0", "t_end_s = 0.0",
     {"simulation.t_end_s", "expected an end time in (0, 1e+05] s", "got 0"}},
    {"MisspeltIntegrator", "t_end_s = 5.0", "t_end_s = 5.0\nintegrator = \"cvode_bfd\"",
     {"simulation.integrator", "one of", "'cvode_bdf'", "got 'cvode_bfd'"}},
    {"FractionalIntegratorOrder", "t_end_s = 5.0", "t_end_s = 5.0\nintegrator_order = 2.5",
     {"simulation.integrator_order", "an order arkode_dirk offers: 2, 3, 4, 5", "got 2.5"}},
    {"IntegratorOrderTheMethodLacks", "t_end_s = 5.0", "t_end_s = 5.0\nintegrator = \"cvode_bdf\"\nintegrator_order = 7",
     {"simulation.integrator_order", "an order cvode_bdf offers: 1, 2, 3, 4, 5", "got 7"}},
    {"FrictionCoefficientWithLinearKalker", "tangential = \"kalker_hertz\"", "tangential = \"kalker_hertz\"\nfriction_coefficient = 0.3",
     {"contacts.", ".friction_coefficient", "no friction_coefficient with creep_law = \"linear_kalker\""}},
    {"FrictionCoefficientOutOfRange", "tangential = \"kalker_hertz\"", "tangential = \"kalker_hertz\"\ncreep_law = \"polach\"\n"
        "friction_coefficient = 5.0",
     {".friction_coefficient", "expected a number in (0, 2]", "got 5"}},
    {"UnknownCreepLaw", "tangential = \"kalker_hertz\"", "tangential = \"kalker_hertz\"\ncreep_law = \"coulomb\"",
     {".creep_law", "'linear_kalker', 'shen_hedrick_elkins', 'polach'"}},
};

class SceneLoaderMistake : public ::testing::TestWithParam<SceneMistake> {};

}  // namespace

TEST_P(SceneLoaderMistake, NamesTheFileTheKeyAndWhatWasExpected) {
  expect_scene_error(minimal_with(GetParam().original, GetParam().replacement), GetParam().fragments);
}

INSTANTIATE_TEST_SUITE_P(SceneLoader, SceneLoaderMistake, ::testing::ValuesIn(kSceneMistakes),
                         [](const ::testing::TestParamInfo<SceneMistake>& info) {
                           return std::string(info.param.name);
                         });

// --- Accepted values, checks after overrides ------------------------------------------

TEST(SceneLoader, ZeroSpeedWithoutCreepForcesIsAllowed) {
  const std::string at_rest =
      replaced(minimal_with("tangential = \"kalker_hertz\"", "tangential = \"none\""),
               "speed_m_per_s = 20.0", "speed_m_per_s = 0.0");
  EXPECT_DOUBLE_EQ(load_scene_text(at_rest, kSource).speed_m_per_s, 0.0);
}

TEST(SceneLoader, ValidateSceneCatchesCommandLineOverride) {
  SceneSpec scene = load_scene_text(kMinimalScene, kSource);
  scene.speed_m_per_s = -5.0;
  try {
    validate_scene(scene);
    ADD_FAILURE() << "expected a SceneError";
  } catch (const SceneError& error) {
    EXPECT_NE(
        std::string(error.what()).find("cases/minimal.toml: scene.speed_m_per_s: expected at least kMinimumCreepSpeed_m_per_s = 0.1 m/s"),
        std::string::npos)
        << error.what();
  }
}

TEST(SceneLoader, IntegratorChoiceAndOrder) {
  const SceneSpec scene = load_scene_text(
      minimal_with("t_end_s = 5.0", "t_end_s = 5.0\nintegrator = \"cvode_bdf\"\nintegrator_order = 2"),
      kSource);
  EXPECT_EQ(scene.simulation.integrator, IntegratorKind::cvode_bdf);
  EXPECT_EQ(scene.simulation.integrator_order, 2);
  EXPECT_EQ(load_scene_text(kMinimalScene, kSource).simulation.integrator,
            IntegratorKind::arkode_dirk);  // the default
}

TEST(SceneLoader, MissingFileIsReported) {
  EXPECT_THROW(load_scene_file("/nonexistent/scene.toml"), SceneError);
}

// --- Shipped case files ---------------------------------------------------------------

TEST(SceneLoader, EveryCaseFileLoadsWithTheExpectedBodyCount) {
  const std::map<std::string, size_t> expected_body_counts = {
      {"thesis_bogie_tangent.toml", 3},   {"thesis_bogie_curve.toml", 3},
      {"thesis_vehicle_tangent.toml", 7}, {"thesis_vehicle_curve.toml", 7},
      {"textbook_wheelset.toml", 1},      {"textbook_bogie.toml", 3},
      {"extreme_stiff_contact.toml", 3},  {"extreme_low_speed.toml", 3},
      {"extreme_high_speed.toml", 3},     {"extreme_tight_curve.toml", 3},
      {"extreme_cant_deficiency.toml", 3}, {"extreme_cant_excess.toml", 3},
      {"extreme_zero_damping.toml", 3},   {"extreme_lift_off.toml", 3},
      {"extreme_near_critical.toml", 3},  {"extreme_conservative.toml", 3},
      {"coach_tangent.toml", 7},          {"coach_curve.toml", 7},
      {"coach_s1002_curve.toml", 7},
      {"thesis_vehicle_s1002_tangent.toml", 7}, {"thesis_bogie_s1002_tangent.toml", 3},
      {"thesis_vehicle_s1002_curve.toml", 7},   {"thesis_bogie_s1002_curve.toml", 3},
      {"thesis_train_4.toml", 28}};  // 4 cars of 7 bodies
  size_t files_seen = 0;
  for (const auto& entry : std::filesystem::directory_iterator(RAILSTAB_CASES_DIR)) {
    if (entry.path().extension() != ".toml") continue;
    // A contact-only file (no bodies), read by `railstab contact-geometry`.
    if (entry.path().filename() == "s1002_uic60_contact.toml") continue;
    ++files_seen;
    const std::string file = entry.path().filename().string();
    SCOPED_TRACE(file);
    SceneSpec scene;
    ASSERT_NO_THROW(scene = load_scene_file(entry.path().string()));
    const auto expected = expected_body_counts.find(file);
    ASSERT_NE(expected, expected_body_counts.end()) << "no expected body count for " << file;
    EXPECT_EQ(scene.bodies.size(), expected->second);
  }
  EXPECT_GE(files_seen, expected_body_counts.size());
}

// The hash is taken once, from the bytes read (reports use it, not the file
// as it is after the analysis); --set does not change it; text has none.
TEST(SceneLoader, SceneCarriesTheHashOfTheBytesRead) {
  const std::string path = std::string(RAILSTAB_CASES_DIR) + "/textbook_wheelset.toml";
  const std::string sha = sha256_of_file(path);
  const SceneSpec scene = load_scene_file(path);
  EXPECT_EQ(scene.source_sha256, sha);
  EXPECT_EQ(build_model(scene).source_sha256, sha);
  EXPECT_EQ(load_scene_file(path, {{"bodies.wheelset1.mass_kg", 1600.0}}).source_sha256, sha);
  EXPECT_TRUE(load_scene_text(read_scene_text(path), path).source_sha256.empty());
}

// The reader records a profile contact's files and grid; it reads no
// profile and builds no table (setup/contact_tables.hpp does).
TEST(SceneLoader, ProfileContactIsRecordedNotBuilt) {
  const SceneSpec scene =
      load_scene_file(std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_s1002_tangent.toml");
  ASSERT_FALSE(scene.contacts.empty());
  const ContactSpec& contact = scene.contacts[0];
  EXPECT_EQ(contact.geometry, ContactGeometryKind::profiles);
  EXPECT_NE(contact.profile_source.wheel_profile_path.find(".prw"), std::string::npos);
  EXPECT_FALSE(contact.profile_geometry);
}

// A scene on a contact table that names no integrator gets CVODE Adams at
// 1e-4/1e-8 (scene_spec.hpp, profile_contact_simulation_defaults); a key it
// gives is kept; a knife-edge scene keeps the SDIRK at 1e-3/1e-6.
TEST(SceneLoader, ProfileContactDefaultsToAdamsAtTighterTolerances) {
  const std::string path = std::string(RAILSTAB_CASES_DIR) + "/thesis_bogie_s1002_tangent.toml";
  std::string text = read_scene_text(path);
  for (const char* key : {"integrator = ", "relative_tolerance = ", "absolute_tolerance = "}) {
    const size_t at = text.find(std::string("\n") + key);
    ASSERT_NE(at, std::string::npos) << key;
    text.erase(at + 1, text.find('\n', at + 1) - at);
  }
  const SimulationSpec profile = load_scene_text(text, path).simulation;
  EXPECT_EQ(profile.integrator, IntegratorKind::cvode_adams);
  EXPECT_EQ(profile.relative_tolerance, 1e-4);
  EXPECT_EQ(profile.absolute_tolerance, 1e-8);
  std::string with_rtol = text;
  const std::string table_header = "[simulation]\n";
  const size_t table = with_rtol.find(table_header);
  ASSERT_NE(table, std::string::npos);
  with_rtol.insert(table + table_header.size(), "relative_tolerance = 1e-5\n");
  const SimulationSpec given = load_scene_text(with_rtol, path).simulation;
  EXPECT_EQ(given.integrator, IntegratorKind::cvode_adams);
  EXPECT_EQ(given.relative_tolerance, 1e-5);
  EXPECT_EQ(given.absolute_tolerance, 1e-8);
  const SimulationSpec named = load_scene_file(path).simulation;  // the case names its own
  EXPECT_EQ(named.integrator, IntegratorKind::arkode_dirk);
  EXPECT_EQ(named.relative_tolerance, 1e-3);
  const SimulationSpec knife_edge = load_scene_text(kMinimalScene, kSource).simulation;
  EXPECT_EQ(knife_edge.integrator, IntegratorKind::arkode_dirk);
  EXPECT_EQ(knife_edge.relative_tolerance, 1e-3);
  EXPECT_EQ(knife_edge.absolute_tolerance, 1e-6);
}

TEST(SceneLoader, ThesisVehicleCaseHasMirroredSuspension) {
  const SceneSpec scene =
      load_scene_file(std::string(RAILSTAB_CASES_DIR) + "/thesis_vehicle_curve.toml");
  EXPECT_EQ(scene.elements.size(), 12u);  // 8 primary + 4 secondary springs (Tables 5.3, 5.5)
  const ElementSpec& secondary = element_named(scene, "secondary_bogie2_right");
  EXPECT_EQ(ends_of(secondary).point2_m, Eigen::Vector3d(-9.675, -1.0, -0.73));
  EXPECT_FALSE(scene.bodies[6].free[int(CoordinateIndex::x)]);  // car body holds the speed
}

TEST(SceneLoader, CreepLawIsReadWithItsFrictionCoefficient) {
  const SceneSpec scene = load_scene_text(
      minimal_with("tangential = \"kalker_hertz\"",
                   "tangential = \"kalker_hertz\"\ncreep_law = \"shen_hedrick_elkins\"\n"
                   "friction_coefficient = 0.35\nkalker_reduction_factor = 0.6"),
      kSource);
  const auto* she = std::get_if<ShenHedrickElkinsCreep<double>>(&scene.contacts[0].creep_law);
  ASSERT_NE(she, nullptr);
  EXPECT_EQ(she->friction_coefficient, 0.35);
  EXPECT_EQ(she->kalker_reduction_factor, 0.6);
  // Default: linear Kalker without reduction (the thesis).
  const SceneSpec plain = load_scene_text(minimal_with("", ""), kSource);
  const auto* lin = std::get_if<LinearKalkerCreep<double>>(&plain.contacts[0].creep_law);
  ASSERT_NE(lin, nullptr);
  EXPECT_EQ(lin->kalker_reduction_factor, 1.0);
}

