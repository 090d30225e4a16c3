// Depth pass: the depth program's fragment part (shaders/depth/, technique/DepthProgram.h)
// follows this source and decides what the fragment writes beyond its depth.
// ALPHA_TEST (an alpha-tested caster, MaterialShading.h): texels whose base color alpha
// is below the material's shadow cutoff cast nothing, whatever the program.
uniform bool uReversedZ;  // the pass's depth direction: near is 1, far 0

void writeDepthFragment();

void main() {
#ifdef ALPHA_TEST
    discardBelowAlphaCutoff(materialBaseColor().a);
#endif
    writeDepthFragment();
}
