#pragma once
// Where the commands find the repository's own data when the user names none: the validation
// cases of `luxgrid validate` and the photometric files of `luxgrid accuracy`. So that they work
// from any folder, a default is looked up beside the binary first (`<binary's folder>/..`, the
// repository when the binary sits in its build folder) and then in the source folder the binary
// was built from; a path the user gives is taken as given.
#include <filesystem>
#include <string>

namespace luxgrid::cli {

// `relative` (e.g. "cases") under the first of those roots that holds it; when none does,
// `relative` itself (so the error names what was looked for, relative to the current folder).
std::filesystem::path find_repository_path(const std::string& relative);

}  // namespace luxgrid::cli
