#pragma once
// The leading wheelset of a model: the wheelset furthest ahead, i.e. with
// the largest track_offset_m (the first in body order among equals). Its
// lateral shift is the signal of limit-cycle amplitudes (error estimate,
// speed ramp) and the scale of a start on a mode (stability/mode_start.hpp).
#include <railstab/model/model.hpp>

namespace railstab {

// Index into model.bodies, or -1 when the model has no wheelset.
inline int leading_wheelset(const Model& model) {
  int lead = -1;
  for (size_t b = 0; b < model.bodies.size(); ++b)
    if (model.bodies[b].wheelset() &&
        (lead < 0 || model.bodies[b].track_offset_m > model.bodies[size_t(lead)].track_offset_m))
      lead = int(b);
  return lead;
}

// Its lateral shift's index in the state, or -1 (no wheelset, or y frozen).
inline int leading_wheelset_lateral_state(const Model& model) {
  const int lead = leading_wheelset(model);
  return lead < 0 ? -1 : model.bodies[size_t(lead)].state_index[int(CoordinateIndex::y)];
}

}  // namespace railstab
