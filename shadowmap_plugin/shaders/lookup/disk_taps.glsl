// What the lookups that filter over a disk share (pcss.glsl, widePcf.glsl): taps on a Vogel
// spiral turned per pixel, the receiver's own depth plane, and a cube face's tangent axes.
// HookGlsl.cpp writes it once, before every lookup's own file.

const float kGoldenAngle = 2.39996323;  // pi (3 - sqrt(5)): Vogel's spiral fills a disk evenly

// Tap i of `count` on the unit disk, the spiral turned by `rotation`.
vec2 diskTap(int i, int count, float rotation) {
    float radius = sqrt((float(i) + 0.5) / float(count));
    float angle = float(i) * kGoldenAngle + rotation;
    return radius * vec2(cos(angle), sin(angle));
}

// A turn of the disk per pixel (interleaved gradient noise, Jimenez 2014): neighbouring pixels
// sample differently, so few taps give fine noise instead of bands; a pixel turns it the same
// way every frame, so a still view stays still.
float diskRotation() {
    return 6.28318531 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
}

// The receiver's window-depth gradient in map coordinates, from the screen derivatives of
// (map coordinates, depth); 0 where they do not span the plane (edge-on, or non-finite).
// Every tap compares against the receiver's own plane (Isidoro, "Shadow Mapping: GPU-based
// Tips and Techniques", GDC 2006: the reference moves with the depth gradient the receiver
// has in map coordinates), so a wide kernel on a sloped receiver finds the receiver, not
// itself, in front: the polygon offset stays the 2x2 filter's.
vec2 receiverDepthGradient(vec3 mapPoint) {
    vec3 dx = dFdx(mapPoint), dy = dFdy(mapPoint);
    float det = dx.x * dy.y - dx.y * dy.x;
    vec2 gradient = vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det;
    return all(lessThan(abs(gradient), vec2(1e30))) ? gradient : vec2(0.0);
}

// The two tangent axes of the cube face `toPoint` falls on (the axes that are not its major
// one): offsets along them at unit distance on the major axis are the face's own coordinates
// (times 2).
void cubeFaceAxes(vec3 toPoint, out vec3 across, out vec3 up) {
    vec3 a = abs(toPoint);
    across = a.x >= a.y && a.x >= a.z ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    up = a.z >= a.x && a.z >= a.y ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0);
}
