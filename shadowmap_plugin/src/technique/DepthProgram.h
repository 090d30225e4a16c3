#pragma once
// The program a depth pass draws the casters with: the part of a way of making a map
// (DepthTechnique.h) that runs on the GPU. The shaders every depth pass shares
// (shaders/depth.vert and depth.frag: the caster's position, alpha-tested materials, the
// depth direction) call one function per stage that the program defines (shaders/depth/):
//   vertex:   bool placesVertex()       true when it placed gl_Position itself, without a
//                                       caster vertex (the full-screen triangle below)
//   fragment: void writeDepthFragment() what the fragment does beyond its rasterized depth:
//                                       nothing, discard, or write gl_FragDepth (and, for a
//                                       map that holds more than depth, its color outputs)
// A pass names its program in its DepthPassStyle; the plugin's DepthRenderer compiles each
// program with every caster material it meets, and every technique's programs before the
// first frame (DepthTechnique::programs).
namespace shadowmap {

struct DepthProgram {
    const char* name;          // in GL's messages and the logs
    const char* vertexGlsl;    // defines placesVertex()
    const char* fragmentGlsl;  // defines writeDepthFragment()
    // After the casters, one full-screen triangle (three vertices from gl_VertexID, no
    // attributes) drawn with uniform uFullScreenLayer true, depth-clamped and without the
    // polygon offset: the program's vertex part places it (Woo's far layer).
    bool drawsFullScreenLayer = false;
};

// Writes the rasterized depth of the nearest caster and nothing else (standard, backface,
// and Woo's first layer).
const DepthProgram& nearestDepthProgram();

} // namespace shadowmap
