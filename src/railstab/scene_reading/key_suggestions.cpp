#include <railstab/scene_reading/key_suggestions.hpp>

#include <railstab/scene_reading/scene_messages.hpp>

#include <algorithm>
#include <cctype>
#include <optional>
#include <utility>

namespace railstab::scene_reading {
namespace {

std::string lower_case(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
  return lower;
}

bool is_unit_word(std::string_view word) {
  static const std::vector<std::string_view> kUnitWords = {
      "m",  "mm",  "cm",  "km",  "kg",  "g",   "s",    "ms",  "h",  "min", "n",  "kn",
      "pa", "kpa", "mpa", "gpa", "rad", "deg", "mrad", "per", "m2", "m3",  "s2", "hz"};
  return std::find(kUnitWords.begin(), kUnitWords.end(), lower_case(word)) != kUnitWords.end();
}

// The key without its unit suffix, lower case: "mass_kg" and "mass_g" -> "mass",
// "speed_m_per_s" -> "speed", "f23_N_m" -> "f23". The first word always stays.
std::string unit_stripped_stem(std::string_view key) {
  std::vector<std::string_view> words;
  size_t start = 0;
  while (start <= key.size()) {
    const size_t end = std::min(key.find('_', start), key.size());
    words.push_back(key.substr(start, end - start));
    start = end + 1;
  }
  while (words.size() > 1 && is_unit_word(words.back())) words.pop_back();
  std::string stem;
  for (std::string_view word : words) stem += (stem.empty() ? "" : "_") + std::string(word);
  return lower_case(stem);
}

// Levenshtein distance (insertions, deletions, substitutions), case-insensitive.
size_t edit_distance(std::string_view a_text, std::string_view b_text) {
  const std::string a = lower_case(a_text), b = lower_case(b_text);
  std::vector<size_t> previous(b.size() + 1), current(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

// The candidate the user most likely meant: one with the same stem before the
// unit suffix, else the nearest within a small edit distance; none if nothing fits.
std::optional<std::string> closest_name(std::string_view name,
                                        const std::vector<std::string_view>& candidates) {
  const std::string stem = unit_stripped_stem(name);
  for (std::string_view candidate : candidates)
    if (unit_stripped_stem(candidate) == stem) return std::string(candidate);
  const size_t allowed = name.size() <= 2 ? 0 : name.size() <= 5 ? 1 : 2;
  std::optional<std::string> best;
  size_t best_distance = allowed + 1;
  for (std::string_view candidate : candidates) {
    const size_t distance = edit_distance(name, candidate);
    if (distance < best_distance) {
      best = std::string(candidate);
      best_distance = distance;
    }
  }
  return best;
}

}  // namespace

std::string did_you_mean(std::string_view name, const std::vector<std::string_view>& candidates) {
  const std::optional<std::string> suggestion = closest_name(name, candidates);
  return suggestion ? " (did you mean " + quoted(*suggestion) + "?)" : "";
}

}  // namespace railstab::scene_reading
