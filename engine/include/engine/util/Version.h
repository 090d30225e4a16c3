#pragma once
// The engine's version (CMake's PROJECT_VERSION, also the shared library's and the package's),
// as the tools print it for --version.
namespace engine {

const char* version();

} // namespace engine
