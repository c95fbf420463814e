#pragma once
// Runs the built railstab executable (RAILSTAB_EXE) in a given folder, with
// an optional PATH, and returns its exit status and combined output. No
// shell is involved, so hostile arguments reach railstab verbatim.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <csignal>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace railstab::test {

struct CliRun {
  int exit_code = -1;  // -1: killed by a signal
  std::string output;  // stdout and stderr
};

// A run longer than `timeout_s` is killed (exit_code -1, output notes it):
// a hang fails the test instead of stalling the suite.
inline CliRun run_railstab(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                           const std::string& path_env = "", int timeout_s = 120) {
  const std::filesystem::path log = cwd / ".railstab_cli_output.txt";
  std::vector<std::string> all = {RAILSTAB_EXE};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(cwd.c_str()) != 0) ::_exit(126);
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd < 0) ::_exit(126);
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    if (!path_env.empty()) ::setenv("PATH", path_env.c_str(), 1);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  int status = 0;
  bool killed = false;
  for (int waited_ms = 0;; waited_ms += 20) {
    if (::waitpid(pid, &status, WNOHANG) == pid) break;
    if (waited_ms > timeout_s * 1000 && !killed) {
      ::kill(pid, SIGKILL);
      killed = true;
    }
    ::usleep(20000);
  }
  CliRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log, std::ios::binary);
  run.output.assign(std::istreambuf_iterator<char>(in), {});
  std::filesystem::remove(log);
  if (killed) run.output += "\n[killed after " + std::to_string(timeout_s) + " s]";
  return run;
}

}  // namespace railstab::test
