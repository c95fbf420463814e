#pragma once
// railstab's version (CMakeLists.txt project(VERSION)), stated in reports.
namespace railstab {
const char* railstab_version();
}  // namespace railstab
