// Shader resolution (#include), compilation with file-named errors, uniforms and buffers.
#include "GlProgram.h"

#include "common/EmbeddedFiles.h"

#include <algorithm>
#include <cstring>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace pl::gl {

namespace {

const std::string kShaderRoot = "shaders/";
constexpr GLuint kMaxGroupsX = 65535; // the minimum GL_MAX_COMPUTE_WORK_GROUP_COUNT[0] of GL 4.3

std::string_view embeddedShader(const std::string& path) {
    for (const auto& f : embeddedFiles())
        if (f.path == kShaderRoot + path) return f.text;
    throw ShaderError("no shader resources/" + kShaderRoot + path + " was embedded");
}

// Appends path's text, resolving #include "x" relative to resources/shaders/. Each file is included
// once (the shared headers define functions), and its lines keep their own numbering.
void appendResolved(const std::string& path, ResolvedShader& out, std::vector<std::string>& stack) {
    if (std::find(stack.begin(), stack.end(), path) != stack.end())
        throw ShaderError("shader include cycle through " + path);
    if (std::find(out.files.begin(), out.files.end(), path) != out.files.end() && !stack.empty()) return;
    const std::string_view text = embeddedShader(path);
    const int number = static_cast<int>(out.files.size());
    out.files.push_back(path);
    stack.push_back(path);
    std::istringstream lines{std::string(text)};
    int lineNumber = 0;
    out.text += "#line 1 " + std::to_string(number) + "\n";
    static const std::regex include(R"(^\s*#include\s+\"([^\"]+)\"\s*$)");
    for (std::string line; std::getline(lines, line);) {
        ++lineNumber;
        std::smatch m;
        if (std::regex_match(line, m, include)) {
            appendResolved(m[1].str(), out, stack);
            out.text += "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(number) + "\n";
        } else {
            out.text += line + "\n";
        }
    }
    stack.pop_back();
}

std::string infoLog(GLuint object, bool program) {
    GLint length = 0;
    program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
            : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    program ? glGetProgramInfoLog(object, length, nullptr, log.data())
            : glGetShaderInfoLog(object, length, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    return log;
}

} // namespace

ResolvedShader resolveShader(const std::string& path, const std::string& defines) {
    ResolvedShader out;
    const std::string_view text = embeddedShader(path);
    // #version must come first: split it off, put the defines after it.
    const auto end = text.find('\n');
    const std::string version(text.substr(0, end));
    if (version.rfind("#version", 0) != 0) throw ShaderError(path + ":1: the first line must be #version");
    std::vector<std::string> stack;
    appendResolved(path, out, stack);
    // Replace the resolved copy of the #version line (line 1 of file 0) by defines, keeping numbering.
    const std::string header = "#line 1 0\n" + version + "\n";
    if (out.text.rfind(header, 0) != 0) throw ShaderError(path + ": unexpected shader layout");
    out.text = version + "\n" + defines + (defines.empty() || defines.back() == '\n' ? "" : "\n") +
               "#line 2 0\n" + out.text.substr(header.size());
    return out;
}

std::string annotateLog(const std::string& log, const std::vector<std::string>& files) {
    // Mesa: "0:12(3): error: ..."; NVIDIA: "0(12) : error C1008: ...".
    static const std::regex mesa(R"((^|\n)(\d+):(\d+)\((\d+)\))");
    static const std::regex nvidia(R"((^|\n)(\d+)\((\d+)\))");
    auto name = [&](const std::string& number) {
        const auto n = static_cast<std::size_t>(std::stoul(number));
        return n < files.size() ? files[n] : "source " + number;
    };
    std::string out;
    std::smatch m;
    std::string rest = log;
    const std::regex& pattern = std::regex_search(log, mesa) ? mesa : nvidia;
    while (std::regex_search(rest, m, pattern)) {
        out += m.prefix().str() + m[1].str() + "resources/shaders/" + name(m[2].str()) + ":" + m[3].str();
        if (&pattern == &mesa) out += ":" + m[4].str();
        rest = m.suffix().str();
    }
    return out + rest;
}

ComputeProgram::ComputeProgram(const std::string& path, const std::string& defines) : path_(path) {
    const ResolvedShader source = resolveShader(path, defines);
    const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
    const char* text = source.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        const std::string log = annotateLog(infoLog(shader, false), source.files);
        glDeleteShader(shader);
        throw ShaderError("compiling resources/shaders/" + path + " failed:\n" + log);
    }
    program_ = glCreateProgram();
    glAttachShader(program_, shader);
    glLinkProgram(program_);
    glDeleteShader(shader);
    glGetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (!ok) {
        const std::string log = annotateLog(infoLog(program_, true), source.files);
        glDeleteProgram(program_);
        program_ = 0;
        throw ShaderError("linking resources/shaders/" + path + " failed:\n" + log);
    }
}

ComputeProgram::~ComputeProgram() {
    if (program_) glDeleteProgram(program_);
}

ComputeProgram& ComputeProgram::operator=(ComputeProgram&& other) noexcept {
    std::swap(program_, other.program_);
    std::swap(path_, other.path_);
    std::swap(uniforms_, other.uniforms_);
    return *this;
}

ComputeProgram::Uniform* ComputeProgram::changed(const char* name, std::array<std::uint32_t, 4> bits) {
    auto it = uniforms_.find(name);
    if (it == uniforms_.end())
        it = uniforms_.emplace(name, Uniform{glGetUniformLocation(program_, name)}).first;
    Uniform& u = it->second;
    if (u.location < 0 || (u.set && u.last == bits)) return nullptr;
    u.last = bits;
    u.set = true;
    return &u;
}

namespace {
template <class... T> std::array<std::uint32_t, 4> bitsOf(T... values) {
    std::array<std::uint32_t, 4> bits{};
    std::size_t k = 0;
    ((std::memcpy(&bits[k++], &values, sizeof(std::uint32_t))), ...);
    return bits;
}
} // namespace

void ComputeProgram::set(const char* name, float v) {
    if (Uniform* u = changed(name, bitsOf(v))) glUniform1f(u->location, v);
}
void ComputeProgram::set(const char* name, int v) {
    if (Uniform* u = changed(name, bitsOf(v))) glUniform1i(u->location, v);
}
void ComputeProgram::set(const char* name, unsigned v) {
    if (Uniform* u = changed(name, bitsOf(v))) glUniform1ui(u->location, v);
}
void ComputeProgram::set(const char* name, float x, float y) {
    if (Uniform* u = changed(name, bitsOf(x, y))) glUniform2f(u->location, x, y);
}
void ComputeProgram::set(const char* name, int x, int y) {
    if (Uniform* u = changed(name, bitsOf(x, y))) glUniform2i(u->location, x, y);
}
void ComputeProgram::set(const char* name, unsigned x, unsigned y) {
    if (Uniform* u = changed(name, bitsOf(x, y))) glUniform2ui(u->location, x, y);
}
void ComputeProgram::set(const char* name, float x, float y, float z, float w) {
    if (Uniform* u = changed(name, bitsOf(x, y, z, w))) glUniform4f(u->location, x, y, z, w);
}

void ComputeProgram::dispatch(std::size_t items, unsigned localSize) const {
    const auto groups = static_cast<GLuint>(groupsFor(items, localSize));
    if (groups == 0) return;
    // Shaders index items as gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x (see common.glsl).
    const GLuint x = std::min(groups, kMaxGroupsX);
    const GLuint y = (groups + x - 1) / x;
    glDispatchCompute(x, y, 1);
}

Buffer::~Buffer() {
    if (id_) glDeleteBuffers(1, &id_);
    if (staging_) glDeleteBuffers(1, &staging_);
}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    std::swap(id_, other.id_);
    std::swap(capacity_, other.capacity_);
    std::swap(staging_, other.staging_);
    std::swap(stagingCapacity_, other.stagingCapacity_);
    return *this;
}

namespace {
bool hasImmutableStorage() {
    static const bool has = epoxy_gl_version() >= 44 || epoxy_has_gl_extension("GL_ARB_buffer_storage");
    return has;
}
} // namespace

void Buffer::reserve(std::size_t bytes) {
    bytes = std::max<std::size_t>(bytes, 16);
    if (id_ && bytes <= capacity_) return;
    if (hasImmutableStorage()) {
        // Immutable storage that the CPU never maps: the driver keeps it in video memory. Growing
        // means a new buffer (contents are undefined after growing anyway).
        if (id_) glDeleteBuffers(1, &id_);
        glGenBuffers(1, &id_);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, id_);
        glBufferStorage(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr,
                        GL_DYNAMIC_STORAGE_BIT);
    } else {
        if (!id_) glGenBuffers(1, &id_);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, id_);
        // DYNAMIC_COPY: written and read by the GPU. A DRAW hint lets a driver keep it where the CPU can
        // write it cheaply, which is the wrong side for buffers the shaders stream through every step.
        glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_DYNAMIC_COPY);
    }
    if (glGetError() == GL_OUT_OF_MEMORY)
        throw std::runtime_error("the GPU has no room for a buffer of " + std::to_string(bytes) + " bytes");
    capacity_ = bytes;
}

void Buffer::upload(const void* data, std::size_t bytes, std::size_t offset) {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, id_);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes),
                    data);
}

void Buffer::download(void* data, std::size_t bytes, std::size_t offset) const {
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    if (!staging_ || stagingCapacity_ < bytes) {
        if (!staging_) glGenBuffers(1, &staging_);
        glBindBuffer(GL_COPY_WRITE_BUFFER, staging_);
        // STREAM_READ: written once by the GPU, read once by the CPU; the driver keeps it host-side.
        glBufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_STREAM_READ);
        stagingCapacity_ = bytes;
    }
    glBindBuffer(GL_COPY_READ_BUFFER, id_);
    glBindBuffer(GL_COPY_WRITE_BUFFER, staging_);
    glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(offset), 0,
                        static_cast<GLsizeiptr>(bytes));
    glGetBufferSubData(GL_COPY_WRITE_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data);
}

void Buffer::fillZero(std::size_t bytes) {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, id_);
    const GLuint zero = 0;
    glClearBufferSubData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, 0, static_cast<GLsizeiptr>(bytes),
                         GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void Buffer::bind(GLuint binding) const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, id_);
}

} // namespace pl::gl
