#pragma once
// Files of the tests: a shipped case by name, a file's text, a fresh
// temporary folder.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace railstab::test {

// cases/<name>.toml of the source tree.
inline std::string case_path(const std::string& name) {
  return std::string(RAILSTAB_CASES_DIR) + "/" + name + ".toml";
}

// The file's bytes ("" for a file that cannot be read).
inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// An empty folder <temp>/railstab_<prefix>_<name>_<pid>, made afresh.
inline std::filesystem::path fresh_dir(const std::string& prefix, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("railstab_" + prefix + "_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace railstab::test
