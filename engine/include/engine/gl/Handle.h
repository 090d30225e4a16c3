#pragma once
// Handle: the one move-only owner of a GL name that every GL object class builds on
// (Buffer, Texture, Sampler, Framebuffer, VertexArray, Program).
//
// - Empty state is explicit: a default-constructed or moved-from handle has id() == 0
//   and deletes nothing.
// - Moving transfers the name *and* what we know about it (Info: size, format, ...), so a
//   moved-from owner is empty in every respect, not just in its name.
// - release() gives the name up (the caller now owns it); each owner's
//   wrap(name, Ownership) takes a foreign name: Adopt deletes it on destruction, Borrow not.
//
// GL names belong to a context: an owner deletes its name in whatever context is current
// when it dies. Destroy owners while their context is current (or one sharing with it).
//
// Every owned name is counted while it is owned (LiveObjects.h), for soaks and leak tests.
#include "engine/gl/LiveObjects.h"

#include <epoxy/gl.h>

#include <string_view>
#include <utility>

namespace engine::gl {

// Whether a wrapped foreign name is deleted when its owner dies.
enum class Ownership {
    Adopt,  // we delete it: the inverse of release()
    Borrow, // someone else deletes it; we only use it
};

struct NoInfo {};

// Traits: struct { static constexpr GLenum labelNamespace; static void destroy(GLuint) noexcept; }
// labelNamespace is the glObjectLabel identifier (GL_BUFFER, GL_TEXTURE, ...).
template <typename Traits, typename Info = NoInfo>
class Handle {
public:
    Handle() = default;
    ~Handle() { reset(); }

    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    Handle(Handle&& other) noexcept
        : name_(std::exchange(other.name_, 0u)),
          owned_(std::exchange(other.owned_, false)),
          info_(std::exchange(other.info_, Info{})) {}

    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0u);
            owned_ = std::exchange(other.owned_, false);
            info_ = std::exchange(other.info_, Info{});
        }
        return *this;
    }

    GLuint id() const noexcept { return name_; }
    explicit operator bool() const noexcept { return name_ != 0; }

    // Gives up ownership: returns the name, which the caller must now delete; *this is empty.
    [[nodiscard]] GLuint release() noexcept {
        if (name_ != 0 && owned_) detail::countOwnedObjects(Traits::labelNamespace, -1);
        owned_ = false;
        info_ = Info{};
        return std::exchange(name_, 0u);
    }

    // Deletes the name (if owned) and leaves *this empty.
    void reset() noexcept {
        if (name_ != 0 && owned_) {
            Traits::destroy(name_);
            detail::countOwnedObjects(Traits::labelNamespace, -1);
        }
        name_ = 0;
        owned_ = false;
        info_ = Info{};
    }

    // Names the object in debug output and GL debuggers (glObjectLabel).
    void setLabel(std::string_view label) {
        glObjectLabel(Traits::labelNamespace, name_, static_cast<GLsizei>(label.size()),
                      label.data());
    }

protected:
    Handle(GLuint name, Ownership ownership, Info info)
        : name_(name), owned_(ownership == Ownership::Adopt), info_(std::move(info)) {
        if (name_ != 0 && owned_) detail::countOwnedObjects(Traits::labelNamespace, +1);
    }

    const Info& info() const noexcept { return info_; }
    Info& info() noexcept { return info_; }

private:
    GLuint name_ = 0;
    bool owned_ = false;
    Info info_{};
};

} // namespace engine::gl
