// The element readers: one per kind of the variant, built from the kinds'
// reader files (scene_reading/element_readers/). The compile-time half of
// the contract is asserted here too: a kind with a reader satisfies
// ElementKindHasReader, a kind without one does not (element_kind_readers.cpp
// then refuses to compile with a message naming the missing reader).
#include <gtest/gtest.h>

#include <railstab/elements/element.hpp>
#include <railstab/scene_reading/element_kind_readers.hpp>
#include <railstab/scene_reading/element_readers/bump_stop_reader.hpp>
#include <railstab/scene_reading/element_readers/traction_rod_reader.hpp>
#include <railstab/scene_reading/load_scene.hpp>

#include <set>
#include <string>
#include <variant>

using namespace railstab;
using namespace railstab::scene_reading;

namespace {

// A kind that is nowhere given a reader.
struct KindWithoutReader {
  static constexpr const char* kType = "kind_without_reader";
};

static_assert(ElementKindHasReader<TractionRod<double>>);
static_assert(ElementKindHasReader<BumpStop<double>>);
static_assert(!ElementKindHasReader<KindWithoutReader>);

template <class... Kinds>
std::vector<std::string> variant_types(std::type_identity<std::variant<Kinds...>>) {
  return {Kinds::kType...};
}

const std::string kScene = R"toml(
[scene]
name = "stops"
speed_m_per_s = 0.0
reference_arc_length_m = 10.0

[track]
[[track.segments]]
type = "tangent"
length_m = 100.0

[[bodies]]
name = "frame"
type = "rigid_body"
mass_kg = 1000.0
inertia_kg_m2 = [100.0, 100.0, 100.0]
position_m = [0.0, 0.0, 1.0]

[[elements]]
name = "stop"
type = "bump_stop"
body1 = "track"
body2 = "frame"
point1_m = [0.0, 0.5, 1.0]
point2_m = [0.0, 0.5, 0.0]
axis = [0.0, 3.0, 4.0]
clearance_m = 0.02
stiffness_N_per_m = 1.0e6
mirror_lateral = true
)toml";

}  // namespace

TEST(ElementReaders, OneReaderPerKindOfTheVariantInItsOrder) {
  std::vector<std::string> types;
  for (const ElementKindReader& r : element_kind_readers()) {
    types.emplace_back(r.type);
    // A kind's own keys are distinct and none is a key every element takes.
    const std::set<std::string_view> own(r.keys.begin(), r.keys.end());
    EXPECT_EQ(own.size(), r.keys.size()) << r.type;
    for (const char* common : {"name", "type", "body1", "body2", "point1_m", "point2_m",
                               "mirror_lateral"})
      EXPECT_EQ(own.count(common), 0u) << r.type << " lists " << common;
  }
  EXPECT_EQ(types, variant_types(std::type_identity<ElementSpec>{}));
}

TEST(ElementReaders, MirroringABumpStopMirrorsItsAxisWithItsPoints) {
  const SceneSpec scene = load_scene_text(kScene, "stops.toml");
  ASSERT_EQ(scene.elements.size(), 2u);
  const auto& left = std::get<BumpStop<double>>(scene.elements[0]);
  const auto& right = std::get<BumpStop<double>>(scene.elements[1]);
  EXPECT_EQ(left.ends.name, "stop_left");
  EXPECT_EQ(right.ends.name, "stop_right");
  // The axis is normalised (0, 0.6, 0.8); the right stop's y is negated.
  EXPECT_NEAR(left.axis.y(), 0.6, 1e-15);
  EXPECT_NEAR(right.axis.y(), -0.6, 1e-15);
  EXPECT_NEAR(right.axis.z(), 0.8, 1e-15);
  EXPECT_DOUBLE_EQ(right.ends.point1_m.y(), -0.5);
  EXPECT_DOUBLE_EQ(right.ends.point2_m.y(), -0.5);
}
