#include <railstab/report/model_check_report.hpp>

#include <railstab/io/json_writer.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace railstab {

namespace {

double max_axle_load(const ModelCheckReport& r) {
  double m = 0.0;
  for (const AxleLoad& a : r.axle_loads) m = std::max(m, a.total_N);
  return m;
}

// A load as the mass it carries (t), "-" without gravity (no finite mass).
std::string tonnes(double load_N, const ModelCheckReport& r) {
  if (!(r.gravity_m_per_s2 > 0.0)) return "-";
  std::ostringstream s;
  s << std::setprecision(6) << load_N / r.gravity_m_per_s2 / 1e3;
  return s.str();
}

}  // namespace

void write_model_check_markdown(std::ostream& out, const ModelCheckReport& r) {
  out << std::setprecision(6);
  out << "# Model check: " << r.scene << "\n\n";
  if (!r.errors.empty()) {
    out << "## Errors\n\n";
    for (const std::string& e : r.errors) out << "- " << e << "\n";
    out << "\n";
  }
  out << "## Warnings\n\n";
  if (r.warnings.empty()) out << "None.\n";
  for (const ModelWarning& w : r.warnings) out << "- **" << w.kind << "**: " << w.message << "\n";
  out << "\n## Masses\n\n| body | role | mass [kg] |\n|---|---|---|\n";
  for (const BodyCheck& b : r.bodies)
    out << "| " << b.name << " | " << b.role << " | " << b.mass_kg << " |\n";
  out << "| total | | " << r.total_mass_kg << " |\n\nWeight " << r.total_mass_kg * r.gravity_m_per_s2
      << " N (g = " << r.gravity_m_per_s2 << " m/s^2).\n\n";
  out << "## Axle loads\n\n";
  if (r.axle_loads.empty()) {
    out << "None (no equilibrium, or no wheelsets).\n\n";
  } else {
    out << "At the equilibrium at " << r.speed_m_per_s
        << " m/s; wheel load = the rail's total force on the wheel along the track normal.\n\n"
        << "| wheelset | left [kN] | right [kN] | axle [kN] | axle [t] |\n|---|---|---|---|---|\n";
    for (const AxleLoad& a : r.axle_loads)
      out << "| " << a.wheelset << " | " << a.left_N / 1e3 << " | " << a.right_N / 1e3 << " | "
          << a.total_N / 1e3 << " | " << tonnes(a.total_N, r) << " |\n";
    out << "| sum | | | " << r.axle_load_sum_N / 1e3 << " | "
        << tonnes(r.axle_load_sum_N, r) << " |\n\n";
  }
  out << "## Static deflections under the preloads\n\n";
  if (r.static_deflections.empty()) {
    out << "None (no preloaded spring).\n\n";
  } else {
    out << "Deflection = preload / stiffness (the stiffness at the nominal configuration), "
           "per element and axis of body 1's frame.\n\n"
        << "| element | type | axis | preload [N, N m] | stiffness [N/m, N m/rad] | "
           "deflection |\n|---|---|---|---|---|---|\n";
    for (const SpringDeflection& d : r.static_deflections)
      out << "| " << d.element << " | " << d.type << " | " << d.axis << " | " << d.preload
          << " | " << d.stiffness << " | " << d.deflection << " " << d.unit << " |\n";
    out << "\n";
  }
  out << "## Natural frequencies at rest\n\n";
  if (!r.natural_frequency_note.empty()) out << r.natural_frequency_note << "\n\n";
  if (!r.natural_frequencies.empty()) {
    out << "Eigenvalues of the model linearised about its equilibrium at "
        << r.natural_frequency_speed_m_per_s
        << " m/s: the creep forces (~ 1/V) then hold the wheels on the rails laterally as "
           "friction holds a standing vehicle, and the suspension modes remain (damped "
           "frequencies; the kinematic modes, whose frequency goes with the speed, are left "
           "out).\n\n"
        << "| frequency [Hz] | damping ratio | mode |\n|---|---|---|\n";
    for (const NaturalFrequency& f : r.natural_frequencies)
      out << "| " << f.frequency_hz << " | " << f.damping_ratio << " | " << f.name << " |\n";
  }
}

void write_model_check_json(std::ostream& out, const ModelCheckReport& r) {
  JsonWriter j(out);
  j.begin_object().field("scene", r.scene).field("speed_m_per_s", r.speed_m_per_s);
  j.key("errors").begin_array();
  for (const std::string& e : r.errors) j.value(e);
  j.end_array().key("warnings").begin_array();
  for (const ModelWarning& w : r.warnings)
    j.begin_object()
        .field("kind", w.kind)
        .field("subject", w.subject)
        .field("message", w.message)
        .end_object();
  j.end_array().key("bodies").begin_array();
  for (const BodyCheck& b : r.bodies)
    j.begin_object().field("name", b.name).field("role", b.role).field("mass_kg", b.mass_kg).end_object();
  j.end_array().field("total_mass_kg", r.total_mass_kg);
  j.key("axle_loads").begin_array();
  for (const AxleLoad& a : r.axle_loads)
    j.begin_object()
        .field("wheelset", a.wheelset)
        .field("left_N", a.left_N)
        .field("right_N", a.right_N)
        .field("total_N", a.total_N)
        .end_object();
  j.end_array().field("axle_load_sum_N", r.axle_load_sum_N);
  j.key("static_deflections").begin_array();
  for (const SpringDeflection& d : r.static_deflections)
    j.begin_object()
        .field("element", d.element)
        .field("type", d.type)
        .field("axis", d.axis)
        .field("preload", d.preload)
        .field("stiffness", d.stiffness)
        .field("deflection", d.deflection)
        .field("unit", d.unit)
        .end_object();
  j.end_array().field("natural_frequency_speed_m_per_s", r.natural_frequency_speed_m_per_s);
  j.key("natural_frequencies").begin_array();
  for (const NaturalFrequency& f : r.natural_frequencies)
    j.begin_object()
        .field("frequency_Hz", f.frequency_hz)
        .field("damping_ratio", f.damping_ratio)
        .field("name", f.name)
        .end_object();
  j.end_array().field("natural_frequency_note", r.natural_frequency_note).end_object();
}

void print_model_check_summary(std::ostream& out, const ModelCheckReport& r) {
  out << std::setprecision(6) << r.scene << ": " << r.bodies.size() << " bodies, total mass "
      << r.total_mass_kg << " kg";
  if (!r.axle_loads.empty())
    out << ", " << r.axle_loads.size() << " axles, axle loads up to " << max_axle_load(r) / 1e3
        << " kN (sum " << r.axle_load_sum_N / 1e3 << " kN, weight "
        << r.total_mass_kg * r.gravity_m_per_s2 / 1e3 << " kN)";
  out << "\n";
  if (!r.static_deflections.empty()) {
    const SpringDeflection& most = *std::max_element(
        r.static_deflections.begin(), r.static_deflections.end(),
        [](const SpringDeflection& a, const SpringDeflection& b) {
          return std::abs(a.deflection) < std::abs(b.deflection);
        });
    out << "largest static deflection under a preload: " << std::abs(most.deflection) << " "
        << most.unit << " (" << most.element << " " << most.axis << ")\n";
  }
  if (!r.natural_frequencies.empty()) {
    out << "lowest natural frequencies at rest:";
    for (size_t i = 0; i < r.natural_frequencies.size() && i < 5; ++i)
      out << (i ? ", " : " ") << r.natural_frequencies[i].frequency_hz << " Hz ("
          << r.natural_frequencies[i].name << ")";
    out << "\n";
  } else if (!r.natural_frequency_note.empty()) {
    out << r.natural_frequency_note << "\n";
  }
  out << r.warnings.size() << " warning(s), " << r.errors.size() << " error(s)\n";
  for (const ModelWarning& w : r.warnings) out << "warning: " << w.message << "\n";
  for (const std::string& e : r.errors) out << "error: " << e << "\n";
}

void print_model_warnings(std::ostream& out, const ModelCheckReport& r) {
  for (const ModelWarning& w : r.warnings) out << "warning: " << w.message << "\n";
  for (const std::string& e : r.errors) out << "model check: " << e << "\n";
  if (!r.warnings.empty() || !r.errors.empty())
    out << "(`railstab check SCENE` reports every model check)\n";
}

}  // namespace railstab
