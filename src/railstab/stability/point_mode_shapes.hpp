#pragma once
// The full shape of every mode of one stability point: displacements, kinetic
// and potential energy shares (stability/mode_shape.hpp). The potential
// shares need the suspension stiffness at the point's steady state (two AD
// Jacobians), so this is computed once by the analysis and handed to the
// writers, which only format it.
#include <railstab/model/model.hpp>
#include <railstab/stability/mode_shape.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <vector>

namespace railstab {

// Shapes of every mode of `p` with potential-energy shares (one stiffness
// evaluation at p's steady state), in the order of p.modes.
std::vector<ModeShape> full_mode_shapes(const Model& model, const StabilityPoint& p);

}  // namespace railstab
