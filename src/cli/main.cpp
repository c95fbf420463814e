// railstab: lateral stability of railway vehicles. Subcommands live in
// src/cli/*_command.cpp; this file only wires them and reports errors.
#include "cli/assess_command.hpp"
#include "cli/bifurcation_command.hpp"
#include "cli/check_command.hpp"
#include "cli/contact_geometry_command.hpp"
#include "cli/curving_command.hpp"
#include "cli/modes_command.hpp"
#include "cli/sensitivity_command.hpp"
#include "cli/simulate_command.hpp"
#include "cli/stability_commands.hpp"
#include "cli/study_command.hpp"
#include "cli/track_command.hpp"
#include "cli/verify_command.hpp"
#include "cli/work_precision_command.hpp"
#include <railstab/setup/model_error_context.hpp>

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"railstab: railway vehicle lateral stability (critical speed, eigen-analysis, "
               "nonlinear time domain)"};
  app.require_subcommand(1);
  railstab::register_simulate_command(app);
  railstab::register_stability_commands(app);
  railstab::register_study_commands(app);
  railstab::register_sensitivity_command(app);
  railstab::register_modes_command(app);
  railstab::register_verify_command(app);
  railstab::register_work_precision_command(app);
  railstab::register_contact_geometry_command(app);
  railstab::register_check_command(app);
  railstab::register_curving_command(app);
  railstab::register_bifurcation_command(app);
  railstab::register_track_command(app);
  railstab::register_assess_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    // CLI11's messages name the flag and the value ("--budget: expected a
    // finite number in (0, 86400] s, got \"nan\"", "Could not convert:
    // --step = abc"); say which command's --help lists the flags.
    std::string help = "railstab --help";
    for (const CLI::App* sub : app.get_subcommands()) help = "railstab " + sub->get_name() + " --help";
    std::cerr << "railstab: error: " << e.what() << "\n(the options are listed by `" << help
              << "`)\n";
    return e.get_exit_code();
  } catch (const std::exception& e) {
    // The analyses place their errors (setup/model_error_context.hpp); any
    // message that still opens with an internal function name gets words.
    std::cerr << "railstab: error: " << railstab::without_function_name(e.what()) << "\n";
    return 1;
  }
  return 0;
}
