// stb_image (Debian libstb-dev) with the fuzzer's instrumentation: the loader decodes
// PNG/JPEG with it (GltfImages.cpp), so its decoders are part of what is fuzzed.
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
