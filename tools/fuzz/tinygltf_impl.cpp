// tinygltf 2.7.0 compiled from Debian's header with the fuzzer's instrumentation (coverage
// + ASan/UBSan) instead of linking libtinygltf.so, so libFuzzer sees inside the parser. Same
// configuration as Debian's library (README.Debian of libtinygltf-dev: the defaults, with
// nlohmann JSON and stb): none of TINYGLTF_NO_FS / NO_STB_IMAGE / NO_EXTERNAL_IMAGE, so the
// inline parts of tiny_gltf.h agree with the engine sources compiled next to this file.
// stb's implementations are in stb_image_impl.cpp / stb_image_write_impl.cpp (separate
// files: they build in parallel, which keeps the CI fuzz step short).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
