#pragma once
#include <CLI/CLI.hpp>

namespace railstab {
// `railstab work-precision SCENE [--speed V] [--t-end T] [--out DIR] [--budget S]
//  [--integrators a,b] [--no-plots]`: every integrator over a ladder of
// tolerances against a tight CVODE reference; CSV, Markdown table and a
// log-log error-vs-CPU-time plot.
void register_work_precision_command(CLI::App& app);
}  // namespace railstab
