// Sandboxed file access for glTF loading (see GltfFileAccess.h for the tinygltf 2.7.0
// hazards it closes: URIs reaching outside the scene's folder, directories, huge files).
#include "GltfFileAccess.h"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace engine::gltf {

namespace {

class FileDescriptor {
public:
    explicit FileDescriptor(int fd) : fd_(fd) {}
    ~FileDescriptor() { if (fd_ >= 0) ::close(fd_); }
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    int get() const { return fd_; }

private:
    int fd_;
};

std::string tooLarge(std::uint64_t size, std::uint64_t maxBytes) {
    return "is " + std::to_string(size) + " bytes, more than the limit of " +
           std::to_string(maxBytes);
}

// True when `path` (a real path) lies strictly below `folder` (a real path).
bool isInsideFolder(const fs::path& path, const fs::path& folder) {
    auto p = path.begin();
    for (auto f = folder.begin(); f != folder.end(); ++f, ++p)
        if (p == path.end() || *p != *f) return false;
    return p != path.end();
}

bool hasUriScheme(const std::string& uri) {
    // RFC 3986: scheme = ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ) ":"
    if (uri.empty() || !std::isalpha(static_cast<unsigned char>(uri[0]))) return false;
    for (char c : uri) {
        if (c == ':') return true;
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.') return false;
    }
    return false;
}

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// The real path of `candidate` if it exists and lies inside `folder`, else the reason.
std::string realPathInside(const fs::path& candidate, const fs::path& folder, fs::path& real) {
    std::error_code error;
    real = fs::canonical(candidate, error);
    if (error) return error == std::errc::no_such_file_or_directory ? "no such file" : error.message();
    if (!isInsideFolder(real, folder))
        return "resolves to '" + real.string() + "', outside the scene's folder";
    return {};
}

} // namespace

bool readRegularFile(const fs::path& path, std::uint64_t maxBytes,
                     std::vector<std::uint8_t>& contents, std::string& problem) {
    // O_NONBLOCK: opening a FIFO must not hang the loader before fstat can refuse it.
    const FileDescriptor fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
    if (fd.get() < 0) {
        problem = errno == ENOENT ? "no such file" : std::string("cannot open: ") + std::strerror(errno);
        return false;
    }
    struct stat info {};
    if (::fstat(fd.get(), &info) != 0) {
        problem = std::string("cannot stat: ") + std::strerror(errno);
        return false;
    }
    // A directory would make tinygltf 2.7.0 allocate 0x7fff... bytes and abort (#416).
    if (!S_ISREG(info.st_mode)) {
        problem = "is not a regular file";
        return false;
    }
    const auto size = static_cast<std::uint64_t>(info.st_size);
    if (size > maxBytes) {
        problem = tooLarge(size, maxBytes);
        return false;
    }
    contents.resize(size);
    std::size_t done = 0;
    while (done < size) {
        const ssize_t got = ::read(fd.get(), contents.data() + done, size - done);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) {
            problem = got == 0 ? "shrank while being read" : std::string("cannot read: ") + std::strerror(errno);
            return false;
        }
        done += static_cast<std::size_t>(got);
    }
    return true;
}

bool decodeUriLikeTinygltf(const std::string& uri, std::string& decoded) {
    decoded.clear();
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            decoded += ' ';
        } else if (uri[i] == '%') {
            // tinygltf decodes any two characters after '%', hex or not; a malformed escape
            // would be opened as some other name, so it is refused instead.
            if (i + 2 >= uri.size()) return false;
            const int high = hexValue(uri[i + 1]), low = hexValue(uri[i + 2]);
            if (high < 0 || low < 0) return false;
            decoded += static_cast<char>(high * 16 + low);
            i += 2;
        } else {
            decoded += uri[i];
        }
    }
    return true;
}

std::string checkExternalUri(const std::string& uri, const fs::path& folder, std::uint64_t maxBytes) {
    const std::string quoted = "uri '" + uri + "'";
    if (uri.empty()) return "uri is empty";
    if (hasUriScheme(uri))
        return quoted + " has a scheme; only relative paths inside the scene's folder are read";
    std::string path;
    if (!decodeUriLikeTinygltf(uri, path)) return quoted + " has a malformed percent escape";
    if (path.find('\0') != std::string::npos) return quoted + " contains a NUL character";
    if (path.find('\\') != std::string::npos) return quoted + " contains a backslash";
    if (path.front() == '/') return quoted + " is an absolute path; only relative paths are read";
    for (const fs::path& segment : fs::path(path))
        if (segment == "..") return quoted + " climbs out of the scene's folder with '..'";

    fs::path real;
    if (const std::string problem = realPathInside(folder / path, folder, real); !problem.empty())
        return quoted + ": " + problem;
    struct stat info {};
    if (::stat(real.c_str(), &info) != 0) return quoted + ": cannot stat: " + std::strerror(errno);
    if (!S_ISREG(info.st_mode)) return quoted + " is not a regular file";
    if (static_cast<std::uint64_t>(info.st_size) > maxBytes)
        return quoted + " " + tooLarge(static_cast<std::uint64_t>(info.st_size), maxBytes);
    return {};
}

namespace {

// tinygltf hands these the joined "base_dir/uri" (and "./uri": it also searches the current
// directory); whatever the path, only regular files under the sandbox's folder pass.
bool sandboxFileExists(const std::string& path, void* userData) {
    const auto& sandbox = *static_cast<const SceneFolderSandbox*>(userData);
    fs::path real;
    std::error_code error;
    return realPathInside(path, sandbox.folder, real).empty() && fs::is_regular_file(real, error);
}

std::string identityExpandFilePath(const std::string& path, void*) { return path; }

bool sandboxReadWholeFile(std::vector<unsigned char>* out, std::string* err,
                          const std::string& path, void* userData) {
    const auto& sandbox = *static_cast<const SceneFolderSandbox*>(userData);
    fs::path real;
    std::string problem = realPathInside(path, sandbox.folder, real);
    if (problem.empty() && readRegularFile(real, sandbox.maxFileBytes, *out, problem)) return true;
    if (err) *err += path + ": " + problem + "\n";
    return false;
}

bool refuseWriteWholeFile(std::string* err, const std::string& path,
                          const std::vector<unsigned char>&, void*) {
    if (err) *err += path + ": the glTF loader never writes files\n";
    return false;
}

} // namespace

tinygltf::FsCallbacks makeSandboxedFsCallbacks(SceneFolderSandbox& sandbox) {
    // tinygltf 2.7.0 has no GetFileSizeInBytes callback: the size cap lives in ReadWholeFile.
    tinygltf::FsCallbacks callbacks{};
    callbacks.FileExists = &sandboxFileExists;
    callbacks.ExpandFilePath = &identityExpandFilePath;
    callbacks.ReadWholeFile = &sandboxReadWholeFile;
    callbacks.WriteWholeFile = &refuseWriteWholeFile;
    callbacks.user_data = &sandbox;
    return callbacks;
}

} // namespace engine::gltf
