#pragma once
// Plan view of a mode shape, as engineers know it from multibody tools: each
// body drawn from above as a rectangle at its longitudinal place (car body,
// bogie frames, wheelset axles), displaced by its lateral motion y and yaw psi
// at several phases of the oscillation:
//   corner (x_b + dx, dy) -> (x_b + dx - a psi dy, dy + a y + a psi dx),
// y = Re(y_hat e^{i phase}), psi = Re(psi_hat e^{i phase}) (small yaw about
// the body's centre, z up, x forward), with one exaggeration factor a for the
// whole mode (so relative amplitudes are true) chosen so the largest
// lateral corner displacement is drawn as kDrawnAmplitude_m.
//
// Bodies carry no outline in the scene, so the rectangles follow the
// topology (stability/mode_names.hpp roles): a wheelset is an axle
// 2 x kAxleHalfLength_m across; a bogie frame spans its wheelsets plus
// kFrameOverhang_m; a car body spans every other body plus kCarOverhang_m.
#include <railstab/io/output_set.hpp>
#include <railstab/model/model.hpp>
#include <railstab/stability/mode_names.hpp>
#include <railstab/stability/mode_shape.hpp>
#include <railstab/stability/speed_analysis.hpp>

#include <array>
#include <string>
#include <vector>

namespace railstab {

inline constexpr double kDrawnAmplitude_m = 0.45;
// Below this share of kinetic energy in lateral, roll and yaw a mode is drawn
// at rest (its lateral motion is round-off of a vertical-plane mode).
inline constexpr double kMinDrawnLateralShare = 1e-6;
inline constexpr double kAxleHalfLength_m = 1.0;
inline constexpr double kFrameHalfWidth_m = 1.1, kFrameOverhang_m = 0.5;
inline constexpr double kCarHalfWidth_m = 1.45, kCarOverhang_m = 2.5;

struct BodyOutline {
  int body = 0;
  BodyRole role = BodyRole::car_body;
  double x_m = 0.0;                       // centre, longitudinal, vehicle frame
  double half_length_m = 0.0, half_width_m = 0.0;
};

// Outlines of the bodies that have a lateral or yaw coordinate.
std::vector<BodyOutline> plan_view_outlines(const Model& model, const BodyRoles& roles);

// Exaggeration factor a for `shape` (see above); 0 when nothing moves laterally.
double plan_view_exaggeration(const std::vector<BodyOutline>& outlines, const ModeShape& shape);

// The five corners (closed) of outline o displaced by the shape at `phase_rad`.
std::array<std::array<double, 2>, 5> displaced_outline(const BodyOutline& o, const ModeShape& shape,
                                                       double exaggeration, double phase_rad);

// Adds <stem>_mode<k>_<name>_<V>mps.png and .svg (`phases` panels) and
// ..._animated.gif (one period, 16 frames), plus the data and the gnuplot
// script, to `outputs` for each mode index in `modes` (into p.modes); runs
// gnuplot; returns the PNG names.
// `shapes`: one per p.modes (stability/point_mode_shapes.hpp full_mode_shapes).
std::vector<std::string> write_mode_plots(const Model& model, const StabilityPoint& p,
                                          const std::vector<ModeShape>& shapes,
                                          const std::vector<int>& modes, OutputSet& outputs,
                                          const std::string& stem, int phases = 4);

}  // namespace railstab
