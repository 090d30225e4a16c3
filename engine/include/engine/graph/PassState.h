#pragma once
// The fixed-function state a pass's draws start from, declared with the pass
// (PassBuilder::setState) and applied by the executor before the pass runs
// (ExecuteOptions::applyState; GlPassState.h in practice). Every field is applied every time,
// so no pass inherits what the one before it left behind and none restores state by hand.
// A pass may still change state between its own draws (culling per material, an offset per
// caster); the next pass starts from its own declaration again. Plain data: no GL here.
namespace engine {

struct PassState {
    enum class DepthTest { Off, Less, Greater };
    enum class Cull { None, Back, Front };
    // Clip-space depth range mapped to window depth [0,1] (glClipControl): ZeroToOne keeps
    // float depth's precision for reversed Z.
    enum class ClipDepth { NegativeOneToOne, ZeroToOne };

    DepthTest depthTest = DepthTest::Less;
    bool depthWrite = true;
    Cull cull = Cull::Back;  // counter-clockwise front faces
    ClipDepth clipDepth = ClipDepth::NegativeOneToOne;
    bool depthClamp = false;
    // glPolygonOffset(factor, units), clamped through glPolygonOffsetClamp when clamp != 0;
    // all zero: no offset.
    float offsetFactor = 0.0f, offsetUnits = 0.0f, offsetClamp = 0.0f;
    bool srgbWrites = false;  // GL_FRAMEBUFFER_SRGB: linear colour encoded on write
    // 0: the size of the first texture the pass writes.
    int viewportWidth = 0, viewportHeight = 0;
    int viewportX = 0, viewportY = 0;  // the viewport's lower left corner
    // Clears and draws stay inside the viewport (the scissor test on it): a pass that
    // renders one rectangle of a shared texture (PassBuilder::writePart) clears only that.
    bool scissorToViewport = false;

    bool operator==(const PassState&) const = default;
};

} // namespace engine
