#pragma once
// Track centreline geometry and the moving track frame (thesis chapter 3, with
// ERRATA 1-5). Double only: a body's track frame depends on time through its
// arc length s(t) = s0 + V t, never on the state, so AD never flows through it.
//
// Frame T at arc length s: origin p_WT(s) on the centreline, orientation
// R_WT = A = Az(heading) Ay(grade) Ax(roll). The seed track has no grade
// (grade = 0) but the formulas keep it. Roll = -asin(cant / D) (cant > 0 raises
// the right rail, see scene/scene_spec.hpp).
#include <railstab/irregularity/track_irregularities.hpp>
#include <railstab/track/track_spec.hpp>

#include <Eigen/Dense>

#include <array>
#include <memory>
#include <vector>

namespace railstab {

// Geometry at one arc length, with first and second arc-length derivatives of
// the three frame angles (what a frame moving at speed V needs).
struct TrackGeometryPoint {
  double s_m = 0.0;
  Eigen::Vector3d p_WT_W = Eigen::Vector3d::Zero();  // centreline point in W
  double heading_rad = 0.0, grade_rad = 0.0, roll_rad = 0.0;
  double curvature_per_m = 0.0;        // d heading / ds
  double curvature_rate_per_m2 = 0.0;  // d2 heading / ds2
  double roll_rate_per_m = 0.0;        // d roll / ds
  double roll_rate2_per_m2 = 0.0;      // d2 roll / ds2
  double grade_rate_per_m = 0.0, grade_rate2_per_m2 = 0.0;
  double cant_m = 0.0;
  int segment = 0;  // index of the segment that contains s
};

// Where one rail is moved from its design position by the track
// irregularities, in the track frame T (m): +y left, +z up. Each rail is
// translated, not rotated (docs/irregular_track.md, "In the contact").
struct RailDisplacement {
  double lateral_m = 0.0, vertical_m = 0.0;
};

// Kinematics of a track frame moving along the track at speed V (and
// acceleration dV/dt).
struct TrackFrameKinematics {
  TrackGeometryPoint geometry;
  Eigen::Matrix3d R_WT = Eigen::Matrix3d::Identity();     // A
  Eigen::Vector3d v_WT_T = Eigen::Vector3d::Zero();       // origin velocity, in T
  Eigen::Vector3d a_WT_T = Eigen::Vector3d::Zero();       // origin acceleration, in T
  Eigen::Vector3d w_WT_T = Eigen::Vector3d::Zero();       // angular velocity of T, in T
  Eigen::Vector3d alpha_WT_T = Eigen::Vector3d::Zero();   // d/dt of w_WT_T components
  // The rails at this arc length: [0] left (side +1), [1] right (side -1);
  // zero on perfect track.
  std::array<RailDisplacement, 2> rails{};
  const RailDisplacement& rail(int side) const { return rails[side > 0 ? 0 : 1]; }
};

class Track {
 public:
  explicit Track(const TrackSpec& spec);

  TrackGeometryPoint geometry_at(double s_m) const;
  // The frame at arc length s moving at ds/dt = V with d2s/dt2 = dV/dt
  // (0: constant speed).
  TrackFrameKinematics frame_at(double s_m, double speed_m_per_s,
                                double speed_rate_m_per_s2 = 0.0) const;

  double length_m() const { return total_length_m_; }
  // The irregularities frame_at applies (null: perfect track). Built once
  // with the track and shared by its copies.
  const TrackIrregularities* irregularities() const { return irregularities_.get(); }
  // Where the constant-curvature, constant-cant stretch through s_m ends
  // (consecutive tangents or arcs with equal curvature and cant merge): the
  // limit of runs that must stay at one steady rolling/curving state. s_m
  // itself inside a clothoid or a cant ramp.
  double uniform_stretch_end_m(double s_m) const;
  const TrackSpec& spec() const { return spec_; }

 private:
  struct SegmentStart {
    double s_m, x_m, y_m, heading_rad, curvature_per_m, cant_m;
  };
  // How a segment evolves from its start: curvature and cant are linear in the
  // local arc length u = s - start.s_m (constant curvature on tangent and arc).
  // Clothoid positions are integrated in pieces of equal length; piece_xy_
  // holds the centreline (x, y) at each piece start, so one evaluation
  // integrates at most one piece.
  struct SegmentLaw {
    TrackSegmentKind kind;
    double length_m, end_curvature_per_m, end_cant_m;
    double piece_length_m;     // clothoid only
    int first_piece, piece_count;  // clothoid only: range in piece_xy_
  };

  void append_segment(int index, const TrackSegmentSpec& segment);
  int segment_containing(double s_m) const;
  // Arc length, position, heading, curvature and cant at local arc length u of
  // a segment: the one evaluation used both for queries and for chaining the
  // next segment's start, so joints are continuous by construction.
  SegmentStart state_at(int segment, double u_m) const;
  Eigen::Vector2d centreline_xy(int segment, double u_m) const;

  TrackSpec spec_;
  std::vector<SegmentStart> starts_;
  std::vector<SegmentLaw> laws_;
  std::vector<Eigen::Vector2d> piece_xy_;
  double total_length_m_ = 0.0;
  std::shared_ptr<const TrackIrregularities> irregularities_;
};

// A = Az(heading) Ay(grade) Ax(roll).
Eigen::Matrix3d track_rotation(double heading_rad, double grade_rad, double roll_rad);

}  // namespace railstab
