// Eigenvalues of a vehicle at one speed through the railstab library API
// only: read the scene and build the model with its static equilibrium
// (prepare_scene), then the steady state at the speed, its exact
// linearisation and every eigenvalue (SpeedStability::at), the same point
// `railstab eigen SCENE --speed V` reports.
//
//   eigen_at_speed SCENE SPEED    speed in m/s
//
// Prints the lateral-plane oscillatory modes up to 20 Hz and the least
// damped of them (the mode that becomes hunting as the speed rises).
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s SCENE SPEED  (m/s)\n", argv[0]);
    return 2;
  }
  try {
    const railstab::PreparedScene scene = railstab::prepare_scene(argv[1], {});
    const double speed_m_per_s = std::stod(argv[2]);
    railstab::SpeedStability stability(scene.model, scene.equilibrium.state,
                                       scene.speed_m_per_s);
    const railstab::StabilityPoint p = stability.at(speed_m_per_s);
    std::printf("%s at %.2f m/s: %d states, %zu eigenvalues\n", scene.model.name.c_str(),
                p.speed_m_per_s, int(p.linear.states()), p.modes.size());
    std::printf("  real [1/s]  freq [Hz]  damping ratio  mode (lateral plane)\n");
    for (const railstab::ModeReport& m : p.modes) {
      if (m.neutral || m.eigenvalue.imag() <= 0.0 || m.frequency_hz > 20.0) continue;
      if (m.lateral_share < 0.5) continue;
      std::printf("  %10.4f %10.4f %14.5f  %s\n", m.eigenvalue.real(), m.frequency_hz,
                  m.damping_ratio, m.name.c_str());
    }
    if (p.least_damped < 0) {
      std::printf("no lateral-plane mode\n");
      return 1;
    }
    const railstab::ModeReport& m = p.modes[size_t(p.least_damped)];
    std::printf("least damped lateral: %.4f 1/s at %.4f Hz, %s\n", m.eigenvalue.real(),
                m.frequency_hz, m.name.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "eigen_at_speed: error: %s\n", e.what());
    return 1;
  }
}
