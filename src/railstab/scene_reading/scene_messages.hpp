#pragma once
// How scene-reading messages are written, shared by the table reader, the
// section readers and the checker: every error reads
//   "<file>: <key path>: expected <what was expected>, got <what was found>"
// with key paths like "bodies[2].mass_kg" and numbers in their shortest
// exact form. Internal to scene_reading/.
#include <railstab/scene/physical_ranges.hpp>
#include <railstab/scene_reading/scene_error.hpp>

#include <Eigen/Dense>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace railstab::scene_reading {

// Shortest text that reads back as the same double: -3, 0.1, 2.1e+11.
std::string format_number(double value);
// "[x, y, z]" with format_number.
std::string format_vector(const Eigen::Vector3d& v);
std::string quoted(std::string_view text);
// "a, b, c" (or "none" for an empty list).
std::string comma_separated(const std::vector<std::string>& items);

// Key paths: "bodies[2]" + "mass_kg" -> "bodies[2].mass_kg"; "bodies", 2 -> "bodies[2]".
std::string child_path(std::string_view parent, std::string_view key);
std::string indexed_path(std::string_view array_path, size_t index);

// "<source>: <key path>: <message>".
SceneError scene_error(std::string_view source, std::string_view key_path,
                       std::string_view message);
// The uniform message: "<file>: <key path>: expected <expected>, got <found>".
[[noreturn]] void fail_expectation(std::string_view source, std::string_view key_path,
                                   std::string_view expected, std::string_view found);

// "a mass in [0.1, 1e6] kg" (scene/physical_ranges.hpp).
std::string range_text(const PhysicalRange& range);

// What is wrong with a name of a body, element, contact or scene (empty,
// too long, a control character), or nothing; see the .cpp for why.
std::optional<std::string> name_problem(std::string_view name,
                                        size_t max_bytes = physical_ranges::kMaxNameBytes);
// The "expected ..." of a name refused by name_problem.
const std::string& name_expectation();

}  // namespace railstab::scene_reading
