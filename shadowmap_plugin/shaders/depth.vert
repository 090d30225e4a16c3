// Depth pass from a light: projection P_light, modelview L^-1 * M, composed in double on
// the CPU and handed over as one float matrix (light-relative, so its numbers stay small).
// invariant: Woo's two passes must produce bit-identical depths for the same triangle.
layout(location = 0) in vec3 inPosition;
uniform mat4 uLightModelViewProjection;  // P_light * L^-1 * M
invariant gl_Position;

void main() {
    gl_Position = uLightModelViewProjection * vec4(inPosition, 1.0);
}
