#include <railstab/study/study_record.hpp>

#include <railstab/io/regular_file.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <toml++/toml.h>

#include <map>
#include <sstream>
#include <stdexcept>

namespace railstab {

namespace {

// Format 2: the output keys renamed to one convention (docs/outputs.md,
// "Naming convention"); format 1 records are refused, naming the renames.
constexpr const char* kFormat = "railstab study record 2";

// Keys of a format-1 record and their names now. A record holding one is
// refused with the file, the key and the new name: an old name is accepted
// nowhere silently (and `scene` changed meaning: it was the path).
struct RenamedKey {
  const char* table;  // "study" or "points"
  const char* old_key;
  const char* new_key;
};
constexpr RenamedKey kRenamedKeys[] = {
    {"study", "scene_name", "scene"},
    {"points", "frequency_Hz", "hunting_frequency_Hz"},
    {"points", "mode", "hunting_mode"},
};

// Refuses a record written with the old key names (format 1, before the
// rename): names the first old key found and its new name, and says what the
// old `scene` (the path) is now.
void refuse_old_key_names(const toml::table& root, const std::string& path) {
  auto refuse = [&](const RenamedKey& k) {
    throw std::runtime_error(
        path + ": " + k.table + "." + k.old_key + ": renamed to " + k.table + "." + k.new_key +
        "; the record was written by an older railstab (format 'railstab study record 1'), "
        "whose study.scene_name, study.scene (the path), points.frequency_Hz and points.mode "
        "are now study.scene, study.scene_file, points.hunting_frequency_Hz and "
        "points.hunting_mode: re-run the study or its shard to write a current record");
  };
  const toml::table* study = root.get_as<toml::table>("study");
  const toml::array* points = root.get_as<toml::array>("points");
  for (const RenamedKey& k : kRenamedKeys) {
    if (std::string(k.table) == "study") {
      if (study && study->contains(k.old_key)) refuse(k);
    } else if (points) {
      for (const toml::node& n : *points)
        if (const toml::table* t = n.as_table(); t && t->contains(k.old_key)) refuse(k);
    }
  }
}

[[noreturn]] void fail(const std::string& path, const std::string& key, const std::string& expected) {
  throw std::runtime_error(path + ": " + key + ": expected " + expected);
}

const toml::table& table_at(const toml::table& t, const std::string& key, const std::string& path) {
  const toml::table* sub = t.get_as<toml::table>(key);
  if (!sub) fail(path, key, "a table");
  return *sub;
}

std::string text_at(const toml::table& t, const std::string& key, const std::string& path,
                    const std::string& where) {
  const auto* s = t.get_as<std::string>(key);
  if (!s) fail(path, where + key, "a string");
  return s->get();
}

double number_at(const toml::table& t, const std::string& key, const std::string& path,
                 const std::string& where) {
  const toml::node* n = t.get(key);
  if (!n || !n->is_number()) fail(path, where + key, "a number");
  return *n->value<double>();
}

std::size_t count_at(const toml::table& t, const std::string& key, const std::string& path,
                     const std::string& where) {
  const auto* n = t.get_as<int64_t>(key);
  if (!n || n->get() < 0) fail(path, where + key, "a whole number >= 0");
  return std::size_t(n->get());
}

const toml::array& array_at(const toml::table& t, const std::string& key, const std::string& path,
                            const std::string& where) {
  const toml::array* a = t.get_as<toml::array>(key);
  if (!a) fail(path, where + key, "an array");
  return *a;
}

}  // namespace

void write_study_record(std::ostream& out, const StudyDefinition& d, const StudyShard& shard,
                        const std::vector<StudyPoint>& points) {
  toml::table study{{"format", kFormat},
                    {"scene", d.scene_name},
                    {"scene_file", d.scene_path},
                    {"scene_fnv1a64", d.scene_hash},
                    {"combinations", int64_t(d.combinations())},
                    {"shard", int64_t(shard.index)},
                    {"shards", int64_t(shard.count)},
                    {"from_m_per_s", d.analysis.from_m_per_s},
                    {"to_m_per_s", d.analysis.to_m_per_s},
                    {"grid_step_m_per_s", d.analysis.grid_step_m_per_s},
                    {"eigen_solver", d.analysis.solver},
                    {"hunting_band_Hz", d.analysis.hunting_band_hz}};
  toml::array set, vary, rows;
  // A number as a number (exact); a TOML value (a table, an array) as its text.
  for (const SceneValueSetting& s : d.fixed)
    set.push_back(s.toml_value.empty() ? toml::table{{"key", s.key}, {"value", s.value}}
                                       : toml::table{{"key", s.key}, {"toml_value", s.toml_value}});
  for (const VariedKey& v : d.varied)
    vary.push_back(toml::table{{"key", v.key}, {"from", v.from}, {"to", v.to}, {"step", v.step}});
  for (const StudyPoint& p : points) {
    toml::array values;
    for (double x : p.values) values.push_back(x);
    rows.push_back(toml::table{{"index", int64_t(p.index)},
                               {"values", values},
                               {"status", p.status},
                               {"critical_speed_found", p.critical_speed_found},
                               {"critical_speed_m_per_s", p.critical_speed_m_per_s},
                               {"hunting_frequency_Hz", p.frequency_hz},
                               {"hunting_mode", p.mode},
                               {"message", p.message}});
  }
  study.insert("set", set);
  study.insert("vary", vary);
  const toml::table root{{"study", study}, {"points", rows}};
  out << "# railstab study record: read by `railstab merge`; do not edit.\n" << root << "\n";
}

StudyRecord read_study_record(const std::string& path) {
  toml::table root;
  try {
    root = toml::parse(read_regular_file(path), path);
  } catch (const toml::parse_error& e) {
    throw std::runtime_error(path + ": expected a railstab study record (TOML), got a syntax error: " +
                             std::string(e.description()));
  }
  refuse_old_key_names(root, path);
  StudyRecord r;
  r.path = path;
  const toml::table& s = table_at(root, "study", path);
  if (text_at(s, "format", path, "study.") != kFormat)
    fail(path, "study.format", std::string("'") + kFormat + "'");
  StudyDefinition& d = r.definition;
  d.scene_name = text_at(s, "scene", path, "study.");
  d.scene_path = text_at(s, "scene_file", path, "study.");
  d.scene_hash = text_at(s, "scene_fnv1a64", path, "study.");
  d.analysis.from_m_per_s = number_at(s, "from_m_per_s", path, "study.");
  d.analysis.to_m_per_s = number_at(s, "to_m_per_s", path, "study.");
  d.analysis.grid_step_m_per_s = number_at(s, "grid_step_m_per_s", path, "study.");
  d.analysis.solver = text_at(s, "eigen_solver", path, "study.");
  try {
    (void)eigen_solver_from_name(d.analysis.solver);  // the names and the message are its own
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path + ": study.eigen_solver: " + e.what());
  }
  d.analysis.hunting_band_hz = number_at(s, "hunting_band_Hz", path, "study.");
  for (const toml::node& n : array_at(s, "set", path, "study.")) {
    const toml::table* t = n.as_table();
    if (!t) fail(path, "study.set", "an array of tables");
    if (t->contains("toml_value")) {
      SceneValueSetting f(text_at(*t, "key", path, "study.set."), 0.0);
      f.toml_value = text_at(*t, "toml_value", path, "study.set.");
      d.fixed.push_back(std::move(f));
    } else {
      d.fixed.push_back({text_at(*t, "key", path, "study.set."), number_at(*t, "value", path, "study.set."), ""});
    }
  }
  for (const toml::node& n : array_at(s, "vary", path, "study.")) {
    const toml::table* t = n.as_table();
    if (!t) fail(path, "study.vary", "an array of tables");
    VariedKey v;
    v.key = text_at(*t, "key", path, "study.vary.");
    v.from = number_at(*t, "from", path, "study.vary.");
    v.to = number_at(*t, "to", path, "study.vary.");
    v.step = number_at(*t, "step", path, "study.vary.");
    try {
      d.varied.push_back(parse_varied_key(varied_key_text(v)));
    } catch (const std::invalid_argument& e) {
      fail(path, "study.vary", std::string("a valid range (") + e.what() + ")");
    }
  }
  if (d.varied.empty()) fail(path, "study.vary", "at least one varied key");
  if (count_at(s, "combinations", path, "study.") != d.combinations())
    fail(path, "study.combinations", "the product of the varied keys' value counts, " +
                                         std::to_string(d.combinations()));
  r.shard.index = count_at(s, "shard", path, "study.");
  r.shard.count = count_at(s, "shards", path, "study.");
  if (r.shard.index < 1 || r.shard.index > r.shard.count)
    fail(path, "study.shard", "1 <= shard <= shards");
  const toml::array* points = root.get_as<toml::array>("points");
  if (points)
    for (const toml::node& n : *points) {
      const toml::table* t = n.as_table();
      if (!t) fail(path, "points", "an array of tables");
      StudyPoint p;
      p.index = count_at(*t, "index", path, "points.");
      if (p.index >= d.combinations() || !r.shard.holds(p.index))
        fail(path, "points.index", "an index of shard " + std::to_string(r.shard.index) + "/" +
                                       std::to_string(r.shard.count) + ", got " + std::to_string(p.index));
      p.values = d.values_of(p.index);
      p.status = text_at(*t, "status", path, "points.");
      const auto* found = t->get_as<bool>("critical_speed_found");
      if (!found) fail(path, "points.critical_speed_found", "true or false");
      p.critical_speed_found = found->get();
      p.critical_speed_m_per_s = number_at(*t, "critical_speed_m_per_s", path, "points.");
      p.frequency_hz = number_at(*t, "hunting_frequency_Hz", path, "points.");
      p.mode = text_at(*t, "hunting_mode", path, "points.");
      p.message = text_at(*t, "message", path, "points.");
      r.points.push_back(std::move(p));
    }
  return r;
}

std::vector<StudyPoint> merge_study_records(const std::vector<StudyRecord>& records) {
  if (records.empty()) throw std::runtime_error("merge: expected at least one shard folder");
  const StudyRecord& first = records.front();
  const std::string identity = first.definition.identity();
  std::map<std::size_t, const StudyRecord*> by_shard;
  for (const StudyRecord& r : records) {
    if (r.definition.identity() != identity)
      throw std::runtime_error("merge: " + r.path + " is from a different study than " + first.path +
                               ":\n  " + r.definition.identity() + "\n  " + identity);
    if (r.shard.count != first.shard.count)
      throw std::runtime_error("merge: " + r.path + " is shard " + std::to_string(r.shard.index) +
                               "/" + std::to_string(r.shard.count) + " but " + first.path +
                               " is shard " + std::to_string(first.shard.index) + "/" +
                               std::to_string(first.shard.count) + ": a study is merged from one split");
    const auto [it, inserted] = by_shard.emplace(r.shard.index, &r);
    if (!inserted)
      throw std::runtime_error("merge: shard " + std::to_string(r.shard.index) + "/" +
                               std::to_string(r.shard.count) + " is given twice: " + it->second->path +
                               " and " + r.path);
  }
  std::string missing;
  for (std::size_t i = 1; i <= first.shard.count; ++i)
    if (!by_shard.count(i))
      missing += (missing.empty() ? "" : ", ") + std::to_string(i) + "/" + std::to_string(first.shard.count);
  if (!missing.empty()) throw std::runtime_error("merge: shard(s) " + missing + " missing");
  const std::size_t n = first.definition.combinations();
  std::vector<StudyPoint> all(n);
  std::vector<bool> have(n, false);
  for (const StudyRecord& r : records)
    for (const StudyPoint& p : r.points) {
      if (have[p.index])
        throw std::runtime_error("merge: " + r.path + ": combination " + std::to_string(p.index) +
                                 " appears twice");
      have[p.index] = true;
      all[p.index] = p;
    }
  for (std::size_t i = 0; i < n; ++i)
    if (!have[i])
      throw std::runtime_error("merge: " + by_shard[i % first.shard.count + 1]->path +
                               ": combination " + std::to_string(i) + " of its shard is missing");
  return all;
}

}  // namespace railstab
