// The nearest caster's depth (DepthProgram.h): every vertex is a caster's.
bool placesVertex() { return false; }
