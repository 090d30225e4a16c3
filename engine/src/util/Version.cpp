#include "engine/util/Version.h"

namespace engine {

const char* version() { return ENGINE_VERSION; }

} // namespace engine
