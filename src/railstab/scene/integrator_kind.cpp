#include <railstab/scene/integrator_kind.hpp>

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

std::vector<int> available_orders(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::cvode_bdf: return {1, 2, 3, 4, 5};
    case IntegratorKind::cvode_adams: return {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    case IntegratorKind::arkode_erk: return {2, 3, 4, 5, 6, 8};
    case IntegratorKind::arkode_dirk: return {2, 3, 4, 5};
    case IntegratorKind::arkode_imex: return {3, 4, 5};
  }
  return {};
}

bool order_available(IntegratorKind kind, int order) {
  if (order == 0) return true;
  for (int q : available_orders(kind))
    if (q == order) return true;
  return false;
}

std::string available_orders_text(IntegratorKind kind) {
  std::string text;
  for (int q : available_orders(kind)) text += (text.empty() ? "" : ", ") + std::to_string(q);
  return text;
}

}  // namespace railstab
