#include <railstab/report/eigen_report.hpp>

#include <railstab/io/file_names.hpp>
#include <railstab/io/json_writer.hpp>
#include <railstab/report/mode_shape_report.hpp>
#include <railstab/report/run_conditions.hpp>

#include <iomanip>
#include <stdexcept>

namespace railstab {

void write_eigen_json(const Model& model, const StabilityPoint& p,
                      const std::vector<ModeShape>& shapes, OutputSet& outputs,
                      const std::string& stem) {
  if (shapes.size() != p.modes.size())
    throw std::invalid_argument("write_eigen_json: " + std::to_string(shapes.size()) +
                                " mode shapes for " + std::to_string(p.modes.size()) + " modes");
  outputs.write(stem + "_eigen_" + speed_file_tag(p.speed_m_per_s) + ".json",
                [&](std::ostream& out) {
    JsonWriter j(out);
    j.begin_object().field("scene", model.name).field("speed_m_per_s", p.speed_m_per_s);
    write_conditions_json(j, run_conditions(model), {p.speed_m_per_s});
    j.field("eigen_solver", eigen_solver_name(p.solver_used)).field("states", int(p.linear.states()));
    j.key("removed_cyclic_states").begin_array();
    for (const std::string& r : p.linear.removed_states) j.value(r);
    j.end_array().key("modes").begin_array();
    for (size_t i = 0; i < p.modes.size(); ++i) {
      const ModeReport& m = p.modes[i];
      j.begin_object()
          .field("eigenvalue_real_per_s", m.eigenvalue.real())
          .field("eigenvalue_imag_per_s", m.eigenvalue.imag())
          .field("frequency_Hz", m.frequency_hz)
          .field("damping_ratio", m.damping_ratio)
          .field("neutral", m.neutral)
          .field("residual", m.residual)
          .field("name", m.name);
      j.key("shape");
      write_mode_shape_json(j, model, shapes[i]);
      j.end_object();
    }
    j.end_array().end_object();
  });
}

void print_eigen_summary(std::ostream& out, const Model& model, const StabilityPoint& p,
                         double max_frequency_hz) {
  out << model.name << " at " << p.speed_m_per_s << " m/s: " << p.linear.states() << " states";
  if (!p.linear.removed_states.empty()) {
    out << " (removed cyclic:";
    for (const std::string& r : p.linear.removed_states) out << ' ' << r;
    out << ")";
  }
  out << ", " << p.modes.size() << " eigenvalues (" << eigen_solver_name(p.solver_used)
      << ") in " << p.seconds << " s\n";
  out << "  real [1/s]     freq [Hz]   damping    residual   mode\n";
  for (const ModeReport& m : p.modes) {
    if (m.eigenvalue.imag() < 0.0 || m.frequency_hz > max_frequency_hz) continue;
    out << "  " << std::setw(12) << m.eigenvalue.real() << std::setw(12) << m.frequency_hz
        << std::setw(11) << m.damping_ratio << std::setw(12) << m.residual << "   " << m.name
        << "\n";
  }
}

}  // namespace railstab
