// Lit pass, vertex stage. Everything is in eye space: the CPU composes the modelview
// V^-1 * M in double and hands over camera-relative floats, so a scene far from the
// origin keeps full precision (DESIGN.md "Transforms").
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inTexcoord;

uniform mat4 uModelView;     // V^-1 * M
uniform mat3 uNormalMatrix;  // inverse transpose of the modelview's 3x3
uniform mat4 uProjection;    // P_eye

out vec3 vEyePosition;
out vec3 vEyeNormal;
out vec2 vTexcoord;

// The visibility hook's vertex part (Frame.h), appended by the engine.
void lightTexgen(vec3 eyePosition);

void main() {
    vec4 eyePosition = uModelView * vec4(inPosition, 1.0);
    vEyePosition = eyePosition.xyz;
    vEyeNormal = uNormalMatrix * inNormal;
    vTexcoord = inTexcoord;
    gl_Position = uProjection * eyePosition;
    lightTexgen(eyePosition.xyz);
}
