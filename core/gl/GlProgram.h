// Compute programs built from resources/shaders/ (embedded at build time) and shader storage buffers.
#pragma once

#include <epoxy/gl.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pl::gl {

// A compile or link failure; the message names the shader file and line of each error.
class ShaderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The text of a shader under resources/shaders/ with its #include "..." lines resolved. Each included
// file is a separate GLSL source-string number (#line 1 N), so errors can be mapped back to files.
struct ResolvedShader {
    std::string text;
    std::vector<std::string> files; // source-string number → path under resources/shaders/
};
ResolvedShader resolveShader(const std::string& path, const std::string& defines = {});
// Rewrites a driver's info log ("0:12(3): error" from Mesa, "0(12) : error" from NVIDIA) so that each
// location names its file instead of the source-string number.
std::string annotateLog(const std::string& log, const std::vector<std::string>& files);

class ComputeProgram {
public:
    ComputeProgram() = default;
    // Compiles and links resources/shaders/<path>; defines are lines such as "#define LOCAL_SIZE 256".
    ComputeProgram(const std::string& path, const std::string& defines = {});
    ~ComputeProgram();
    ComputeProgram(ComputeProgram&& other) noexcept { *this = std::move(other); }
    ComputeProgram& operator=(ComputeProgram&& other) noexcept;
    ComputeProgram(const ComputeProgram&) = delete;
    ComputeProgram& operator=(const ComputeProgram&) = delete;

    void use() const { glUseProgram(program_); }
    // Uniform setters of the program in use; unknown names are ignored (the compiler may drop them).
    // Names must be string literals (they are kept as views), and a value equal to the last one set is
    // not sent again: a small step issues a few dispatches, and their uniforms were most of its CPU time.
    void set(const char* name, float v);
    void set(const char* name, int v);
    void set(const char* name, unsigned v);
    void set(const char* name, float x, float y);
    void set(const char* name, int x, int y);
    void set(const char* name, unsigned x, unsigned y);
    void set(const char* name, float x, float y, float z, float w);
    // Dispatches ceil(items / localSize) groups (at most 65535 per dimension: the rest go to y).
    void dispatch(std::size_t items, unsigned localSize) const;

private:
    struct Uniform {
        GLint location = -1;
        std::array<std::uint32_t, 4> last{}; // bits of the last value set
        bool set = false;
    };
    // The uniform's record, or nullptr when the value equals the last one (nothing to send).
    Uniform* changed(const char* name, std::array<std::uint32_t, 4> bits);
    GLuint program_ = 0;
    std::string path_;
    std::unordered_map<std::string_view, Uniform> uniforms_;
};

// Blocks until every command issued so far in the current context is complete, on a fence (not glFinish):
// another context (the viewport's) reads the buffers those commands wrote next.
inline void waitUntilCommandsComplete() {
    GLsync done = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    constexpr GLuint64 kSecondNs = 1000000000;
    GLenum state = glClientWaitSync(done, GL_SYNC_FLUSH_COMMANDS_BIT, kSecondNs);
    while (state == GL_TIMEOUT_EXPIRED) state = glClientWaitSync(done, 0, kSecondNs);
    glDeleteSync(done);
}

// Memory barrier between dependent dispatches: on a real GPU they overlap otherwise.
inline void storageBarrier() {
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

class Buffer {
public:
    Buffer() = default;
    ~Buffer();
    Buffer(Buffer&& other) noexcept { *this = std::move(other); }
    Buffer& operator=(Buffer&& other) noexcept;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    // Grows (never shrinks) to at least bytes; contents are undefined after growing.
    void reserve(std::size_t bytes);
    // Reads go through a staging buffer: a driver that sees the CPU read a buffer may move it to host
    // memory (NVIDIA reports "copied/moved from VIDEO memory to HOST memory"), after which every pass
    // that streams through it crosses PCIe. The buffers the shaders use are never read by the CPU.
    void upload(const void* data, std::size_t bytes, std::size_t offset = 0);
    void download(void* data, std::size_t bytes, std::size_t offset = 0) const;
    void fillZero(std::size_t bytes);
    void bind(GLuint binding) const;
    std::size_t capacity() const { return capacity_; }
    GLuint id() const { return id_; }

    template <class T> void uploadVector(const std::vector<T>& v) {
        reserve(v.size() * sizeof(T));
        if (!v.empty()) upload(v.data(), v.size() * sizeof(T));
    }
    template <class T> std::vector<T> downloadVector(std::size_t count) const {
        std::vector<T> v(count);
        if (count) download(v.data(), count * sizeof(T));
        return v;
    }

private:
    GLuint id_ = 0;
    std::size_t capacity_ = 0;
    mutable GLuint staging_ = 0; // where download() copies to before the CPU reads (host-side memory)
    mutable std::size_t stagingCapacity_ = 0;
};

// Groups needed for items at localSize per group.
inline std::size_t groupsFor(std::size_t items, unsigned localSize) {
    return (items + localSize - 1) / localSize;
}

} // namespace pl::gl
