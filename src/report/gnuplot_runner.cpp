#include "report/gnuplot_runner.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace railstab {

void run_gnuplot_script(const std::string& script_path,
                        const std::vector<std::string>& expected_outputs) {
  for (const std::string& out : expected_outputs) {
    std::error_code ec;
    std::filesystem::remove(out, ec);  // a stale file must not pass the check below
  }
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(std::string("cannot start gnuplot: ") + std::strerror(errno));
  if (pid == 0) {
    std::string program = "gnuplot";
    std::string script = script_path;
    char* argv[] = {program.data(), script.data(), nullptr};
    execvp(argv[0], argv);
    _exit(127);  // exec failed: gnuplot not installed
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error("waiting for gnuplot failed on " + script_path);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("gnuplot failed on " + script_path +
                             (WIFEXITED(status) && WEXITSTATUS(status) == 127
                                  ? " (is gnuplot installed?)"
                                  : " (exit status " + std::to_string(WEXITSTATUS(status)) + ")"));
  for (const std::string& out : expected_outputs) {
    std::error_code ec;
    if (!std::filesystem::exists(out, ec) || std::filesystem::file_size(out, ec) == 0)
      throw std::runtime_error("gnuplot ran " + script_path + " but did not write " + out);
  }
}

}  // namespace railstab
