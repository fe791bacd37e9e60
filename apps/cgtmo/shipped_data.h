#pragma once
// The files cgtmo ships (the OCIO config and its LUTs), found from where the program is, never
// from the current folder.
#include <string>

namespace cgtmo::cli {

// The shipped config.ocio: <program's folder>/../share/cgtmo/ocio_config/config.ocio for an
// installed program (cmake --install, the Debian package), else the source tree's
// ocio_config/config.ocio for a program that runs from its build tree. "" when neither exists.
std::string shipped_config_path();

}  // namespace cgtmo::cli
