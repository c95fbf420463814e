#include <railstab/report/mode_plot.hpp>

#include <railstab/io/file_names.hpp>
#include <railstab/io/gnuplot.hpp>
#include <railstab/report/mode_shape_report.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace railstab {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kAnimationFrames = 16;

double body_x(const Body& b) { return b.track_offset_m + b.nominal_q(0); }

bool moves_in_plan(const Body& b) { return b.state_index[1] >= 0 || b.state_index[5] >= 0; }

// y_hat and psi_hat of a body in the shape (0 where frozen).
std::array<std::complex<double>, 2> lateral_and_yaw(const ModeShape& shape, int body) {
  std::array<std::complex<double>, 2> r{};
  for (const CoordinateMotion& c : shape.coordinates)
    if (c.body == body && c.coordinate == 1) r[0] = c.displacement;
    else if (c.body == body && c.coordinate == 5) r[1] = c.displacement;
  return r;
}

}  // namespace

std::vector<BodyOutline> plan_view_outlines(const Model& model, const BodyRoles& roles) {
  std::vector<BodyOutline> out;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (!moves_in_plan(body)) continue;
    BodyOutline o;
    o.body = int(b);
    o.role = roles.role[b];
    o.x_m = body_x(body);
    switch (o.role) {
      case BodyRole::wheelset:
        o.half_length_m = 0.08;
        o.half_width_m = kAxleHalfLength_m;
        break;
      case BodyRole::bogie_frame: {
        double reach = 1.0;
        for (size_t w = 0; w < model.bodies.size(); ++w)
          if (w != b && roles.unit[w] == int(b))
            reach = std::max(reach, std::abs(body_x(model.bodies[w]) - o.x_m));
        o.half_length_m = reach + kFrameOverhang_m;
        o.half_width_m = kFrameHalfWidth_m;
        break;
      }
      case BodyRole::car_body: {
        double reach = 2.0;
        for (size_t w = 0; w < model.bodies.size(); ++w)
          if (roles.role[w] != BodyRole::car_body)
            reach = std::max(reach, std::abs(body_x(model.bodies[w]) - o.x_m));
        o.half_length_m = reach + kCarOverhang_m;
        o.half_width_m = kCarHalfWidth_m;
        break;
      }
    }
    out.push_back(o);
  }
  return out;
}

double plan_view_exaggeration(const std::vector<BodyOutline>& outlines, const ModeShape& shape) {
  double largest = 0.0;
  for (const BodyOutline& o : outlines) {
    const auto [y, psi] = lateral_and_yaw(shape, o.body);
    largest = std::max(largest, std::abs(y) + std::abs(psi) * o.half_length_m);
  }
  return largest > 0.0 ? kDrawnAmplitude_m / largest : 0.0;
}

std::array<std::array<double, 2>, 5> displaced_outline(const BodyOutline& o, const ModeShape& shape,
                                                       double exaggeration, double phase_rad) {
  const auto [y_hat, psi_hat] = lateral_and_yaw(shape, o.body);
  const std::complex<double> turn = std::polar(1.0, phase_rad);
  const double y = exaggeration * (y_hat * turn).real();
  const double psi = exaggeration * (psi_hat * turn).real();
  const double sx[5] = {1, -1, -1, 1, 1}, sy[5] = {1, 1, -1, -1, 1};
  std::array<std::array<double, 2>, 5> corners;
  for (int k = 0; k < 5; ++k) {
    const double dx = sx[k] * o.half_length_m, dy = sy[k] * o.half_width_m;
    corners[size_t(k)] = {o.x_m + dx - psi * dy, dy + y + psi * dx};
  }
  return corners;
}

std::vector<std::string> write_mode_plots(const Model& model, const StabilityPoint& p,
                                          const std::vector<ModeShape>& shapes,
                                          const std::vector<int>& modes, OutputSet& outputs,
                                          const std::string& stem, int phases) {
  if (shapes.size() != p.modes.size())
    throw std::invalid_argument("write_mode_plots: " + std::to_string(shapes.size()) +
                                " mode shapes for " + std::to_string(p.modes.size()) + " modes");
  const BodyRoles roles = body_roles(model);
  const std::vector<BodyOutline> outlines = plan_view_outlines(model, roles);
  double x_lo = 0.0, x_hi = 0.0;
  for (const BodyOutline& o : outlines) {
    x_lo = std::min(x_lo, o.x_m - o.half_length_m);
    x_hi = std::max(x_hi, o.x_m + o.half_length_m);
  }
  const double y_half = kCarHalfWidth_m + kDrawnAmplitude_m + 0.4;
  std::vector<std::string> pngs, expected;
  const std::string script = stem + "_modes_" + speed_file_tag(p.speed_m_per_s) + ".gp";
  std::ostringstream gp;
  gp << "# Plan views of mode shapes; run from the output folder: gnuplot " << script << "\n"
     << std::setprecision(8);
  int k = 0;
  for (const int index : modes) {
    const ModeReport& m = p.modes[size_t(index)];
    const ModeShape& shape = shapes[size_t(index)];
    ++k;
    const std::string base = stem + "_mode" + std::to_string(k) + "_" + file_stem(m.name) + "_" +
                             speed_file_tag(p.speed_m_per_s);
    const std::string data = base + ".dat";
    // A mode without lateral-plane motion (bounce, pitch) is drawn at rest:
    // its round-off lateral motion must not be blown up to full size.
    const bool lateral = m.lateral_share >= kMinDrawnLateralShare;
    const double a = lateral ? plan_view_exaggeration(outlines, shape) : 0.0;
    outputs.write(data, [&](std::ostream& out) {
      out << std::setprecision(10)
          << "# x_m y_m role(0 wheelset, 1 bogie frame, 2 car body); one index per phase, "
             "first the rest position\n";
      // Index 0: rest; 1..phases: the panels; then the animation frames.
      for (int ph = -1; ph < phases + kAnimationFrames; ++ph) {
        const double phase = ph < phases ? 2.0 * kPi * ph / phases
                                         : 2.0 * kPi * (ph - phases) / kAnimationFrames;
        for (const BodyOutline& o : outlines) {
          const auto corners = ph < 0 ? displaced_outline(o, shape, 0.0, 0.0)
                                      : displaced_outline(o, shape, a, phase);
          for (const auto& c : corners)
            out << c[0] << ' ' << c[1] << ' ' << int(o.role) << '\n';
          out << '\n';
        }
        out << '\n';
      }
    });
    std::ostringstream title, note;
    title << model.name << ": " << m.name << ", " << std::setprecision(4) << m.frequency_hz
          << " Hz, damping ratio " << m.damping_ratio << ", at " << p.speed_m_per_s << " m/s";
    note << "plan view from above; ";
    if (lateral)
      note << "lateral and yaw scaled so the largest corner moves " << kDrawnAmplitude_m
           << " m; grey dashed: rest";
    else
      note << "no lateral or yaw motion: the mode moves out of this plane";
    // A short unit (a bogie: about as long as wide) in a 2 x 2 grid of
    // panels, a long one (a car) one panel per row: either way the panels
    // are drawn to scale (ratio -1) at a readable size, the note said once.
    const bool grid = (x_hi - x_lo + 1.0) < 3.0 * (2.0 * y_half);
    const int columns = grid ? 2 : 1, rows = (phases + columns - 1) / columns;
    const int height = grid ? 90 + 400 * rows : 110 + 190 * rows;
    for (const char* ext : {".png", ".svg"}) {
      const std::string file = base + ext;
      gp << (ext == std::string(".png")
                 ? "set terminal pngcairo size 1100,"
                 : "set terminal svg dynamic size 1100,")
         << height << " font 'Sans,10' noenhanced\n"
         << "set output " << gnuplot_text(file) << "\n"
         << "set multiplot layout " << rows << "," << columns << " title "
         << gnuplot_text(title.str()) << ".\"\\n\"." << gnuplot_text(note.str()) << "\n"
         << "set xrange [" << x_hi + 0.5 << ":" << x_lo - 0.5 << "]\n"  // forward to the left
         << "set yrange [" << -y_half << ":" << y_half << "]\nset size ratio -1\nunset key\n"
         << "set xlabel 'x [m], forward to the left'\nset ylabel 'y [m]'\nset grid\n";
      for (int ph = 0; ph < phases; ++ph)
        gp << "set title 'phase " << 360 * ph / phases << " deg'\n"
           << "plot " << gnuplot_path(data) << " index 0 using 1:2 with lines lc rgb '#b0b0b0' "
           << "dt 2, '' index " << ph + 1 << " using 1:2:($3==0 ? 0xd62728 : $3==1 ? 0x2ca02c "
           << ": 0x1f77b4) with lines lw 2 lc rgb variable\n";
      gp << "unset multiplot\nunset output\n";
      expected.push_back(file);
    }
    // One period as an animated GIF (libgd terminal), one frame per phase step.
    const std::string gif = base + "_animated.gif";
    gp << "set terminal gif animate delay " << 160 / kAnimationFrames << " loop 0 size 1100,360 "
       << "noenhanced\nset output " << gnuplot_text(gif) << "\nset size noratio\nset size ratio -1\n"
       << "set title " << gnuplot_text(title.str()) << "\nset xlabel " << gnuplot_text(note.str())
       << "\ndo for [f=0:" << kAnimationFrames - 1 << "] {\n  plot " << gnuplot_path(data)
       << " index 0 using 1:2 with lines lc rgb '#b0b0b0' dt 2, '' index (" << phases + 1
       << " + f) using 1:2:($3==0 ? 0xd62728 : $3==1 ? 0x2ca02c : 0x1f77b4) with lines lw 2 lc "
          "rgb variable\n}\nunset output\n";
    expected.push_back(gif);
    pngs.push_back(base + ".png");
  }
  outputs.write(script, [&](std::ostream& out) { out << gp.str(); });
  for (const std::string& f : expected) outputs.add(f);
  if (!modes.empty()) run_gnuplot(script, outputs.staging_dir(), expected);
  return pngs;
}

}  // namespace railstab
