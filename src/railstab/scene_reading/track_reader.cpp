#include <railstab/scene_reading/track_reader.hpp>

#include <railstab/io/regular_file.hpp>
#include <railstab/irregularity/measured_irregularity_file.hpp>
#include <railstab/scene/physical_ranges.hpp>

#include <cmath>
#include <cstdint>

namespace railstab::scene_reading {

namespace {

const Choices<TrackSegmentKind> kSegmentKinds = choices_of(kTrackSegmentKindNames);
const Choices<double> kTurnSigns = {{"left", +1.0}, {"right", -1.0}};

double read_clothoid_end_curvature(const TableReader& segment) {
  const bool by_radius = segment.has("end_radius_m");
  const bool by_curvature = segment.has("end_curvature_per_m");
  if (by_radius == by_curvature)
    segment.fail_here(
        "exactly one of end_radius_m (with turn) and end_curvature_per_m for a clothoid",
        by_radius ? "both" : "neither");
  if (by_curvature) {
    segment.reject_if_present(
        "turn", "no turn with end_curvature_per_m (its sign is the direction: > 0 turns left)");
    return segment.number("end_curvature_per_m", "1/m");
  }
  const double radius = segment.number("end_radius_m", "m");
  if (!physical_ranges::curve_radius_m.contains(radius))
    segment.fail("end_radius_m",
                 range_text(physical_ranges::curve_radius_m) +
                     " (end_curvature_per_m = 0 ends a curve)",
                 format_number(radius));
  return segment.choice("turn", kTurnSigns) / radius;
}

void reject_clothoid_keys(const TableReader& segment, std::string_view kind) {
  for (std::string_view key : {"end_radius_m", "turn", "end_curvature_per_m"})
    segment.reject_if_present(
        key, "no " + std::string(key) + " on " + std::string(kind) +
                 " (only a clothoid sets its end curvature; an arc keeps the one it starts with)");
}

TrackSegmentSpec read_segment(const TableReader& segment, double start_curvature_per_m,
                              double start_cant_m) {
  TrackSegmentSpec spec;
  spec.kind = segment.choice("type", kSegmentKinds);
  spec.length_m = segment.number("length_m", "m");
  spec.end_cant_m = segment.number_or("end_cant_m", "m", start_cant_m);
  switch (spec.kind) {
    case TrackSegmentKind::tangent:
      reject_clothoid_keys(segment, "a tangent segment");
      // Curvature is continuous along the track: a tangent starts straight.
      if (start_curvature_per_m != 0.0)
        segment.fail("type",
                     "a segment that starts at the curvature the track has there (\"arc\" or "
                     "\"clothoid\"; a tangent needs start curvature 0: insert a clothoid before it)",
                     "\"tangent\" where the curvature is " + format_number(start_curvature_per_m) +
                         " 1/m");
      spec.end_curvature_per_m = 0.0;
      break;
    case TrackSegmentKind::arc:
      reject_clothoid_keys(segment, "an arc segment");
      spec.end_curvature_per_m = start_curvature_per_m;
      break;
    case TrackSegmentKind::clothoid:
      spec.end_curvature_per_m = read_clothoid_end_curvature(segment);
      break;
  }
  return spec;
}

const Choices<IrregularitySpectrum> kSpectra = choices_of(kIrregularitySpectrumNames);

// The synthesis keys: with `file` they do not apply.
constexpr std::string_view kSynthesisKeys[] = {"psd", "seed", "wavelength_min_m", "start_m", "length_m",
                                               "components"};

// [track.irregularities] from a measured file (`file = "..."`, resolved
// against the scene's folder; irregularity/measured_irregularity_file.hpp).
void read_measured(const TableReader& table, IrregularitySpec& spec) {
  for (std::string_view key : kSynthesisKeys)
    table.reject_if_present(key, "no synthesis key beside `file` (a measured record is used as it is)");
  const std::string path = path_relative_to_file(table.source(), table.text("file"));
  try {
    spec.measured = read_measured_irregularities(path);
  } catch (const IrregularityFileError& e) {
    throw SceneError(table.source() + ": " + table.path_of("file") + ": " + e.what());
  }
  spec.start_m = spec.measured->arc_length_m.front();
  spec.length_m = spec.measured->arc_length_m.back() - spec.start_m;
}

// [track.irregularities] (irregularity/irregularity_spec.hpp).
IrregularitySpec read_irregularities(const TableReader& table) {
  IrregularitySpec spec;
  if (table.has("file") && table.has("psd"))
    table.fail_here("either psd (synthesised) or file (measured)", "both");
  if (!table.has("file") && !table.has("psd"))
    table.fail("psd", "a spectrum (psd = \"erri_b176_low\", ...) or a measured file (file = \"track.csv\")",
               kMissingKey);
  if (table.has("file")) {
    read_measured(table, spec);
  } else {
    spec.spectrum = table.choice("psd", kSpectra);
    spec.seed = std::uint64_t(
        table.whole_number_or("seed", 0.0, 9007199254740992.0, double(spec.seed), "a whole number in [0, 2^53]"));
    spec.wavelength_min_m = table.number_or("wavelength_min_m", "m", spec.wavelength_min_m);
    spec.start_m = table.number_or("start_m", "m", spec.start_m);
    spec.length_m = table.number_or("length_m", "m", spec.length_m);
    spec.components = int(table.whole_number_or("components", 1.0, 100000.0, double(spec.components),
                                                 "a whole number of cosines in [1, 100000]"));
  }
  spec.wavelength_max_m = table.number_or("wavelength_max_m", "m", spec.wavelength_max_m);
  spec.sample_interval_m = table.number_or("sample_interval_m", "m", spec.sample_interval_m);
  spec.amplitude_scale = table.number_or("amplitude_scale", "", spec.amplitude_scale);
  spec.fade_in_m = table.number_or("fade_in_m", "m", spec.fade_in_m);
  spec.fade_out_m = table.number_or("fade_out_m", "m", spec.fade_out_m);
  if (!(spec.wavelength_min_m > 0.0 && spec.wavelength_min_m < spec.wavelength_max_m &&
        spec.wavelength_max_m <= 1000.0))
    table.fail("wavelength_max_m", "wavelength_min_m > 0 below wavelength_max_m <= 1000 m",
               format_number(spec.wavelength_min_m) + " to " + format_number(spec.wavelength_max_m) + " m");
  if (!(spec.sample_interval_m >= 0.01 && spec.sample_interval_m <= spec.wavelength_min_m / 4.0))
    table.fail("sample_interval_m", "[0.01 m, wavelength_min_m / 4] (four samples per shortest wave)",
               format_number(spec.sample_interval_m));
  if (!spec.measured && !(spec.length_m > 0.0 && spec.length_m <= 1e5))
    table.fail("length_m", "(0, 1e5] m", format_number(spec.length_m));
  if (!spec.measured && !(spec.length_m / spec.sample_interval_m * spec.components <= 4e9))
    table.fail("components", "length_m / sample_interval_m x components <= 4e9 (the synthesis work)",
               format_number(spec.length_m / spec.sample_interval_m * spec.components));
  if (!spec.measured && !(spec.start_m >= 0.0 && spec.start_m <= 1e7))
    table.fail("start_m", "[0, 1e7] m", format_number(spec.start_m));
  if (!(spec.amplitude_scale >= 0.0 && spec.amplitude_scale <= 10.0))
    table.fail("amplitude_scale", "[0, 10]", format_number(spec.amplitude_scale));
  if (!(spec.fade_in_m >= 0.0 && spec.fade_in_m <= spec.length_m))
    table.fail("fade_in_m", "[0, length_m] (the length of the irregular stretch)", format_number(spec.fade_in_m));
  if (!(spec.fade_out_m >= 0.0 && spec.fade_in_m + spec.fade_out_m <= spec.length_m))
    table.fail("fade_out_m", "[0, length_m - fade_in_m] (the length of the irregular stretch)", format_number(spec.fade_out_m));
  return spec;
}

}  // namespace

TrackSpec read_track(const TableReader& top) {
  const TableReader track = top.table(
      "track", {"start_x_m", "start_y_m", "start_z_m", "start_heading_rad", "start_curvature_per_m",
                "start_cant_m", "rail_contact_distance_m", "segments", "irregularities"});
  TrackSpec spec;
  spec.start_x_m = track.number_or("start_x_m", "m", spec.start_x_m);
  spec.start_y_m = track.number_or("start_y_m", "m", spec.start_y_m);
  spec.start_z_m = track.number_or("start_z_m", "m", spec.start_z_m);
  spec.start_heading_rad = track.number_or("start_heading_rad", "rad", spec.start_heading_rad);
  spec.start_curvature_per_m =
      track.number_or("start_curvature_per_m", "1/m", spec.start_curvature_per_m);
  spec.start_cant_m = track.number_or("start_cant_m", "m", spec.start_cant_m);
  spec.rail_contact_distance_m =
      track.number_or("rail_contact_distance_m", "m", spec.rail_contact_distance_m);
  double curvature = spec.start_curvature_per_m;
  double cant = spec.start_cant_m;
  for (const TableReader& segment : track.tables_in_array(
           "segments",
           {"type", "length_m", "end_cant_m", "end_radius_m", "turn", "end_curvature_per_m"})) {
    spec.segments.push_back(read_segment(segment, curvature, cant));
    curvature = spec.segments.back().end_curvature_per_m;
    cant = spec.segments.back().end_cant_m;
  }
  if (const std::optional<TableReader> irregularities = track.optional_table(
          "irregularities", {"psd", "file", "seed", "wavelength_min_m", "wavelength_max_m", "start_m",
                             "length_m", "sample_interval_m", "components", "amplitude_scale", "fade_in_m",
                             "fade_out_m"}))
    spec.irregularities = read_irregularities(*irregularities);
  return spec;
}

}  // namespace railstab::scene_reading
