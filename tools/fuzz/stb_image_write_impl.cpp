// stb_image_write: tinygltf's writer needs the symbols; the loader never writes, so this is
// compiled without instrumentation (see CMakeLists.txt).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
