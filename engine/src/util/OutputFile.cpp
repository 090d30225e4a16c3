#include "engine/util/OutputFile.h"

#include "engine/util/Error.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <unistd.h>

namespace engine {

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
    std::filesystem::path temporary = path;
    temporary += ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throwInputError(path.string(), "", "cannot create the output file");
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.flush();
        if (!out) {
            out.close();
            std::remove(temporary.c_str());
            throwInputError(path.string(), "", "writing the output failed");
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::remove(temporary.c_str());
        throwInputError(path.string(), "", "cannot move the output into place: " + error.message());
    }
}

void writePngAtomically(const std::filesystem::path& path, int width, int height, int channels,
                        const std::vector<std::uint8_t>& pixels) {
    std::string png;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                   static_cast<std::size_t>(size));
    };
    if (!stbi_write_png_to_func(append, &png, width, height, channels, pixels.data(),
                                width * channels))
        throwInputError(path.string(), "", "PNG encoding failed");
    writeFileAtomically(path, png);
}

std::vector<std::uint8_t> readPng(const std::filesystem::path& path, int channels, int& width,
                                  int& height) {
    int fileChannels = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load(path.c_str(), &width, &height, &fileChannels, channels), stbi_image_free);
    if (!data) throwInputError(path.string(), "", std::string("cannot read PNG: ") +
                                                      (stbi_failure_reason() ? stbi_failure_reason() : "?"));
    return {data.get(), data.get() + static_cast<std::size_t>(width) * height * channels};
}

} // namespace engine
