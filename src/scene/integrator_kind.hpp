#pragma once
// Which SUNDIALS integrator runs the time domain: a scene parameter
// ([simulation] integrator), so it lives with the scene description; the
// steppers are in src/integrate/.
#include <string>
#include <vector>

namespace railstab {

enum class IntegratorKind { cvode_bdf, cvode_adams, arkode_erk, arkode_dirk, arkode_imex };

std::string integrator_name(IntegratorKind kind);
// Inverse of integrator_name; throws std::invalid_argument listing the names.
IntegratorKind parse_integrator_kind(const std::string& name);
const std::vector<IntegratorKind>& all_integrator_kinds();

}  // namespace railstab
