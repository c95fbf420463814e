#include <railstab/io/output_set.hpp>

#include <railstab/io/file_names.hpp>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace railstab {

namespace fs = std::filesystem;

namespace {

bool exists_no_follow(const fs::path& p) {
  std::error_code ec;
  return fs::exists(fs::symlink_status(p, ec));
}

}  // namespace

OutputSet::OutputSet(const fs::path& out_dir) : out_dir_(out_dir.empty() ? fs::path(".") : out_dir) {
  std::error_code ec;
  if (exists_no_follow(out_dir_) && !fs::is_directory(out_dir_, ec))
    throw std::runtime_error("output folder " + out_dir_.string() +
                             ": expected a folder, got a file of another kind (--out)");
  // Remember the topmost folder this run creates, to remove it again if the
  // run fails (the output folder is then as it was: absent).
  for (fs::path p = fs::absolute(out_dir_).lexically_normal(); !p.empty() && !exists_no_follow(p);
       p = p.parent_path()) {
    created_root_ = p;
    if (p == p.parent_path()) break;
  }
  fs::create_directories(out_dir_, ec);
  if (ec)
    throw std::runtime_error("cannot create the output folder " + out_dir_.string() + " (--out): " +
                             ec.message());
  std::string pattern = (out_dir_ / ".railstab-staging-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    const std::string why = std::strerror(errno);
    discard();
    throw std::runtime_error("cannot write in the output folder " + out_dir_.string() +
                             " (--out): " + why);
  }
  staging_ = pattern;
}

OutputSet::~OutputSet() {
  if (!committed_) discard();
}

void OutputSet::discard() noexcept {
  std::error_code ec;
  for (const Entry& e : entries_)
    if (e.staged.parent_path() != staging_) fs::remove(e.staged, ec);
  if (!staging_.empty()) fs::remove_all(staging_, ec);
  if (!created_root_.empty()) {
    // Only empty folders go: fs::remove refuses a non-empty one.
    const fs::path root = created_root_;
    for (fs::path p = fs::absolute(out_dir_).lexically_normal();; p = p.parent_path()) {
      if (!fs::remove(p, ec) || p == root || p == p.parent_path()) break;
    }
  }
}

OutputSet::Entry& OutputSet::stage(const fs::path& staged, const fs::path& destination) {
  for (const Entry& e : entries_)
    if (e.destination == destination)
      throw std::logic_error("output " + destination.string() + " added twice");
  Entry e;
  e.staged = staged;
  e.destination = destination;
  entries_.push_back(e);
  return entries_.back();
}

fs::path OutputSet::add(const std::string& file_name) {
  if (!is_safe_file_name(file_name))
    throw std::invalid_argument("output file name \"" + file_name +
                                "\" is not a single safe name ([A-Za-z0-9._-], not starting "
                                "with '.')");
  Entry& e = stage(staging_ / file_name, out_dir_ / file_name);
  e.backup = staging_ / "old" / file_name;
  return e.staged;
}

fs::path OutputSet::add_at(const fs::path& destination) {
  const fs::path dir = destination.has_parent_path() ? destination.parent_path() : fs::path(".");
  if (!destination.has_filename())
    throw std::invalid_argument("output path " + destination.string() + " names no file");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create the folder of " + destination.string() + ": " + ec.message());
  const std::string tag = "." + destination.filename().string() + ".railstab-" +
                          std::to_string(::getpid()) + "-" + std::to_string(counter_++);
  Entry& e = stage(dir / (tag + ".tmp"), destination);
  e.backup = dir / (tag + ".old");
  return e.staged;
}

namespace {

fs::path write_file(const fs::path& path, const fs::path& shown_as,
                    const std::function<void(std::ostream&)>& write) {
  std::ofstream out(path, std::ios::binary);
  if (!out)
    throw std::runtime_error("cannot write " + shown_as.string() + ": " + std::strerror(errno));
  write(out);
  out.flush();
  if (!out) throw std::runtime_error("error while writing " + shown_as.string());
  return path;
}

}  // namespace

fs::path OutputSet::write(const std::string& file_name,
                          const std::function<void(std::ostream&)>& writer) {
  return write_file(add(file_name), final_path(file_name), writer);
}

fs::path OutputSet::write_at(const fs::path& destination,
                             const std::function<void(std::ostream&)>& writer) {
  return write_file(add_at(destination), destination, writer);
}

void OutputSet::replaces(const std::string& file_name) {
  if (!is_safe_file_name(file_name))
    throw std::invalid_argument("output file name \"" + file_name + "\" is not safe");
  replaced_names_.push_back(file_name);
}

fs::path OutputSet::final_path(const std::string& file_name) const { return out_dir_ / file_name; }

void OutputSet::roll_back(std::vector<Entry>& entries) {
  std::error_code ec;
  for (auto it = entries.rbegin(); it != entries.rend(); ++it) {
    if (it->moved_in) fs::rename(it->destination, it->staged, ec);
    if (it->moved_aside) fs::rename(it->backup, it->destination, ec);
    it->moved_in = it->moved_aside = false;
  }
}

std::vector<std::string> OutputSet::commit() {
  if (committed_) throw std::logic_error("output set committed twice");
  // Old files of this run's other names: moved aside with the rest, then
  // deleted, so the folder never holds a mix of two runs.
  std::vector<Entry> all = entries_;
  for (const std::string& name : replaced_names_) {
    bool written = false;
    for (const Entry& e : entries_) written = written || e.destination == out_dir_ / name;
    if (!written) all.push_back(Entry{{}, out_dir_ / name, staging_ / "old" / name});
  }
  std::error_code ec;
  for (const Entry& e : all) {
    if (!e.staged.empty() && !fs::is_regular_file(e.staged, ec))
      throw std::logic_error("output " + e.destination.string() + " was declared but not written");
    if (fs::is_directory(fs::symlink_status(e.destination, ec)))
      throw std::runtime_error("cannot write " + e.destination.string() +
                               ": a folder of that name is in the way");
  }
  fs::create_directories(staging_ / "old", ec);
  try {
    for (Entry& e : all)
      if (exists_no_follow(e.destination)) {
        fs::rename(e.destination, e.backup);
        e.moved_aside = true;
      }
    for (Entry& e : all)
      if (!e.staged.empty()) {
        fs::rename(e.staged, e.destination);
        e.moved_in = true;
      }
  } catch (const fs::filesystem_error& error) {
    roll_back(all);
    throw std::runtime_error(std::string("outputs not written (the previous ones are kept): ") +
                             error.what());
  }
  committed_ = true;
  for (const Entry& e : all) fs::remove(e.backup, ec);
  fs::remove_all(staging_, ec);
  std::vector<std::string> written;
  for (const Entry& e : entries_) written.push_back(e.destination.string());
  return written;
}

}  // namespace railstab
