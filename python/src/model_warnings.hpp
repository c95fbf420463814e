#pragma once
// The model check's warnings of a prepared scene, as the commands print
// them on stderr before an analysis (src/cli/model_warnings.cpp): without
// the natural frequencies (an eigen-analysis at rest the analysis does not
// need). The Python layer raises them as railstab.ModelWarning.
#include <railstab/setup/prepare_scene.hpp>

#include <string>
#include <vector>

namespace railstab::python {

// Each warning's message, then each check error as "model check: ...";
// a check that fails itself gives one line "model check skipped: ...".
std::vector<std::string> model_warnings(const PreparedScene& scene);

}  // namespace railstab::python
