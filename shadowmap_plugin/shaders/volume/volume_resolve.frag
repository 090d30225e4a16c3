// The light's visibility per camera pixel: drawn where the stencil test passes (the count of
// volumes in front of the nearest surface is 0) into a target cleared to 0 (shadowed).
layout(location = 0) out float outVisibility;

void main() {
    outVisibility = 1.0;
}
