// Woo's midpoint map, pass 2 (technique/depth/WooDepth.h). Its last draw is the far plane
// as one more layer: a full-screen triangle at window depth 1 (0 with reversed Z), from
// gl_VertexID alone (DepthProgram::drawsFullScreenLayer).
bool placesVertex() {
    if (!uFullScreenLayer) return false;
    vec2 corner = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
    gl_Position = vec4(corner, uReversedZ ? 0.0 : 1.0, 1.0);
    return true;
}
