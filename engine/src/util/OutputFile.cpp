#include "engine/util/OutputFile.h"

#include "engine/util/Error.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sys/stat.h>
#include <unistd.h>

namespace engine {

void checkOutputPath(const std::filesystem::path& path) {
    std::error_code error;
    if (path.empty()) throwInputError("(empty path)", "", "an output needs a file name");
    if (std::filesystem::is_directory(path, error))
        throwInputError(path.string(), "", "is a folder, not a file to write");
    const std::filesystem::path folder = std::filesystem::absolute(path, error).parent_path();
    if (!std::filesystem::is_directory(folder, error))
        throwInputError(path.string(), "", "its folder " + folder.string() + " does not exist");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throwInputError(path.string(), "", "its folder " + folder.string() + " is not writable: " + std::strerror(errno));
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) return;  // no file there yet
    if ((status.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0 || ::access(path.c_str(), W_OK) != 0)
        throwInputError(path.string(), "", "the file exists and is read-only: not replaced (make it writable or "
                                           "write elsewhere)");
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
    checkOutputPath(path);
    std::filesystem::path temporary = path;
    temporary += ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throwInputError(path.string(), "", std::string("cannot create the output file: ") + std::strerror(errno));
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
