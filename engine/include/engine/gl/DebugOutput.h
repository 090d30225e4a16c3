#pragma once
// DebugOutput: routes the driver's high-severity debug messages (GL errors, undefined
// behaviour) to stderr as they happen, with the object labels set through setLabel(), so a
// failing call is seen at its call site instead of at the next checkGlError.
// Installed by the contexts when ContextOptions::debug is set; needs a debug context to be
// useful (others may report nothing).
namespace engine::gl {

// Enables synchronous debug output on the current context, high severity only.
void installDebugOutput();

} // namespace engine::gl
