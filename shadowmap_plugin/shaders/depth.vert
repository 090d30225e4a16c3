// Depth pass from a light: projection P_light, modelview L^-1 * M, composed in double on
// the CPU and handed over as one float matrix (light-relative, so its numbers stay small).
// invariant: Woo's two passes must produce bit-identical depths for the same triangle.
// Alpha-tested casters' programs get the engine's material parts (MaterialShading.h)
// prepended; for the others passMaterialInputs() does nothing.
layout(location = 0) in vec3 inPosition;
uniform mat4 uLightModelViewProjection;  // P_light * L^-1 * M
invariant gl_Position;

#ifdef PEEL
// Woo pass 2's last draw (see DepthRenderer.cpp): a full-screen triangle at the far plane,
// window depth 1 (0 with reversed Z), from gl_VertexID alone.
uniform bool uFarLayer;
uniform bool uReversedZ;
#endif

void main() {
#ifdef PEEL
    if (uFarLayer) {
        vec2 corner = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
        gl_Position = vec4(corner, uReversedZ ? 0.0 : 1.0, 1.0);
        return;
    }
#endif
    gl_Position = uLightModelViewProjection * vec4(inPosition, 1.0);
    passMaterialInputs();
}
