#pragma once
#include <string>
#include <vector>

namespace railstab {

// Runs `gnuplot SCRIPT` without a shell (fork + execvp, the path passed as
// one argument), waits for it, and checks that every expected output file
// exists and is not empty. Throws std::runtime_error naming the script.
void run_gnuplot_script(const std::string& script_path,
                        const std::vector<std::string>& expected_outputs);

}  // namespace railstab
