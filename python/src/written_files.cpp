#include "written_files.hpp"

#include <pybind11/stl.h>

#include <railstab/io/regular_file.hpp>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace railstab::python {

namespace fs = std::filesystem;

namespace {

// A fresh folder of this process alone (mkdtemp: created with mode 0700, its
// name unique even among threads), removed by the destructor.
class TemporaryFolder {
 public:
  TemporaryFolder() {
    std::string pattern = (fs::temp_directory_path() / "railstab-python-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throw std::runtime_error("cannot create a temporary folder under " +
                               fs::temp_directory_path().string() +
                               " for the analysis's outputs (set TMPDIR to a writable folder)");
    path_ = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

const std::string& WrittenFiles::ending_with(const std::string& suffix) const {
  const std::string* found = nullptr;
  std::string names;
  for (const auto& [name, contents] : text) {
    names += (names.empty() ? "" : ", ") + name;
    if (name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
      if (found) throw std::logic_error("railstab Python module: two outputs end with " + suffix + ": " + names);
      found = &contents;
    }
  }
  if (!found)
    throw std::logic_error("railstab Python module: no output ends with " + suffix + " (written: " +
                           names + ")");
  return *found;
}

WrittenFiles write_and_read(const std::function<void(OutputSet&)>& write) {
  TemporaryFolder folder;
  const fs::path out = folder.path() / "out";
  {
    OutputSet outputs(out);
    write(outputs);
    outputs.commit();
  }
  WrittenFiles files;
  for (const fs::directory_entry& e : fs::directory_iterator(out))
    if (e.is_regular_file())
      files.text[e.path().filename().string()] =
          read_regular_file(e.path().string(), std::size_t(1) << 31);
  return files;
}

pybind11::dict files_by_key(const WrittenFiles& files,
                            const std::vector<std::pair<const char*, const char*>>& key_suffixes,
                            const std::vector<std::string>& model_warnings) {
  pybind11::dict out;
  for (const auto& [key, suffix] : key_suffixes) out[key] = files.ending_with(suffix);
  out["model_warnings"] = pybind11::cast(model_warnings);
  return out;
}

}  // namespace railstab::python
