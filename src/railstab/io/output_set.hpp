#pragma once
// All-or-nothing outputs of one command run.
//
// Every file of a run is first written into a staging folder inside the
// output folder (".railstab-staging-XXXXXX", same file system, so renames are
// atomic). commit() then moves the whole set into place: old files of the
// same names (and the run's other names declared with replaces(), e.g. plots
// of an earlier run made with plots) are first moved aside, the new files
// renamed in, and only when every rename succeeded are the old ones deleted;
// if one rename fails, the old set is restored. Destroying an uncommitted
// set (an exception half-way, gnuplot failing) removes the staging folder,
// so a failing run leaves the output folder as it was (and removes the
// output folder too if this run created it). Only a killed process leaves a
// hidden staging folder behind.
//
// Names inside the output folder must be single safe components
// (is_safe_file_name; build them with file_stem). A file the user placed
// elsewhere (--csv PATH) is staged beside its destination under a hidden
// temporary name and committed with the rest.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace railstab {

class OutputSet {
 public:
  explicit OutputSet(const std::filesystem::path& out_dir);
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // Declares `file_name` (one safe component) in the output folder as part of
  // the set; returns where to write it now (inside the staging folder).
  std::filesystem::path add(const std::string& file_name);
  // The same for a file at a path of the user's choice.
  std::filesystem::path add_at(const std::filesystem::path& destination);
  // add() or add_at(), then writes the file through `write` (the stream is
  // checked after it); returns the staged path.
  std::filesystem::path write(const std::string& file_name,
                              const std::function<void(std::ostream&)>& write);
  std::filesystem::path write_at(const std::filesystem::path& destination,
                                 const std::function<void(std::ostream&)>& write);
  // A name this kind of run may write, removed at commit if this run did not
  // write it, so old and new outputs never mix.
  void replaces(const std::string& file_name);

  const std::filesystem::path& staging_dir() const { return staging_; }
  const std::filesystem::path& out_dir() const { return out_dir_; }
  // Final path of a file added under `file_name`.
  std::filesystem::path final_path(const std::string& file_name) const;

  // Moves the set into place (see above); returns the final paths in the
  // order the files were added. Throws (leaving the old set in place) if a
  // staged file is missing or a destination cannot be replaced.
  std::vector<std::string> commit();

 private:
  struct Entry {
    std::filesystem::path staged, destination, backup;
    bool moved_aside = false, moved_in = false;
  };
  Entry& stage(const std::filesystem::path& staged, const std::filesystem::path& destination);
  void roll_back(std::vector<Entry>& entries);
  void discard() noexcept;

  std::filesystem::path out_dir_, staging_;
  std::filesystem::path created_root_;  // topmost folder this set created, if any
  std::vector<Entry> entries_;
  std::vector<std::string> replaced_names_;
  bool committed_ = false;
  int counter_ = 0;
};

}  // namespace railstab
