#pragma once
// What every force element has: a name, the two bodies it joins and a point
// on each. Body 1 may be the track: the track frame of body 2 (it moves along
// the track at V and takes no reaction). The scene reader fills the names;
// the model builder resolves them into body indices.
#include <Eigen/Dense>

#include <string>

namespace railstab {

inline constexpr int kTrackBody = -1;  // body index of "the track frame of body 2"
inline const std::string kTrackBodyName = "track";

struct ElementEnds {
  std::string name;
  std::string body1_name, body2_name;  // body1 may be kTrackBodyName
  int body1 = kTrackBody;              // resolved by the model builder
  int body2 = 0;
  Eigen::Vector3d point1_m = Eigen::Vector3d::Zero();  // in body 1's attachment frame
  Eigen::Vector3d point2_m = Eigen::Vector3d::Zero();  // in body 2's attachment frame
};

}  // namespace railstab
