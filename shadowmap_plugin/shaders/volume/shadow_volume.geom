// The classic shadow volume of a closed mesh, one triangle at a time, from its triangle and the
// three across its edges (GL_TRIANGLES_ADJACENCY: corners 0, 2, 4; across-vertices 1, 3, 5):
// the same volume the CPU makes (math/ShadowVolumeMesh.h). A triangle facing the light is a
// near cap and stands a quad on each edge whose neighbour does not face it (each silhouette
// edge once: only from its facing side); one facing away is a far cap at infinity (w = 0),
// none for a directional light, whose extruded corners coincide. Edge-on triangles count as
// facing, within EDGE_ON_SINE, so that both triangles of a face holding the light agree.
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 21) out;

uniform mat4 uModelViewProjection;  // P * V^-1 * M (with the mesh's centre), camera-relative
uniform vec4 uLight;                // object space: (position, 1), or (toward the light, 0)

bool facesLight(vec3 a, vec3 b, vec3 c) {
    vec3 normal = cross(b - a, c - a);
    vec3 toLight = uLight.w == 0.0 ? uLight.xyz : uLight.xyz - a;
    float side = dot(normal, toLight);
    return side > 0.0 || abs(side) <= EDGE_ON_SINE * length(normal) * length(toLight);
}

vec4 atInfinity(vec3 p) {
    return uModelViewProjection * vec4(uLight.w == 0.0 ? -uLight.xyz : p - uLight.xyz, 0.0);
}

void emitTriangle(vec4 a, vec4 b, vec4 c) {
    gl_Position = a;
    EmitVertex();
    gl_Position = b;
    EmitVertex();
    gl_Position = c;
    EmitVertex();
    EndPrimitive();
}

void main() {
    vec3 corner[3] = vec3[3](gl_in[0].gl_Position.xyz, gl_in[2].gl_Position.xyz, gl_in[4].gl_Position.xyz);
    vec3 across[3] = vec3[3](gl_in[1].gl_Position.xyz, gl_in[3].gl_Position.xyz, gl_in[5].gl_Position.xyz);
    vec4 projected[3];
    for (int k = 0; k < 3; ++k) projected[k] = uModelViewProjection * vec4(corner[k], 1.0);
    if (!facesLight(corner[0], corner[1], corner[2])) {
        if (uLight.w != 0.0) emitTriangle(atInfinity(corner[0]), atInfinity(corner[1]), atInfinity(corner[2]));
        return;
    }
    emitTriangle(projected[0], projected[1], projected[2]);
    for (int k = 0; k < 3; ++k) {
        int next = (k + 1) % 3;
        // The neighbour traverses the edge the other way: (next, k, across).
        if (facesLight(corner[next], corner[k], across[k])) continue;
        vec4 a = projected[k], b = projected[next];
        vec4 aFar = atInfinity(corner[k]), bFar = atInfinity(corner[next]);
        emitTriangle(b, a, aFar);
        if (uLight.w != 0.0) emitTriangle(b, aFar, bFar);
    }
}
