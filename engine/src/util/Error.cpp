#include "engine/util/Error.h"

namespace engine {

InputError::~InputError() = default;

} // namespace engine
