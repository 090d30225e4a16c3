// The nearest caster's depth (DepthProgram.h): the rasterized depth as it is.
void writeDepthFragment() {}
