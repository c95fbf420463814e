#pragma once
// An analysis's files, written by the command line's own writers (report/)
// into a private temporary folder and read back as text: the Python module
// returns the same JSON fields as the files because the same code renders
// them, and a change to a report reaches both at once. The folder is removed
// whatever happens (the writers' OutputSet is all-or-nothing, so a failing
// writer leaves nothing half-written to read).
#include <railstab/io/output_set.hpp>

#include <pybind11/pybind11.h>

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace railstab::python {

struct WrittenFiles {
  std::map<std::string, std::string> text;  // file name -> contents
  // The one file whose name ends with `suffix` (e.g. "_critical_speed.json");
  // throws std::logic_error naming the files there are when there is not
  // exactly one (a writer renamed its output: a bug of this module).
  const std::string& ending_with(const std::string& suffix) const;
};

WrittenFiles write_and_read(const std::function<void(OutputSet&)>& write);

// What a binding returns of them: for each (key, suffix) the file ending
// with that suffix, and the model check's warnings under "model_warnings".
pybind11::dict files_by_key(const WrittenFiles& files,
                            const std::vector<std::pair<const char*, const char*>>& key_suffixes,
                            const std::vector<std::string>& model_warnings);

}  // namespace railstab::python
