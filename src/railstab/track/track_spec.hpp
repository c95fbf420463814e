#pragma once
// The track as a scene describes it ([track], [[track.segments]];
// conventions: scene/scene_spec.hpp).
#include <railstab/core/name_table.hpp>
#include <railstab/irregularity/irregularity_spec.hpp>

#include <optional>

#include <string_view>
#include <vector>

namespace railstab {

// --- Track --------------------------------------------------------------------
enum class TrackSegmentKind { tangent, clothoid, arc };
// A segment's `type` in scene files and messages.
inline constexpr NameTable<TrackSegmentKind, 3> kTrackSegmentKindNames = {{
    {"tangent", TrackSegmentKind::tangent},
    {"clothoid", TrackSegmentKind::clothoid},
    {"arc", TrackSegmentKind::arc}}};
constexpr std::string_view track_segment_kind_name(TrackSegmentKind kind) {
  return name_in(kTrackSegmentKindNames, kind);
}

// A segment starts where the previous one ends (position, heading, curvature,
// cant), so continuity holds by construction. Curvature varies linearly over a
// clothoid and is constant on tangent (zero) and arc (= start curvature).
// Cant varies linearly over every segment from its start to `end_cant_m`.
struct TrackSegmentSpec {
  TrackSegmentKind kind = TrackSegmentKind::tangent;
  double length_m = 0.0;
  double end_curvature_per_m = 0.0;  // clothoid only; tangent 0, arc = start
  double end_cant_m = 0.0;
};

struct TrackSpec {
  double start_x_m = 0.0;
  double start_y_m = 0.0;
  double start_z_m = 0.0;
  double start_heading_rad = 0.0;
  double start_curvature_per_m = 0.0;
  double start_cant_m = 0.0;
  double rail_contact_distance_m = 1.5;  // D in phi = asin(cant / D) (ERRATA 2)
  std::vector<TrackSegmentSpec> segments;
  // [track.irregularities]; none: perfect track.
  std::optional<IrregularitySpec> irregularities;
};

}  // namespace railstab
