// Depth pass from a light: projection P_light, modelview L^-1 * M, composed in double on
// the CPU and handed over as one float matrix (light-relative, so its numbers stay small).
// invariant: Woo's two passes must produce bit-identical depths for the same triangle.
// Alpha-tested casters' programs get the engine's material parts (MaterialShading.h)
// prepended; for the others passMaterialInputs() does nothing. The depth program's vertex
// part (shaders/depth/, technique/DepthProgram.h) follows this source.
layout(location = 0) in vec3 inPosition;
uniform mat4 uLightModelViewProjection;  // P_light * L^-1 * M
uniform bool uReversedZ;                 // the pass's depth direction: far is 0, not 1
uniform bool uFullScreenLayer;           // DepthProgram::drawsFullScreenLayer's last draw
invariant gl_Position;

bool placesVertex();

void main() {
    if (placesVertex()) return;
    gl_Position = uLightModelViewProjection * vec4(inPosition, 1.0);
    passMaterialInputs();
}
