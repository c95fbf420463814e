#pragma once
// A value from the text of a JSON output, without a JSON parser: enough for
// the command-line tests, which compare a few numbers and names.
#include <regex>
#include <string>

namespace railstab::test {

// The text after the first `"key": ` up to the next comma or newline
// ("<missing>" when the key does not occur).
inline std::string json_value(const std::string& json, const std::string& key) {
  const std::regex re("\"" + key + "\": ([^,\\n]*)");
  std::smatch m;
  if (!std::regex_search(json, m, re)) return "<missing>";
  return m[1].str();
}

}  // namespace railstab::test
