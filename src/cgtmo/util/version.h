#pragma once
// The library's version (the CMake project version), as the CLI prints it and outputs record it.
namespace cgtmo {
const char* version();
}  // namespace cgtmo
