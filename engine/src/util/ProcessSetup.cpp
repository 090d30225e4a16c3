#include "engine/util/ProcessSetup.h"

#include <malloc.h>

namespace engine {

void tuneAllocatorForRendering() {
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
}

} // namespace engine
