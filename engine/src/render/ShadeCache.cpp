#include "engine/render/ShadeCache.h"

#include "engine/util/Hasher.h"

#include <algorithm>
#include <cstdio>

namespace engine {

namespace {
constexpr int kChannelsPerLayer = 4;
// The lit pass writes the layers as extra colour outputs beside the image: GL 4.5
// guarantees 8 draw buffers, so at most 7 layers, 28 cached lights; lights past them are
// evaluated every frame (Inline).
constexpr int kMaxLayers = 7;
const char* const kComponents[kChannelsPerLayer] = {"x", "y", "z", "w"};

// A GLSL float literal that reads back as exactly `value`.
std::string glslFloat(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9e", static_cast<double>(value));
    return text;
}
} // namespace

int ShadeCache::Plan::count(Source source) const {
    return static_cast<int>(std::count(sources.begin(), sources.end(), source));
}

std::string ShadeCache::Plan::glsl() const {
    const int lightCount = static_cast<int>(sources.size());
    if (lightCount == 0) return {};
    const bool writes = writeArray != 0;
    std::string code;
    if (layers > 0)
        code += "layout(binding = " + std::to_string(kTextureUnit) + ") uniform sampler2DArray uShadeCache;\n";
    if (writes)
        code += "layout(location = 1) out vec4 outShadeCache[" + std::to_string(layers) + "];\n";
    code += "void loadShades(out float shades[LIGHT_COUNT], vec3 eyePosition, vec3 eyeNormal) {\n";
    // One fetch per layer that holds a still-valid light.
    std::vector<bool> fetched(layers, false);
    for (int slot = 0; slot < lightCount; ++slot)
        if (sources[slot] == Source::Fetch) fetched[channels[slot] / kChannelsPerLayer] = true;
    for (int layer = 0; layer < layers; ++layer)
        if (fetched[layer])
            code += "    vec4 cached" + std::to_string(layer) +
                    " = texelFetch(uShadeCache, ivec3(gl_FragCoord.xy, " + std::to_string(layer) + "), 0);\n";
    std::vector<std::string> layerValues(layers * kChannelsPerLayer, "0.0");
    for (int slot = 0; slot < lightCount; ++slot) {
        const std::string target = "    shades[" + std::to_string(slot) + "] = ";
        const int channel = channels[slot];
        if (sources[slot] == Source::Fetch)
            code += target + "cached" + std::to_string(channel / kChannelsPerLayer) + "." +
                    kComponents[channel % kChannelsPerLayer] + ";\n";
        else if (sources[slot] == Source::Constant)  // a literal: 1 folds away entirely
            code += target + "uReceiveShadows ? " + glslFloat(constants[slot]) + " : 1.0;\n";
        else
            code += target + "shadeOf(" + std::to_string(slot) + ", eyePosition, eyeNormal);\n";
        if (channel >= 0) layerValues[channel] = "shades[" + std::to_string(slot) + "]";
    }
    if (writes)
        for (int layer = 0; layer < layers; ++layer) {
            code += "    outShadeCache[" + std::to_string(layer) + "] = vec4(";
            for (int c = 0; c < kChannelsPerLayer; ++c)
                code += layerValues[layer * kChannelsPerLayer + c] + (c + 1 < kChannelsPerLayer ? ", " : ");\n");
        }
    code += "}\n";
    return code;
}

void ShadeCache::ensureArrays(int width, int height, int layers) {
    const gl::Texture& current = arrays_[current_];
    if (current.id() && current.width() == width && current.height() == height && current.layers() == layers)
        return;
    for (gl::Texture& array : arrays_) array = gl::Texture::create2DArray(GL_RGBA32F, width, height, layers);
    current_ = 0;
    channelKeys_.assign(static_cast<std::size_t>(layers) * kChannelsPerLayer, 0);
}

ShadeCache::Plan ShadeCache::uncached(int lightCount) {
    Plan plan;
    plan.sources.assign(lightCount, Source::Inline);
    plan.channels.assign(lightCount, -1);
    plan.constants.assign(lightCount, 1.0f);
    return plan;
}

ShadeCache::Plan ShadeCache::plan(std::uint64_t viewKey, const LightVisibilityHook& hook, int lightCount,
                                  int width, int height) {
    Plan plan = uncached(lightCount);
    const std::vector<std::uint64_t>& shadeKeys = hook.shadeKeys;
    int cached = 0;
    for (int slot = 0; slot < lightCount; ++slot) {
        if (const auto constant = hook.constantShades.find(slot); constant != hook.constantShades.end()) {
            plan.sources[slot] = Source::Constant;
            plan.constants[slot] = constant->second;
        } else if (slot < static_cast<int>(shadeKeys.size()) && shadeKeys[slot] != 0 &&
                   cached < kMaxLayers * kChannelsPerLayer) {
            plan.channels[slot] = cached++;
        }
    }
    if (cached == 0) return plan;
    plan.layers = (cached + kChannelsPerLayer - 1) / kChannelsPerLayer;
    ensureArrays(width, height, plan.layers);

    plan.writtenKeys.assign(channelKeys_.size(), 0);
    previousKeys_.resize(std::max<std::size_t>(previousKeys_.size(), lightCount), 0);
    changedLastFrame_.resize(previousKeys_.size(), false);
    bool fetches = false, computes = false;
    for (int slot = 0; slot < lightCount; ++slot) {
        const int channel = plan.channels[slot];
        if (channel < 0) {
            previousKeys_[slot] = 0;
            changedLastFrame_[slot] = false;
            continue;
        }
        // A channel is valid for this slot under this view with this hook key only.
        Hasher hasher;
        hasher.add(viewKey);
        hasher.add(slot);
        hasher.add(shadeKeys[slot]);
        const std::uint64_t key = std::max<std::uint64_t>(hasher.value(), 1);  // 0 = invalid
        // Written when another light's compute writes the array anyway: it is the shade
        // of this key, so a moving light that stops next frame is fetched, not recomputed.
        plan.writtenKeys[channel] = key;
        const bool valid = channelKeys_[channel] == key;
        const bool changed = previousKeys_[slot] != 0 && previousKeys_[slot] != key;
        const bool moving = !valid && changed && changedLastFrame_[slot];
        previousKeys_[slot] = key;
        changedLastFrame_[slot] = changed;
        plan.sources[slot] = valid ? Source::Fetch : moving ? Source::Moving : Source::Compute;
        fetches = fetches || valid;
        computes = computes || plan.sources[slot] == Source::Compute;
    }
    if (fetches) plan.readArray = arrays_[current_].id();
    if (computes) plan.writeArray = arrays_[1 - current_].id();
    return plan;
}

void ShadeCache::commit(const Plan& plan) {
    if (plan.writeArray == 0 || plan.writeArray != arrays_[1 - current_].id()) return;
    current_ = 1 - current_;
    channelKeys_ = plan.writtenKeys;
}

void ShadeCache::clear() {
    std::fill(channelKeys_.begin(), channelKeys_.end(), 0);
    previousKeys_.clear();
    changedLastFrame_.clear();
}

} // namespace engine
