#pragma once
// The model check (check/model_check.hpp) as a Markdown report, a JSON file
// and text for the terminal: the summary of `railstab check` and the
// warnings every command prints before it starts.
#include <railstab/check/model_check.hpp>

#include <ostream>

namespace railstab {

void write_model_check_markdown(std::ostream& out, const ModelCheckReport& r);
void write_model_check_json(std::ostream& out, const ModelCheckReport& r);

// Mass, axle loads, the lowest natural frequencies, the deflection range and
// every warning and error, one line each.
void print_model_check_summary(std::ostream& out, const ModelCheckReport& r);

// "warning: <message>" per warning and "error: <message>" per error (nothing
// for a clean model), and where the full report comes from.
void print_model_warnings(std::ostream& out, const ModelCheckReport& r);

}  // namespace railstab
