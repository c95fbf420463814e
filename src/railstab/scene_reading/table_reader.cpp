#include <railstab/scene_reading/table_reader.hpp>

#include <railstab/scene_reading/key_suggestions.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace railstab::scene_reading {

std::string describe_found(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "a string " + quoted(node.as_string()->get());
    case toml::node_type::integer:
      return std::to_string(node.as_integer()->get());
    case toml::node_type::floating_point:
      return format_number(node.as_floating_point()->get());
    case toml::node_type::boolean:
      return node.as_boolean()->get() ? "true" : "false";
    case toml::node_type::array: {
      const size_t size = node.as_array()->size();
      return "an array of " + std::to_string(size) + (size == 1 ? " element" : " elements");
    }
    case toml::node_type::table:
      return "a table";
    case toml::node_type::date:
    case toml::node_type::time:
    case toml::node_type::date_time:
      return "a date/time";
    default:
      return "nothing";
  }
}

std::string unit_suffix(std::string_view unit) {
  return unit.empty() ? "" : " (" + std::string(unit) + ")";
}

std::string number_description(std::string_view unit) { return "a number" + unit_suffix(unit); }

double number_from(const toml::node& node, std::string_view source, std::string_view path,
                   std::string_view unit) {
  if (!node.is_number())
    fail_expectation(source, path, number_description(unit), describe_found(node));
  const double value = *node.value<double>();
  if (!std::isfinite(value))
    fail_expectation(source, path, "a finite number" + unit_suffix(unit), describe_found(node));
  return value;
}

std::string text_from(const toml::node& node, std::string_view source, std::string_view path) {
  if (!node.is_string()) fail_expectation(source, path, "a string", describe_found(node));
  return node.as_string()->get();
}

size_t choice_index(const toml::node& node, std::string_view source, std::string_view path,
                    const std::vector<std::string_view>& spellings) {
  std::string expected = "one of ";
  for (size_t i = 0; i < spellings.size(); ++i)
    expected += (i == 0 ? "" : ", ") + quoted(spellings[i]);
  if (!node.is_string()) fail_expectation(source, path, expected, describe_found(node));
  const std::string& text = node.as_string()->get();
  for (size_t i = 0; i < spellings.size(); ++i)
    if (text == spellings[i]) return i;
  fail_expectation(source, path, expected, quoted(text) + did_you_mean(text, spellings));
}

toml::table parse_toml(const std::string& text, const std::string& source) {
  try {
    return toml::parse(std::string_view(text), std::string_view(source));
  } catch (const toml::parse_error& error) {
    const toml::source_position& where = error.source().begin;
    throw SceneError(source + ": line " + std::to_string(where.line) + ", column " +
                     std::to_string(where.column) + ": expected valid TOML, got a syntax error: " +
                     std::string(error.description()));
  }
}

// --- TableReader ---------------------------------------------------------------------

TableReader::TableReader(const toml::table& table, std::string key_path, std::string source,
                         std::vector<std::string_view> known_keys, std::string owner)
    : table_(table),
      key_path_(std::move(key_path)),
      source_(std::move(source)),
      known_keys_(std::move(known_keys)),
      owner_(std::move(owner)) {
  reject_unknown_keys();
}

double TableReader::number(std::string_view key, std::string_view unit) const {
  return number_from(required(key, number_description(unit)), source_, path_of(key), unit);
}

std::string TableReader::text(std::string_view key) const {
  return text_from(required(key, "a string"), source_, path_of(key));
}

bool TableReader::flag_or(std::string_view key, bool fallback) const {
  const toml::node* node = find(key);
  if (!node) return fallback;
  if (!node->is_boolean()) fail(key, "true or false", describe_found(*node));
  return node->as_boolean()->get();
}

Eigen::Vector3d TableReader::vector3(std::string_view key, std::string_view unit) const {
  const std::string expected = "an array of 3 numbers" + unit_suffix(unit);
  const toml::node& node = required(key, expected);
  const toml::array* array = node.as_array();
  if (!array || array->size() != 3) fail(key, expected, describe_found(node));
  Eigen::Vector3d vector;
  for (size_t i = 0; i < 3; ++i)
    vector(Eigen::Index(i)) =
        number_from(*array->get(i), source_, indexed_path(path_of(key), i), unit);
  return vector;
}

const toml::array& TableReader::array(std::string_view key, std::string_view expected) const {
  const toml::node& node = required(key, expected);
  if (!node.is_array()) fail(key, expected, describe_found(node));
  return *node.as_array();
}

const toml::table* TableReader::raw_table_or_null(std::string_view key) const {
  const toml::node* node = find(key);
  if (!node) return nullptr;
  if (!node->is_table()) fail(key, "a table", describe_found(*node));
  return node->as_table();
}

std::optional<TableReader> TableReader::optional_table(
    std::string_view key, const std::vector<std::string_view>& known_keys) const {
  const toml::table* table = raw_table_or_null(key);
  if (!table) return std::nullopt;
  return TableReader(*table, path_of(key), source_, known_keys);
}

TableReader TableReader::table(std::string_view key,
                               const std::vector<std::string_view>& known_keys) const {
  if (!has(key)) fail_missing(key, "a table [" + path_of(key) + "]");
  return *optional_table(key, known_keys);
}

std::vector<TableReader> TableReader::tables_in_array(
    std::string_view key, const std::vector<std::string_view>& known_keys) const {
  const toml::array& tables = array(key, "an array of tables [[" + path_of(key) + "]]");
  std::vector<TableReader> readers;
  for (size_t i = 0; i < tables.size(); ++i) {
    const toml::node& element = *tables.get(i);
    const std::string path = indexed_path(path_of(key), i);
    if (!element.is_table()) fail_expectation(source_, path, "a table", describe_found(element));
    readers.emplace_back(*element.as_table(), path, source_, known_keys);
  }
  return readers;
}

const toml::node* TableReader::find(std::string_view key) const {
  if (std::find(known_keys_.begin(), known_keys_.end(), key) == known_keys_.end())
    throw std::logic_error("TableReader: key '" + std::string(key) +
                           "' is read but not declared for " + key_path_);
  return table_.get(key);
}

const toml::node& TableReader::required(std::string_view key, std::string_view expected) const {
  const toml::node* node = find(key);
  if (!node) fail_missing(key, expected);
  return *node;
}

void TableReader::reject_unknown_keys() const {
  for (const auto& [key, value] : table_) {
    const std::string_view name = key.str();
    if (std::find(known_keys_.begin(), known_keys_.end(), name) != known_keys_.end()) continue;
    throw scene_error(source_, path_of(name),
                      (owner_.empty() ? "unknown key" : "no such key on " + owner_) +
                          did_you_mean(name, known_keys_));
  }
}

}  // namespace railstab::scene_reading
