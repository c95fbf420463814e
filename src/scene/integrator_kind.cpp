#include "scene/integrator_kind.hpp"

#include <stdexcept>

namespace railstab {

std::string integrator_name(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::cvode_bdf: return "cvode_bdf";
    case IntegratorKind::cvode_adams: return "cvode_adams";
    case IntegratorKind::arkode_erk: return "arkode_erk";
    case IntegratorKind::arkode_dirk: return "arkode_dirk";
    case IntegratorKind::arkode_imex: return "arkode_imex";
  }
  return "unknown";
}

const std::vector<IntegratorKind>& all_integrator_kinds() {
  static const std::vector<IntegratorKind> kinds = {
      IntegratorKind::cvode_bdf, IntegratorKind::cvode_adams, IntegratorKind::arkode_erk,
      IntegratorKind::arkode_dirk, IntegratorKind::arkode_imex};
  return kinds;
}

IntegratorKind parse_integrator_kind(const std::string& name) {
  std::string known;
  for (IntegratorKind k : all_integrator_kinds()) {
    if (integrator_name(k) == name) return k;
    known += (known.empty() ? "" : ", ") + integrator_name(k);
  }
  throw std::invalid_argument("unknown integrator '" + name + "' (known: " + known + ")");
}

}  // namespace railstab
