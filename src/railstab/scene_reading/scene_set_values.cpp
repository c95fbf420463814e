#include <railstab/scene_reading/scene_set_values.hpp>

#include <toml++/toml.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace railstab {

namespace {

// One step of a key path: a key (or an entry's name), maybe with an index.
struct PathStep {
  std::string key;
  std::optional<size_t> index;
};

// "name" or "name[3]"; nullopt if the brackets are malformed.
std::optional<PathStep> parse_step(std::string_view text) {
  PathStep step;
  const size_t open = text.size() > 2 && text.back() == ']' ? text.rfind('[') : std::string_view::npos;
  if (open == std::string_view::npos) {
    step.key = std::string(text);
    return step;
  }
  const std::string_view digits = text.substr(open + 1, text.size() - open - 2);
  size_t index = 0;
  const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), index);
  if (digits.empty() || r.ec != std::errc() || r.ptr != digits.data() + digits.size())
    return std::nullopt;
  step.key = std::string(text.substr(0, open));
  step.index = index;
  return step;
}

std::vector<std::string> split_dots(const std::string& key) {
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t dot; (dot = key.find('.', start)) != std::string::npos; start = dot + 1)
    parts.push_back(key.substr(start, dot - start));
  parts.push_back(key.substr(start));
  return parts;
}

std::string joined(const std::vector<std::string>& parts, size_t from, size_t to) {
  std::string text;
  for (size_t i = from; i < to; ++i) text += (i > from ? "." : "") + parts[i];
  return text;
}

std::string node_kind(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    default: return "not a number";
  }
}

// Applies one setting to `root`; throws std::invalid_argument with what is
// wrong (the caller adds the file and the flag).
class SettingWriter {
 public:
  explicit SettingWriter(const SceneValueSetting& setting) : setting_(setting), parts_(split_dots(setting.key)) {}

  void apply(toml::table& root) {
    if (setting_.key.empty()) throw std::invalid_argument("expected a key path before '='");
    for (const std::string& part : parts_)
      if (part.empty())
        throw std::invalid_argument("expected a key path like bodies.carbody.mass_kg, got an empty "
                                    "step between dots");
    descend(root, 0, "");
  }

 private:
  // The names a table or an array of tables offers at `where`, for messages.
  static std::string offered(const toml::node& node) {
    std::string list;
    auto add = [&](const std::string& s) { list += (list.empty() ? "" : ", ") + s; };
    if (const toml::table* t = node.as_table())
      for (const auto& [k, v] : *t) add(std::string(k.str()));
    if (const toml::array* a = node.as_array())
      for (size_t i = 0; i < a->size(); ++i) {
        const toml::table* entry = a->get(i)->as_table();
        const std::string* name = entry && entry->get_as<std::string>("name")
                                      ? &entry->get_as<std::string>("name")->get()
                                      : nullptr;
        add(name ? *name : "[" + std::to_string(i) + "]");
      }
    return list.empty() ? "nothing" : list;
  }

  static std::string place(const std::string& where) { return where.empty() ? "the scene" : where; }

  void descend(toml::node& node, size_t at, const std::string& where) {
    const bool is_array_of_tables = node.is_array() && node.as_array()->is_array_of_tables();
    if (!node.is_table() && !is_array_of_tables)
      throw std::invalid_argument(place(where) + " is " + node_kind(node) + ", which holds no '" +
                                  joined(parts_, at, parts_.size()) + "'");
    // The longest run of steps that names a child: names may hold dots.
    for (size_t end = parts_.size(); end > at; --end) {
      const std::optional<PathStep> step = parse_step(joined(parts_, at, end));
      if (!step) continue;
      const std::string here = (where.empty() ? "" : where + ".") + step->key;
      toml::node* child = nullptr;
      if (toml::table* t = node.as_table()) {
        child = t->get(step->key);
        slot_ = Slot{t, step->key, nullptr, 0};
      } else if (step->key.empty() && step->index) {
        continue;  // "[i]" alone is handled below as an index on the array
      } else {
        for (toml::node& entry : *node.as_array()) {
          const toml::table* e = entry.as_table();
          if (e && e->get_as<std::string>("name") && e->get_as<std::string>("name")->get() == step->key)
            child = &entry;
        slot_ = Slot{};  // an entry is a table, never written
        }
      }
      if (!child) continue;
      if (step->index) {
        toml::array* array = child->as_array();
        if (!array)
          throw std::invalid_argument(here + " is " + node_kind(*child) +
                                      (child->is_number() ? " number" : "") +
                                      ", not an array: drop the index [" +
                                      std::to_string(*step->index) + "]");
        if (*step->index >= array->size())
          throw std::invalid_argument("index " + std::to_string(*step->index) + " out of range: " +
                                      here + " has " + std::to_string(array->size()) +
                                      (array->size() == 1 ? " element" : " elements") +
                                      " (indices from 0)");
        child = array->get(*step->index);
        slot_ = Slot{nullptr, "", array, *step->index};
      }
      if (end == parts_.size()) return write(*child, here + (step->index ? "[" + std::to_string(*step->index) + "]" : ""));
      return descend(*child, end, here + (step->index ? "[" + std::to_string(*step->index) + "]" : ""));
    }
    // An index on an array of tables: "bodies[2].mass_kg".
    const std::optional<PathStep> step = parse_step(parts_[at]);
    if (step && step->index && node.is_table()) {
      toml::node* array_node = node.as_table()->get(step->key);
      if (array_node && array_node->is_array() && array_node->as_array()->is_array_of_tables()) {
        toml::array& array = *array_node->as_array();
        const std::string here = (where.empty() ? "" : where + ".") + step->key;
        if (*step->index >= array.size())
          throw std::invalid_argument("index " + std::to_string(*step->index) + " out of range: " +
                                      here + " has " + std::to_string(array.size()) +
                                      (array.size() == 1 ? " entry" : " entries") +
                                      " (indices from 0)");
        toml::node& entry = *array.get(*step->index);
        const std::string entry_where = here + "[" + std::to_string(*step->index) + "]";
        if (at + 1 == parts_.size()) return write(entry, entry_where);
        return descend(entry, at + 1, entry_where);
      }
    }
    // A last key the table does not hold is added; the reader decides
    // whether that table may have it.
    if (at + 1 == parts_.size() && node.is_table() && step && !step->index) {
      node.as_table()->insert_or_assign(step->key, setting_.value);
      return;
    }
    throw std::invalid_argument(place(where) + " has no '" + parts_[at] + "' (it has: " +
                                offered(node) + ")");
  }

  // Where a value lives, so that an integer can be replaced by a float.
  struct Slot {
    toml::table* table = nullptr;
    std::string key;
    toml::array* array = nullptr;
    size_t index = 0;
  };

  void write(toml::node& node, const std::string& where) {
    const double v = setting_.value;
    if (node.is_integer() && v == std::floor(v) && std::abs(v) < 9.0e15) {
      node.ref<int64_t>() = int64_t(v);  // an integer stays one (an order, a count)
      return;
    }
    if (node.is_floating_point()) {
      node.ref<double>() = v;
      return;
    }
    if (node.is_integer()) {  // 1500 in the file, 1500.5 asked: becomes a float
      if (slot_.table) slot_.table->insert_or_assign(slot_.key, v);
      if (slot_.array) slot_.array->replace(slot_.array->cbegin() + std::ptrdiff_t(slot_.index), v);
      return;
    }
    if (node.is_array())
      throw std::invalid_argument(where + " is an array of " +
                                  std::to_string(node.as_array()->size()) +
                                  " values: give an index, e.g. " + setting_.key + "[0]");
    throw std::invalid_argument(where + " is " + node_kind(node) + " in the scene, not a number");
  }

  const SceneValueSetting& setting_;
  std::vector<std::string> parts_;
  Slot slot_;  // of the node write() is given
};

}  // namespace

std::string number_text_exact(double value) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, r.ptr);
}

std::string setting_text(const SceneValueSetting& setting) {
  return setting.key + "=" + number_text_exact(setting.value);
}

SceneValueSetting parse_scene_value_setting(std::string_view text) {
  const size_t eq = text.find('=');
  if (eq == std::string_view::npos)
    throw std::invalid_argument("expected KEY=VALUE (e.g. bodies.carbody.mass_kg=32000), got '" +
                                std::string(text) + "'");
  SceneValueSetting s;
  s.key = std::string(text.substr(0, eq));
  if (s.key.empty())
    throw std::invalid_argument("expected KEY=VALUE with a key path before '=', got '" +
                                std::string(text) + "'");
  std::string_view value = text.substr(eq + 1);
  if (!value.empty() && value.front() == '+') value.remove_prefix(1);
  const auto r = std::from_chars(value.data(), value.data() + value.size(), s.value);
  if (value.empty() || r.ec != std::errc() || r.ptr != value.data() + value.size() ||
      !std::isfinite(s.value))
    throw std::invalid_argument("expected a finite number as the value of " + s.key + ", got '" +
                                std::string(text.substr(eq + 1)) + "'");
  return s;
}

std::string scene_text_with_values(const std::string& toml_text, const std::string& source_name,
                                   const std::vector<SceneValueSetting>& settings) {
  if (settings.empty()) return toml_text;
  toml::table root;
  try {
    root = toml::parse(std::string_view(toml_text), std::string_view(source_name));
  } catch (const toml::parse_error&) {
    return toml_text;  // the reader reports the syntax error with its line and column
  }
  for (const SceneValueSetting& s : settings) {
    try {
      SettingWriter(s).apply(root);
    } catch (const std::invalid_argument& e) {
      throw SceneError(source_name + ": " + (s.origin.empty() ? "--set " + setting_text(s) : s.origin) +
                       ": " + e.what());
    }
  }
  // toml++ writes floats in their shortest exact form (std::to_chars), so
  // every number reads back as the same double.
  std::ostringstream text;
  text << root;
  return text.str();
}

std::string settings_in_force(const std::vector<SceneValueSetting>& settings) {
  if (settings.empty()) return "";
  std::string in_force;
  for (const SceneValueSetting& s : settings)
    in_force += " " + (s.origin.empty() ? "--set " + setting_text(s) : s.origin);
  return " (with" + in_force + ")";
}

}  // namespace railstab
