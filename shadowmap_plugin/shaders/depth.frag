// Depth pass: only depth is written (the framebuffer has no color attachment).
void main() {
}
