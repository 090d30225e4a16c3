#include "technique/lookup/HardwareCompareLookup.h"

namespace shadowmap {

namespace shaders {
extern const char hardwareCompare_glsl[];
} // namespace shaders

const char* HardwareCompareLookup::glsl() const { return shaders::hardwareCompare_glsl; }

} // namespace shadowmap
