#include <railstab/core/version.hpp>

#ifndef RAILSTAB_VERSION
#error "RAILSTAB_VERSION is defined by CMakeLists.txt for this file"
#endif

namespace railstab {
const char* railstab_version() { return RAILSTAB_VERSION; }
}  // namespace railstab
