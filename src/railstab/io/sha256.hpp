#pragma once
// SHA-256 (FIPS 180-4) of bytes or of a file, as 64 lowercase hex digits:
// reports name the exact scene file they were computed from, checkable with
// `sha256sum scene.toml`. Written out (about 60 lines) rather than adding a
// crypto library for one digest.
#include <string>
#include <string_view>

namespace railstab {

std::string sha256_hex(std::string_view bytes);

// Throws std::runtime_error naming the file if it cannot be read.
std::string sha256_of_file(const std::string& path);

}  // namespace railstab
