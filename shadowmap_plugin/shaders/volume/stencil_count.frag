// The count of shadow volumes holding each camera pixel's surface, read from the stencil
// buffer (as a stencil-index texture) and written as itself into an R8 target (k / 255 is
// stored as k exactly): what a viewer shows in a volume light's map view.
layout(binding = 0) uniform usampler2D uStencil;
layout(location = 0) out float outCount;

void main() {
    outCount = float(texelFetch(uStencil, ivec2(gl_FragCoord.xy), 0).r) / 255.0;
}
