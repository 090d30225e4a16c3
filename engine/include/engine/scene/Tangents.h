#pragma once
// Tangent frames for normal mapping when a file gives none (glTF: "When tangents are not
// specified, client implementations SHOULD calculate tangents using default MikkTSpace
// algorithms with the specified vertex positions, normals, and texture coordinates
// associated with the normal texture").
//
// Which way the bitangent points. glTF 2.0 says three things:
//   - TANGENT: "bitangent = cross(normal.xyz, tangent.xyz) * tangent.w";
//   - material.normalTexture: "The normal vectors use the convention +X is right and +Y is
//     up. +Z points toward the viewer." (right and up as the image is seen);
//   - textures: "The origin of the texture coordinates (0, 0) corresponds to the upper left
//     corner of a texture image": u grows to the right, v grows DOWN the image.
// So the map's +X (the tangent) is the direction of increasing u, and its +Y (the
// bitangent) the direction of DECREASING v. MikkTSpace itself follows increasing v, which
// is "up" only for UVs with the origin at the bottom left (OpenGL's, Blender's); an
// implementation that fed it glTF's UVs unchanged would turn every normal map's green
// channel upside down. Hence w below: +1 when cross(normal, tangent) points along -dp/dv.
// Example: a quad facing +z with u along +x and v along -y (an upright image) has tangent
// +x, bitangent +y = cross(+z, +x), w = +1; mirror u (u along -x) and w becomes -1.
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace engine {

// One tangent per vertex for the triangle list `indices`, from `positions`, unit `normals`
// and the texture coordinates `uvs` of the normal texture (glTF's UV convention), as
// Primitive::tangents holds them: xyz a unit vector perpendicular to the vertex normal
// along increasing u, w = +1 or -1 (the header comment says which).
//
// Like MikkTSpace, each triangle's dp/du and -dp/dv are projected into the plane of the
// vertex normal, normalized and summed weighted by the triangle's angle at that vertex;
// the sum is made perpendicular to the normal (Gram-Schmidt) and w is the side of
// cross(normal, tangent) the summed bitangent lies on. Unlike MikkTSpace, vertices are not
// split: where triangles sharing a vertex disagree (a UV seam that mirrors, a hard edge in
// UV space), their frames are averaged into one, so a normal map is slightly wrong along
// such seams unless the file's vertices are already split there (exporters usually split
// them: UV seams need their own vertices anyway).
//
// Triangles whose UVs span no area (or whose positions do) contribute nothing; a vertex
// left with no usable direction gets anyPerpendicular(normal) and w = +1, so shaders never
// see a zero or non-finite tangent. Computed in double.
std::vector<glm::vec4> generateTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec2>& uvs, const std::vector<std::uint32_t>& indices);

// A unit vector perpendicular to `normal` (of any length; a zero normal counts as +z, as
// generateNormals' fallback), always the same for the same normal (Duff et al., "Building
// an Orthonormal Basis, Revisited", JCGT 6(1), 2017): +x for a normal of +z or -z.
glm::vec3 anyPerpendicular(const glm::vec3& normal);

} // namespace engine
