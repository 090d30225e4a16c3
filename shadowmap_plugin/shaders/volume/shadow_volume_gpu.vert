// Shadow volumes extruded on the GPU: a closed mesh's welded vertices, in object space
// relative to the mesh's centre; the geometry stage classifies and projects them.
layout(location = 0) in vec3 inPosition;

void main() {
    gl_Position = vec4(inPosition, 1.0);
}
