#include "technique/DepthProgram.h"

namespace shadowmap {

namespace shaders {
extern const char nearest_vert[];
extern const char nearest_frag[];
} // namespace shaders

const DepthProgram& nearestDepthProgram() {
    static const DepthProgram program{"shadow depth", shaders::nearest_vert, shaders::nearest_frag};
    return program;
}

} // namespace shadowmap
