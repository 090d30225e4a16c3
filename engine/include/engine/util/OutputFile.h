#pragma once
// Outputs are written through a temporary file in the same folder and renamed into place,
// so a failure never leaves a half-written PNG, CSV or JSON behind. Throws InputError
// naming the path on failure.
#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

namespace engine {

// Whether `path` can take an output, for tools to ask before any long work: its folder exists
// and is writable (the file is written beside itself and renamed into place), the path is not
// a folder, and a file already there is not read-only (no write permission for anyone, or not
// writable by this user): a file the user protected is refused as cp refuses it, never
// replaced, even for root. Throws InputError naming the path and the reason.
void checkOutputPath(const std::filesystem::path& path);

// Checks the path as checkOutputPath does, then writes.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);
// 8-bit PNG, rows top first; channels 1 (gray), 3 or 4.
void writePngAtomically(const std::filesystem::path& path, int width, int height, int channels,
                        const std::vector<std::uint8_t>& pixels);
// Decodes an 8-bit PNG (for tests and tools comparing images); channels forced as asked.
std::vector<std::uint8_t> readPng(const std::filesystem::path& path, int channels, int& width,
                                  int& height);

} // namespace engine
