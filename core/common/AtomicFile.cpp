// POSIX implementation of atomic file replacement (write, fsync, rename).
#include "AtomicFile.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace pl {

namespace {
std::string systemReason() {
    return std::strerror(errno);
}
} // namespace

void writeFileAtomically(const std::string& path, std::string_view content) {
    std::string temp = path + ".XXXXXX";
    const int fd = ::mkstemp(temp.data());
    if (fd < 0) throw FileError("cannot write '" + path + "': " + systemReason());
    std::size_t written = 0;
    while (written < content.size()) {
        const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
        if (n < 0) {
            if (errno == EINTR) continue;
            const std::string reason = systemReason();
            ::close(fd);
            ::unlink(temp.c_str());
            throw FileError("cannot write '" + path + "': " + reason);
        }
        written += static_cast<std::size_t>(n);
    }
    // mkstemp creates 0600; a saved document should carry the usual permissions.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    if (::fsync(fd) != 0 || ::close(fd) != 0) {
        const std::string reason = systemReason();
        ::unlink(temp.c_str());
        throw FileError("cannot write '" + path + "': " + reason);
    }
    if (::rename(temp.c_str(), path.c_str()) != 0) {
        const std::string reason = systemReason();
        ::unlink(temp.c_str());
        throw FileError("cannot replace '" + path + "': " + reason);
    }
}

std::string readWholeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError("cannot open '" + path + "': " + systemReason());
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw FileError("cannot read '" + path + "': " + systemReason());
    return buffer.str();
}

} // namespace pl
