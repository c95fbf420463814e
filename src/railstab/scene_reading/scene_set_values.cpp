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

// A TOML value given as text ("{ y_m = 0.001 }", "[1, 2]", "\"polach\"",
// "true"), parsed as the value of a key; throws std::invalid_argument saying
// what was expected and what TOML made of it.
toml::table parsed_value_document(const std::string& key, const std::string& text) {
  try {
    toml::table doc = toml::parse("value = " + text);
    if (doc.size() != 1 || !doc.contains("value")) throw std::invalid_argument("");
    return doc;
  } catch (const toml::parse_error& e) {
    throw std::invalid_argument(
        "expected a number or one TOML value (an inline table like {y_m = 0.001}, an array "
        "like [1.0, 2.0], a quoted string, true or false) as the value of " + key + ", got '" +
        text + "' (" + std::string(e.description()) + ")");
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument("expected one TOML value as the value of " + key + ", got '" +
                                text + "' (more than one value)");
  }
}

// Does VALUE's text ask for a TOML value rather than a number?
bool is_toml_value_text(std::string_view value) {
  if (value.empty()) return false;
  const char c = value.front();
  return c == '{' || c == '[' || c == '"' || c == '\'' || value == "true" || value == "false";
}

// Applies one setting to `root`; throws std::invalid_argument with what is
// wrong (the caller adds the file and the flag).
class SettingWriter {
 public:
  explicit SettingWriter(const SceneValueSetting& setting) : setting_(setting), parts_(split_dots(setting.key)) {
    if (!setting.toml_value.empty()) value_document_ = parsed_value_document(setting.key, setting.toml_value);
  }

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

  // Steps at..end are keys without an index.
  bool plain_keys_from(size_t at) const {
    for (size_t i = at; i < parts_.size(); ++i) {
      const std::optional<PathStep> step = parse_step(parts_[i]);
      if (!step || step->index || step->key.empty()) return false;
    }
    return true;
  }

  // The setting's value written under `key` of `table` (a number, or a copy
  // of the parsed TOML value).
  void put(toml::table& table, const std::string& key) const {
    if (value_document_.empty()) {
      table.insert_or_assign(key, setting_.value);
      return;
    }
    value_document_.get("value")->visit([&](const auto& v) { table.insert_or_assign(key, v); });
  }
  void put(toml::array& array, size_t index) const {
    const auto at = array.cbegin() + std::ptrdiff_t(index);
    if (value_document_.empty()) {
      array.replace(at, setting_.value);
      return;
    }
    value_document_.get("value")->visit([&](const auto& v) { array.replace(at, v); });
  }

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
        // An entry of an array of tables is never written whole.
        slot_ = array->is_array_of_tables() ? Slot{} : Slot{nullptr, "", array, *step->index};
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
        slot_ = Slot{};  // an entry is a table, never written whole
        const std::string entry_where = here + "[" + std::to_string(*step->index) + "]";
        if (at + 1 == parts_.size()) return write(entry, entry_where);
        return descend(entry, at + 1, entry_where);
      }
    }
    // A key the table does not hold is added, with the tables on the way
    // to it when the rest of the path has none of its own (an optional key
    // or section at its default); the reader decides whether the scene may
    // have them. An index asks for an array that is not there: refused.
    // Not a new entry of a named collection ([contacts.<name>]): a name
    // that is not there is a typo, refused below with the names there are.
    if (node.is_table() && plain_keys_from(at) && where != "contacts") {
      toml::table* table = node.as_table();
      for (size_t i = at; i + 1 < parts_.size(); ++i)
        table = table->insert_or_assign(parts_[i], toml::table{}).first->second.as_table();
      put(*table, parts_.back());
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
    if (!value_document_.empty()) {  // a TOML value replaces whatever is there
      if (slot_.table) return put(*slot_.table, slot_.key);
      if (slot_.array) return put(*slot_.array, slot_.index);
      throw std::invalid_argument(where + " is an entry of an array of tables, which --set does "
                                  "not replace whole: set its keys one by one (" + setting_.key +
                                  ".KEY=VALUE)");
    }
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
    throw std::invalid_argument(where + " is " + node_kind(node) +
                                " in the scene, not a number: give a value of that kind (e.g. " +
                                setting_.key + "={...} for a table, [...] for an array, \"...\" "
                                "for a string)");
  }

  const SceneValueSetting& setting_;
  std::vector<std::string> parts_;
  toml::table value_document_;  // { value = <the TOML value> }; empty for a number
  Slot slot_;  // of the node write() is given
};

}  // namespace

std::string number_text_exact(double value) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, r.ptr);
}

std::string setting_text(const SceneValueSetting& setting) {
  return setting.key + "=" +
         (setting.toml_value.empty() ? number_text_exact(setting.value) : setting.toml_value);
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
  if (is_toml_value_text(value)) {
    s.toml_value = std::string(value);
    parsed_value_document(s.key, s.toml_value);  // throws what is wrong
    return s;
  }
  if (!value.empty() && value.front() == '+') value.remove_prefix(1);
  const auto r = std::from_chars(value.data(), value.data() + value.size(), s.value);
  if (value.empty() || r.ec != std::errc() || r.ptr != value.data() + value.size() ||
      !std::isfinite(s.value))
    throw std::invalid_argument("expected a finite number (or a TOML value: {...}, [...], \"...\", "
                                "true, false) as the value of " + s.key + ", got '" +
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
