// Shadow volumes only count in the stencil buffer: no colour, no depth.
void main() {}
