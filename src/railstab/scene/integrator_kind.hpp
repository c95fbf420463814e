#pragma once
// Which SUNDIALS integrator runs the time domain: a scene parameter
// ([simulation] integrator), so it lives with the scene description; the
// steppers are in src/railstab/integrate/.
#include <string>
#include <vector>

namespace railstab {

enum class IntegratorKind { cvode_bdf, cvode_adams, arkode_erk, arkode_dirk, arkode_imex };

std::string integrator_name(IntegratorKind kind);
// Inverse of integrator_name; throws std::invalid_argument listing the names.
IntegratorKind parse_integrator_kind(const std::string& name);
const std::vector<IntegratorKind>& all_integrator_kinds();

// Orders the method offers (SUNDIALS 6.4): CVODE BDF 1-5 and Adams 1-12 (the
// maximum order); ARKODE's default tables ERK 2-6 and 8, DIRK 2-5, IMEX 3-5.
// 0 always means the method's default.
std::vector<int> available_orders(IntegratorKind kind);
bool order_available(IntegratorKind kind, int order);
// "2, 3, 4, 5" for messages.
std::string available_orders_text(IntegratorKind kind);

}  // namespace railstab
