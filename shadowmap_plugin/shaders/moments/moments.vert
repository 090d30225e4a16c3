// One triangle over the whole target (gl_VertexID only, no vertex buffer): the moments passes
// write every texel of a map layer, the shadow volumes' resolve every camera pixel.
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
