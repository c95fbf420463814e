#pragma once
// Index of a state by its report name (Model::state_name, e.g.
// "wheelset1.y_m", "bogie1.yaw_rad/s", "yd_series.damper_elongation_m"); a
// name the model does not have fails the test and gives 0.
#include <railstab/model/model.hpp>

#include <gtest/gtest.h>

#include <string>

namespace railstab::test {

inline int state_index(const Model& model, const std::string& name) {
  for (int i = 0; i < model.state_size(); ++i)
    if (model.state_name(i) == name) return i;
  ADD_FAILURE() << "no state " << name;
  return 0;
}

}  // namespace railstab::test
