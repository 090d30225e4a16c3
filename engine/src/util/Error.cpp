#include "engine/util/Error.h"

namespace engine {

InputError::~InputError() = default;
PluginError::~PluginError() = default;

} // namespace engine
