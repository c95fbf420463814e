#pragma once
// Track irregularities as a scene gives them ([track.irregularities];
// docs/irregular_track.md): synthesised from a published PSD with a seed and
// a wavelength band, or read from a measured file.
#include <railstab/core/name_table.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace railstab {

// The four channels, each a function of the arc length s (m):
//   alignment   lateral position of the track centreline, +y (left);
//   level       vertical position of the track centreline, +z (up);
//   cross_level height of the left rail over the right one, z_left - z_right;
//   gauge       gauge deviation from nominal (> 0 wider).
// Rails: y_left = alignment + gauge/2, y_right = alignment - gauge/2,
//        z_left = level + cross_level/2, z_right = level - cross_level/2.
enum class IrregularityChannel { alignment, level, cross_level, gauge };
inline constexpr int kIrregularityChannels = 4;
inline constexpr NameTable<IrregularityChannel, 4> kIrregularityChannelNames = {{
    {"alignment", IrregularityChannel::alignment},
    {"level", IrregularityChannel::level},
    {"cross_level", IrregularityChannel::cross_level},
    {"gauge", IrregularityChannel::gauge}}};

// The published spectra (irregularity/irregularity_psd.hpp).
enum class IrregularitySpectrum { erri_b176_low, erri_b176_high, fra_class_4, fra_class_5, fra_class_6 };
inline constexpr NameTable<IrregularitySpectrum, 5> kIrregularitySpectrumNames = {{
    {"erri_b176_low", IrregularitySpectrum::erri_b176_low},
    {"erri_b176_high", IrregularitySpectrum::erri_b176_high},
    {"fra_class_4", IrregularitySpectrum::fra_class_4},
    {"fra_class_5", IrregularitySpectrum::fra_class_5},
    {"fra_class_6", IrregularitySpectrum::fra_class_6}}};

// A measured record (irregularity/measured_irregularity_file.hpp), in metres
// along the track's arc length. A channel the file does not hold is zero.
struct MeasuredIrregularities {
  std::string path;                  // the file, resolved against the scene's folder
  std::vector<double> arc_length_m;  // strictly increasing
  std::array<std::vector<double>, kIrregularityChannels> channels_m;  // each as long as arc_length_m
  std::array<bool, kIrregularityChannels> in_file{};
};

struct IrregularitySpec {
  // Set: the channels come from this file (`file = ...`), and the synthesis
  // keys (spectrum, seed, band, start, length, components) do not apply.
  std::optional<MeasuredIrregularities> measured;
  IrregularitySpectrum spectrum = IrregularitySpectrum::erri_b176_low;
  std::uint64_t seed = 1;
  // The band synthesised: EN 13848-1's D1-D3 wavelength ranges, 3-150 m.
  double wavelength_min_m = 3.0, wavelength_max_m = 150.0;
  double start_m = 0.0;             // arc length where the irregularities begin
  double length_m = 1000.0;         // how far they run (zero beyond)
  double sample_interval_m = 0.25;  // grid the channels are sampled on, then splined
  int components = 2000;            // cosines per channel
  double amplitude_scale = 1.0;     // multiplies every channel
  // Lengths over which the channels ramp in from zero where they begin and
  // back to zero where they end (smooth (1 - cos) ramps), so a run meets no
  // step at either end.
  double fade_in_m = 10.0;
  double fade_out_m = 10.0;
};

}  // namespace railstab
