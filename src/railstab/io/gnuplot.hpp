#pragma once
// Running gnuplot without a shell, and text that is safe inside its scripts.
//
// gnuplot is started with posix_spawnp("gnuplot", {"gnuplot", [-e VAR=..],
// script}) in a given working directory: no shell ever parses a path or a
// name, so quotes, spaces, `;` or `$( )` in a scene name or in --out run
// nothing. Inside the script, user text goes in single-quoted strings, where
// gnuplot does no backquote or macro substitution and '' stands for '.
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace railstab {

// gnuplot could not run or did not make every promised plot.
class GnuplotError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `text` as a gnuplot single-quoted string literal (with the quotes), for
// titles and labels: ' doubled, control characters (which would end the
// command) shown as spaces.
std::string gnuplot_text(const std::string& text);

// A file path as a gnuplot single-quoted string literal; throws GnuplotError
// if the path holds a control character (it cannot be written in a script).
std::string gnuplot_path(const std::string& path);

// The path of an executable `gnuplot` on PATH, empty if none.
std::string find_gnuplot();

// Throws GnuplotError with advice ("install gnuplot or pass --no-plots")
// when gnuplot is not on PATH: checked before a long computation.
void require_gnuplot();

// Runs `gnuplot script` in `working_dir` (relative paths in the script
// resolve there), first setting each variable of `variables` to a string
// (-e "name='value'"). Waits for it, then checks that every file in
// `expected_outputs` (relative to working_dir) exists and is non-empty.
// Throws GnuplotError naming the script and the cause (not found, exit
// status, signal, missing plot); gnuplot's own messages go to stderr.
void run_gnuplot(const std::filesystem::path& script, const std::filesystem::path& working_dir,
                 const std::vector<std::string>& expected_outputs,
                 const std::map<std::string, std::string>& variables = {});

}  // namespace railstab
