#pragma once
// Where raylab-import is: beside the running executable (an install puts them in one folder), or
// in the build tree's src/import seen from src/cli, src/bench, src/viewer or tests/<area>. The
// environment variable RAYLAB_IMPORT_HELPER, when set, names it instead.

#include <string>

namespace raylab {

// The helper's absolute path, or an empty string with `error` (one line) when none is found.
std::string findImportHelper(std::string& error);

} // namespace raylab
