#pragma once
// The speed-ramp outputs of `simulate --ramp-rate` (nonlinear/speed_ramp.hpp):
// <stem>_ramp.json, <stem>_ramp_envelope.csv and <stem>_ramp.md, one entry
// per rate, and the terminal summary. Every one says that the hunting end
// speed depends on the rate (and the start), and gives the spread between
// the rates when there are two or more.
#include <railstab/model/model.hpp>
#include <railstab/nonlinear/speed_ramp.hpp>
#include <railstab/report/simulation_report.hpp>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace railstab {

// The one sentence on the rate dependence, in every output.
extern const char* const kRampRateDependenceNote;

// Largest minus smallest hunting end speed over the ramps that vanished,
// when two or more did.
std::optional<double> hunting_end_speed_spread(const std::vector<SpeedRampResult>& ramps);

std::string speed_ramp_json(const Model& model, const std::vector<SpeedRampResult>& ramps,
                            const RunStart& start);
void write_speed_ramp_envelope_csv(std::ostream& out, const std::vector<SpeedRampResult>& ramps);
std::string speed_ramp_markdown(const Model& model, const std::vector<SpeedRampResult>& ramps,
                                const RunStart& start);
void print_speed_ramp_summary(std::ostream& out, const std::vector<SpeedRampResult>& ramps);

}  // namespace railstab
