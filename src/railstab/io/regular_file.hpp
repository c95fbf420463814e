#pragma once
// Reading an input file that must be a regular file of bounded size.
//
// The file is opened without blocking and checked with fstat before a byte
// is read: a named pipe with no writer would otherwise hang the open, a
// device (/dev/zero) would never end, a folder reads as an error late.
#include <cstddef>
#include <string>

namespace railstab {

// Far above any scene (the largest case is ~20 kB); a bound so that a huge
// or endless input is refused instead of filling memory.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t(16) << 20;

// Returns the whole file. Throws std::runtime_error with a message without the
// path (the caller prefixes it), e.g. "expected a regular file, got a named
// pipe (not a regular file)".
std::string read_regular_file(const std::string& path, std::size_t max_bytes = kMaxInputFileBytes);

// `path` as named inside the file `file_path` (e.g. a profile in a scene):
// relative paths are taken from the file's folder; absolute ones are kept.
std::string path_relative_to_file(const std::string& file_path, const std::string& path);

}  // namespace railstab
