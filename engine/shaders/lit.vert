// Lit pass, vertex stage. Everything is in eye space: the CPU composes the modelview
// V^-1 * M in double and hands over camera-relative floats, so a scene far from the
// origin keeps full precision (float spacing is 0.0625 at 10^6). The engine prepends the material
// parts (MaterialShading.h): texture coordinates and vertex color.
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

uniform mat4 uModelView;     // V^-1 * M
uniform mat3 uNormalMatrix;  // inverse transpose of the modelview's 3x3
uniform mat4 uProjection;    // P_eye

out vec3 vEyePosition;
out vec3 vEyeNormal;
#ifdef NORMAL_TEXTURE
layout(location = ATTRIB_TANGENT) in vec4 inTangent;  // xyz unit, w = +-1 (glTF TANGENT)
out vec3 vEyeTangent;
out vec3 vEyeBitangent;
#endif

// The visibility hook's vertex part (Frame.h), appended by the engine.
void lightTexgen(vec3 eyePosition);

void main() {
    vec4 eyePosition = uModelView * vec4(inPosition, 1.0);
    vEyePosition = eyePosition.xyz;
    vEyeNormal = uNormalMatrix * inNormal;
#ifdef NORMAL_TEXTURE
    // Tangent and bitangent are directions along the surface, so the modelview carries them
    // (the normal matrix is the normal's). The bitangent is formed in object space, so a
    // mirroring transform mirrors it as it mirrors the texture. Unit per vertex: the normal
    // map's tilt must not stretch with the node's scale.
    vEyeTangent = normalize(mat3(uModelView) * inTangent.xyz);
    vEyeBitangent = normalize(mat3(uModelView) * (cross(inNormal, inTangent.xyz) * inTangent.w));
#endif
    passMaterialInputs();
    gl_Position = uProjection * eyePosition;
    lightTexgen(eyePosition.xyz);
}
