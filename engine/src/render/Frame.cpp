#include "engine/render/Frame.h"

#include "engine/util/Error.h"

namespace engine {

void Frame::setLightVisibility(LightVisibilityHook hook) {
    if (visibility_)
        throw InputError("plugins \"" + visibility_->owner + "\" and \"" + hook.owner +
                         "\" both shade lights; load only one of them");
    visibility_ = std::move(hook);
}

} // namespace engine
