// The critical (hunting) speed of a vehicle through the railstab library API
// only (no command-line code): read the scene and build the model with its
// static equilibrium (prepare_scene), then follow the least stable mode over
// a speed grid and bisect where its real part crosses zero
// (find_critical_speed).
//
//   critical_speed SCENE [FROM TO STEP]    speeds in m/s
//
// The defaults bracket the thesis vehicle's critical speed (cases/
// thesis_vehicle_tangent.toml: 111.46 m/s, README) with a short grid.
#include <railstab/setup/prepare_scene.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2 && argc != 5) {
    std::fprintf(stderr, "usage: %s SCENE [FROM TO STEP]  (speeds in m/s)\n", argv[0]);
    return 2;
  }
  try {
    const railstab::PreparedScene scene = railstab::prepare_scene(argv[1], {});
    railstab::CriticalSpeedOptions options;
    options.from_m_per_s = argc == 5 ? std::stod(argv[2]) : 100.0;
    options.to_m_per_s = argc == 5 ? std::stod(argv[3]) : 120.0;
    options.grid_step_m_per_s = argc == 5 ? std::stod(argv[4]) : 5.0;
    const railstab::CriticalSpeedResult r = railstab::find_critical_speed(
        scene.model, scene.equilibrium.state, scene.speed_m_per_s, options);
    if (!r.critical_speed_found) {
      std::printf("%s: no critical speed between %.2f and %.2f m/s\n", scene.model.name.c_str(),
                  options.from_m_per_s, options.to_m_per_s);
      return 1;
    }
    const railstab::ModeReport& mode = r.at_critical.modes[r.at_critical.least_stable];
    std::printf("%s: critical speed %.2f m/s (%.1f km/h), mode %s at %.3f Hz\n",
                scene.model.name.c_str(), r.critical_speed_m_per_s,
                3.6 * r.critical_speed_m_per_s, mode.name.c_str(), mode.frequency_hz);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "critical_speed: error: %s\n", e.what());
    return 1;
  }
}
