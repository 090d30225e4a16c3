#pragma once
// Seeds that reach the loader's decoders of compressed data, made here with the encoders of
// the same Debian libraries the engine decodes with (libdraco, libmeshoptimizer), so the
// fuzzer starts from streams that decode and mutates them from there.
#include "gltf_writer.h"  // tests/unit/

namespace compressed_seeds {

// A split-vertex cube (24 points, 12 triangles) as one KHR_draco_mesh_compression
// primitive: 11-bit positions, 8-bit normals.
gltf_writer::GltfBuilder dracoCube();

// A two-triangle quad under EXT_meshopt_compression and KHR_mesh_quantization: positions
// UNSIGNED_SHORT (ATTRIBUTES, dequantized by the node's scale), normals +x, +y, +z and
// (0.6, 0, -0.8) as BYTE normalized (ATTRIBUTES + OCTAHEDRAL), texture coordinates FLOAT (ATTRIBUTES + EXPONENTIAL),
// indices as TRIANGLES and as INDICES; every decoded view lives in a fallback buffer
// without data, as gltfpack writes it.
gltf_writer::GltfBuilder meshoptQuad();

} // namespace compressed_seeds
