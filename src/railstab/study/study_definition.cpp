#include <railstab/study/study_definition.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace railstab {

namespace {

double number_in(std::string_view text, const std::string& what, const std::string& whole) {
  double value = 0.0;
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(value))
    throw std::invalid_argument("expected KEY=FROM:TO:STEP with finite numbers, got '" + whole +
                                "' (" + what + " is '" + std::string(text) + "')");
  return value;
}

std::size_t parse_count(std::string_view text, const std::string& whole) {
  std::size_t value = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size())
    throw std::invalid_argument("expected I/N with whole numbers 1 <= I <= N, got '" + whole + "'");
  return value;
}

}  // namespace

VariedKey parse_varied_key(std::string_view text) {
  const std::string whole(text);
  const size_t eq = text.find('=');
  if (eq == std::string_view::npos || eq == 0)
    throw std::invalid_argument("expected KEY=FROM:TO:STEP (e.g. "
                                "elements.yaw_damper.damping_N_s_per_m[0]=1e5:5e5:1e5), got '" +
                                whole + "'");
  VariedKey v;
  v.key = whole.substr(0, eq);
  for (size_t from = 0;;) {
    const size_t comma = v.key.find(',', from);
    std::string one = v.key.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
    if (one.empty())
      throw std::invalid_argument("expected KEY1,KEY2=FROM:TO:STEP with no empty key, got '" + whole + "'");
    for (const std::string& earlier : v.keys)
      if (earlier == one)
        throw std::invalid_argument("'" + one + "' is linked to itself in '" + whole + "'");
    v.keys.push_back(std::move(one));
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  const std::string_view range = text.substr(eq + 1);
  const size_t c1 = range.find(':');
  const size_t c2 = c1 == std::string_view::npos ? c1 : range.find(':', c1 + 1);
  if (c2 == std::string_view::npos || range.find(':', c2 + 1) != std::string_view::npos)
    throw std::invalid_argument("expected KEY=FROM:TO:STEP (three numbers after '='), got '" +
                                whole + "'");
  v.from = number_in(range.substr(0, c1), "FROM", whole);
  v.to = number_in(range.substr(c1 + 1, c2 - c1 - 1), "TO", whole);
  v.step = number_in(range.substr(c2 + 1), "STEP", whole);
  if (!(v.to >= v.from))
    throw std::invalid_argument("expected FROM <= TO in '" + whole + "'");
  if (!(v.step > 0.0)) throw std::invalid_argument("expected STEP > 0 in '" + whole + "'");
  const double steps = (v.to - v.from) / v.step;
  if (!(steps <= double(kMaxStudyCombinations)))
    throw std::invalid_argument("'" + whole + "' gives " + number_text_exact(std::floor(steps) + 1) +
                                " values; at most " + std::to_string(kMaxStudyCombinations));
  const double whole_steps = std::round(steps);
  if (std::abs(steps - whole_steps) > 1e-9 * std::max(1.0, steps))
    throw std::invalid_argument("expected TO = FROM + a whole number of STEPs in '" + whole +
                                "' ((TO - FROM) / STEP = " + number_text_exact(steps) + ")");
  const size_t n = size_t(whole_steps) + 1;
  // Each value rounded to 12 significant digits: 0.05 + 0.01 is 0.06, not
  // 0.060000000000000005 (what an engineer typed, in files and scenes).
  for (size_t i = 0; i < n; ++i) {
    const double exact = i + 1 == n ? v.to : v.from + double(i) * v.step;
    char text[32];
    std::snprintf(text, sizeof text, "%.12g", exact);
    v.values.push_back(std::strtod(text, nullptr));
  }
  return v;
}

std::string varied_key_text(const VariedKey& v) {
  return v.key + "=" + number_text_exact(v.from) + ":" + number_text_exact(v.to) + ":" +
         number_text_exact(v.step);
}

std::vector<SceneValueSetting> varied_settings(const VariedKey& v, double value) {
  const std::string origin = "--vary " + varied_key_text(v) + " (at " + number_text_exact(value) + ")";
  std::vector<SceneValueSetting> settings;
  for (const std::string& key : v.keys) settings.push_back({key, value, origin});
  return settings;
}

std::size_t StudyDefinition::combinations() const {
  std::size_t n = varied.empty() ? 0 : 1;
  for (const VariedKey& v : varied) n *= v.values.size();
  return n;
}

std::vector<double> StudyDefinition::values_of(std::size_t index) const {
  std::vector<double> values(varied.size());
  for (size_t k = varied.size(); k-- > 0;) {
    const size_t n = varied[k].values.size();
    values[k] = varied[k].values[index % n];
    index /= n;
  }
  return values;
}

std::string StudyDefinition::identity() const {
  // The path is left out: shards may run in other folders on other machines.
  std::string s = "scene " + scene_name + " (file FNV-1a " + scene_hash + ")";
  for (const SceneValueSetting& f : fixed) s += "; --set " + setting_text(f);
  for (const VariedKey& v : varied) s += "; --vary " + varied_key_text(v);
  s += "; --from " + number_text_exact(analysis.from_m_per_s) + " --to " +
       number_text_exact(analysis.to_m_per_s) + " --step " +
       number_text_exact(analysis.grid_step_m_per_s) + " --solver " + analysis.solver +
       " --hunting-band " + number_text_exact(analysis.hunting_band_hz);
  return s;
}

void check_study_definition(const StudyDefinition& d) {
  if (d.varied.empty()) throw std::invalid_argument("--vary: expected at least one KEY=FROM:TO:STEP");
  for (size_t i = 0; i < d.varied.size(); ++i)
    for (const std::string& key : d.varied[i].keys) {
      for (size_t j = 0; j < i; ++j)
        for (const std::string& earlier : d.varied[j].keys)
          if (earlier == key)
            throw std::invalid_argument("--vary: " + key + " is varied twice");
      for (const SceneValueSetting& f : d.fixed)
        if (f.key == key)
          throw std::invalid_argument("--set " + f.key + ": the key is also varied (--vary " +
                                      varied_key_text(d.varied[i]) + "); give it once");
    }
  double n = 1.0;
  for (const VariedKey& v : d.varied) n *= double(v.values.size());
  if (n > double(kMaxStudyCombinations))
    throw std::invalid_argument("--vary: the keys give " + number_text_exact(n) +
                                " combinations; at most " + std::to_string(kMaxStudyCombinations));
}

std::string fnv1a64_hex(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  static const char* hex = "0123456789abcdef";
  std::string s(16, '0');
  for (int i = 15; i >= 0; --i, h >>= 4) s[size_t(i)] = hex[h & 0xF];
  return s;
}

StudyShard parse_study_shard(std::string_view text) {
  const std::string whole(text);
  const size_t slash = text.find('/');
  if (slash == std::string_view::npos)
    throw std::invalid_argument("expected I/N with whole numbers 1 <= I <= N, got '" + whole + "'");
  StudyShard s;
  s.index = parse_count(text.substr(0, slash), whole);
  s.count = parse_count(text.substr(slash + 1), whole);
  if (s.index < 1 || s.index > s.count || s.count > kMaxStudyCombinations)
    throw std::invalid_argument("expected I/N with whole numbers 1 <= I <= N, got '" + whole + "'");
  return s;
}

}  // namespace railstab
