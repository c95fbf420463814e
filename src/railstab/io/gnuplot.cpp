#include <railstab/io/gnuplot.hpp>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace railstab {

std::string gnuplot_text(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (c == '\'') out += "''";
    else if (u < 0x20 || u == 0x7F) out += ' ';
    else out += c;
  }
  return out + "'";
}

std::string gnuplot_path(const std::string& path) {
  for (char c : path) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7F)
      throw GnuplotError("cannot pass the path \"" + gnuplot_text(path) +
                         "\" to gnuplot: it holds a control character");
  }
  return gnuplot_text(path);
}

std::string find_gnuplot() {
  const char* path_env = std::getenv("PATH");
  const std::string path = path_env ? path_env : "/usr/bin:/bin";
  size_t start = 0;
  while (start <= path.size()) {
    const size_t end = std::min(path.find(':', start), path.size());
    const std::string dir = end > start ? path.substr(start, end - start) : ".";
    const std::string candidate = dir + "/gnuplot";
    struct stat st {};
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
    start = end + 1;
  }
  return "";
}

void require_gnuplot() {
  if (find_gnuplot().empty())
    throw GnuplotError(
        "gnuplot is not on PATH, so the plots cannot be made: install gnuplot (Debian package "
        "gnuplot-nox) or pass --no-plots");
}

void run_gnuplot(const std::filesystem::path& script, const std::filesystem::path& working_dir,
                 const std::vector<std::string>& expected_outputs,
                 const std::map<std::string, std::string>& variables) {
  const std::string script_text = script.string();
  std::vector<std::string> args = {"gnuplot"};
  for (const auto& [name, value] : variables) {
    args.push_back("-e");
    args.push_back(name + "=" + gnuplot_path(value));
  }
  args.push_back(script_text);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  // glibc >= 2.29: the child changes directory, the parent's stays put.
  posix_spawn_file_actions_addchdir_np(&actions, working_dir.c_str());
  // No terminal input: a script can never wait for a key press (pause -1).
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  pid_t pid = 0;
  const int spawn_error = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawn_error == ENOENT)
    throw GnuplotError("gnuplot is not on PATH, so " + script_text +
                       " was not run: install gnuplot or pass --no-plots");
  if (spawn_error != 0)
    throw GnuplotError("cannot start gnuplot on " + script_text + ": " +
                       std::strerror(spawn_error));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR)
      throw GnuplotError("waiting for gnuplot on " + script_text + ": " + std::strerror(errno));
  }
  if (WIFSIGNALED(status))
    throw GnuplotError("gnuplot was killed by signal " + std::to_string(WTERMSIG(status)) +
                       " on " + script_text);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
    throw GnuplotError("gnuplot could not be started in " + working_dir.string() + " on " +
                       script_text + " (exit status 127)");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw GnuplotError("gnuplot failed (exit status " + std::to_string(WEXITSTATUS(status)) +
                       ") on " + script_text + "; its messages are above");
  for (const std::string& name : expected_outputs) {
    const std::filesystem::path plot = working_dir / name;
    std::error_code ec;
    const auto size = std::filesystem::file_size(plot, ec);
    if (ec || size == 0)
      throw GnuplotError("gnuplot ran " + script_text + " but did not make " + name +
                         (ec ? " (no such file)" : " (empty file)"));
  }
}

}  // namespace railstab
