// libFuzzer harness: scene reader + model build (issue 10).
//
// Every input is a scene file. The contract under test: whatever the bytes,
// railstab either builds a model (preloads solved, the model evaluated at its
// nominal state) or throws an exception whose message starts with the file
// name ("fuzz.toml: ..."), i.e. says where the problem is. A crash, a
// sanitizer report, a hang (libFuzzer -timeout), an escaping exception that
// does not name the file, or a message that begins with an internal function
// name ("hertz_shape: ...") is a finding: the harness aborts.
//
// Built only with clang (CMake option RAILSTAB_SANITIZE, scripts/sanitize.sh);
// seed corpus: cases/*.toml.
#include <railstab/equilibrium/equilibrium.hpp>
#include <railstab/scene_reading/load_scene.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/setup/build_model.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace {

const std::string kSource = "fuzz.toml";

[[noreturn]] void finding(const char* what, const std::string& message) {
  std::fprintf(stderr, "FUZZ FINDING (%s): %s\n", what, message.c_str());
  std::abort();
}

// The internal function names that used to open messages (issue 10).
const char* const kInternalNames[] = {
    "hertz_shape:", "eigen_dense:", "eigen_arpack_shift_invert:", "kalker_coefficients:",
    "kalker_table:", "combine_materials:", "modal_assurance:", "assemble_model:",
    "solve_equilibrium:", "scene_reading:", "make_contact_table:", "make_profile_pair:"};

// `input`: the scene text (a name the fuzzer copied into it may be quoted back).
void check_message(const std::string& message, const std::string& input) {
  if (message.rfind(kSource + ":", 0) != 0)
    finding("error does not name the file", message);
  for (const char* name : kInternalNames)
    if (message.find(name) != std::string::npos && input.find(name) == std::string::npos)
      finding("error is a bare internal function name", message);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 64 * 1024) return 0;  // scene files are a few kB
  const std::string text(reinterpret_cast<const char*>(data), size);
  using namespace railstab;
  SceneSpec spec;
  try {
    spec = load_scene_text(text, kSource);
  } catch (const SceneError& e) {
    check_message(e.what(), text);
    return 0;
  } catch (const std::exception& e) {
    finding("scene reader threw a non-SceneError", e.what());
  }
  // Bound the work per input (the equilibrium Jacobian is O(states^2)):
  // larger scenes are valid but too slow to fuzz.
  if (spec.bodies.size() > 10 || spec.elements.size() > 60 || spec.track.segments.size() > 50)
    return 0;
  try {
    const Model model = build_model(spec);
    const double V = spec.speed_m_per_s;
    const Eigen::VectorXd x = lowered_nominal_state(model, V);
    (void)rhs(model, V, 0.0, x);
  } catch (const std::bad_alloc&) {
    finding("out of memory", "");
  } catch (const std::exception& e) {
    check_message(e.what(), text);
  }
  return 0;
}
