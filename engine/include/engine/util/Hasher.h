#pragma once
// FNV-1a over the bytes of what is fed in: the cache keys of shadow maps and of the lit
// pass's shade cache hash a few dozen values per frame, so simple beats fast here.
#include <glm/glm.hpp>

#include <cstdint>
#include <cstring>

namespace engine {

class Hasher {
public:
    template <typename T>
    void add(const T& value) {
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        for (unsigned char byte : bytes) hash_ = (hash_ ^ byte) * 1099511628211ull;
    }
    void add(const glm::dmat4& m) {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) add(m[c][r]);
    }
    std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = 14695981039346656037ull;
};

} // namespace engine
