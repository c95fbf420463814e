#include <railstab/report/mode_shape_report.hpp>

#include <railstab/report/markdown_text.hpp>
#include <railstab/stability/modes.hpp>

#include <cmath>
#include <iomanip>

namespace railstab {

namespace {

constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;

// Phase in degrees in (-180, 180]; 0 for a zero amplitude (no meaningful phase).
double phase_deg(std::complex<double> z) { return std::abs(z) > 0.0 ? std::arg(z) * kDegPerRad : 0.0; }

}  // namespace

void write_mode_shape_json(JsonWriter& j, const Model& model, const ModeShape& shape) {
  j.begin_object();
  if (shape.reference >= 0)
    j.field("normalised_to", coordinate_label(model, shape.coordinates[size_t(shape.reference)]));
  else
    j.key("normalised_to").null();
  j.field("units",
          "amplitude: translations in m, rotations in rad, per unit amplitude of the reference "
          "coordinate (phase 0); phase in degrees");
  j.field("potential_energy_defined", shape.potential_defined);
  j.key("coordinates").begin_array();
  for (const CoordinateMotion& c : shape.coordinates) {
    j.begin_object()
        .field("body", model.bodies[size_t(c.body)].name)
        .field("coordinate", coordinate_word(c.coordinate))
        .field("amplitude", std::abs(c.displacement))
        .field("phase_deg", phase_deg(c.displacement))
        .field("kinetic_energy_share", c.kinetic_share);
    if (shape.potential_defined)
      j.field("potential_energy_share", c.potential_share);
    else
      j.key("potential_energy_share").null();
    j.end_object();
  }
  j.end_array().end_object();
}

void write_mode_shape_markdown(std::ostream& md, const Model& model, const ModeShape& shape,
                               double min_share) {
  double amax = 0.0, tmax = 0.0, vmax = 0.0;
  for (const CoordinateMotion& c : shape.coordinates) {
    amax = std::max(amax, std::abs(c.displacement));
    tmax = std::max(tmax, c.kinetic_share);
    vmax = std::max(vmax, std::abs(c.potential_share));
  }
  md << "Mode shape (normalised to "
     << (shape.reference >= 0 ? md_text(coordinate_label(model, shape.coordinates[size_t(shape.reference)]))
                              : std::string("nothing: no coordinate moves"))
     << " = 1; translations in m, rotations in rad; energy shares of the mode's kinetic and "
        "potential energy):\n\n"
     << "| body | coordinate | amplitude | phase [deg] | kinetic share | potential share |\n"
     << "|---|---|---|---|---|---|\n"
     << std::setprecision(3);
  for (const CoordinateMotion& c : shape.coordinates) {
    const bool moves = std::abs(c.displacement) >= min_share * amax ||
                       c.kinetic_share >= min_share * tmax ||
                       (shape.potential_defined && std::abs(c.potential_share) >= min_share * vmax);
    if (!moves) continue;
    md << "| " << md_text(model.bodies[size_t(c.body)].name) << " | " << coordinate_word(c.coordinate)
       << " | " << std::abs(c.displacement) << " | " << std::fixed << std::setprecision(1)
       << phase_deg(c.displacement) << std::defaultfloat << std::setprecision(3) << " | "
       << c.kinetic_share << " | ";
    if (shape.potential_defined)
      md << c.potential_share;
    else
      md << "-";
    md << " |\n";
  }
  md << "\nKinetic share: m_i |u_i|^2 over the sum (u the rates). Potential share: the "
        "coordinate's part Re(conj(q_i) (K q)_i) of q^H K q, K the stiffness of the suspension "
        "and gravity without the wheel-rail contact (creep forces have no potential); it is "
        "negative where a spring's other end moves further the same way than the coordinate. "
        "Both sum to 1.";
  if (!shape.potential_defined)
    md << " Here no suspension is deflected by the mode: potential shares undefined (-).";
  md << "\n\n";
}

}  // namespace railstab
