// A shadow volume's triangles, made on the CPU in camera-relative eye space (V^-1 * M composed
// in double, so a scene far from the origin keeps its precision): finite points with w = 1,
// points extruded to infinity with w = 0. Depth clamping (not an infinite far plane) keeps the
// far caps from being clipped.
layout(location = 0) in vec4 inEyePoint;

uniform mat4 uProjection;  // P_eye

void main() {
    gl_Position = uProjection * inEyePoint;
}
