// POSIX implementation of safe file writes: atomic replacement (write, fsync, rename, fsync the folder)
// and unbuffered streaming, both through symbolic links and never over a file that is not regular.
#include "AtomicFile.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <ctime>
#include <dirent.h>
#include <fcntl.h>
#include <filesystem>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace pl {

namespace {

// Temporary files are named target + kTempMark + the writer's process id + '-' + six characters of
// mkstemp ("s.csv.tmp-4711-a8Zq0B"); a writer holds an exclusive flock on its own while it lives. One whose
// process is gone and that nobody holds is removed at once, whatever its age. Builds before the process id
// was in the name wrote target + kTempMark + six characters: those, and those of a process id that lives
// (perhaps reused), are removed once nobody holds them and they are not brand new.
constexpr const char* kTempMark = ".tmp-";
constexpr int kTempRandom = 6;
// A temporary file this young may belong to a writer between mkstemp and flock: it is left alone unless
// its process is gone.
constexpr std::time_t kStaleSeconds = 10;
constexpr int kMaxLinkHops = 40; // as the kernel's own limit on a chain of links

std::string systemReason() {
    return std::strerror(errno);
}

std::string folderOf(const std::string& path) {
    const auto slash = path.rfind('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string nameOf(const std::string& path) {
    const auto slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

// Flushes the folder's entry of a renamed file; a file system that cannot (EINVAL) has nothing to flush.
void syncFolder(const std::string& folder) {
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}

bool isTempRandom(const std::string& text) {
    if (text.size() != kTempRandom) return false;
    for (const char c : text)
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'))) return false;
    return true;
}

// Whether entry is a temporary file of base; pid receives its writer's process id, or 0 for a name of an
// earlier build that holds none.
bool isTempName(const std::string& entry, const std::string& base, pid_t& pid) {
    const std::string prefix = base + kTempMark;
    if (entry.size() <= prefix.size() || entry.compare(0, prefix.size(), prefix) != 0) return false;
    const std::string rest = entry.substr(prefix.size());
    pid = 0;
    const auto dash = rest.find('-');
    if (dash == std::string::npos) return isTempRandom(rest);
    if (dash == 0 || dash > 9) return false; // a process id has at most 7 digits (pid_max ≤ 2²²)
    for (std::size_t i = 0; i < dash; ++i) {
        if (rest[i] < '0' || rest[i] > '9') return false;
        pid = pid * 10 + (rest[i] - '0');
    }
    return pid > 0 && isTempRandom(rest.substr(dash + 1));
}

bool processIsGone(pid_t pid) {
    return pid > 0 && ::kill(pid, 0) != 0 && errno == ESRCH;
}

// Removes temporary files of target that no living writer holds: at once when the process that made
// them is gone, else once they are not brand new.
void removeStaleTemps(const std::string& target) {
    const std::string folder = folderOf(target), base = nameOf(target);
    DIR* dir = ::opendir(folder.c_str());
    if (!dir) return;
    const std::time_t now = std::time(nullptr);
    while (const dirent* entry = ::readdir(dir)) {
        const std::string name = entry->d_name;
        pid_t pid = 0;
        if (!isTempName(name, base, pid)) continue;
        const std::string path = folder + "/" + name;
        struct stat st {};
        if (::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
        if (!processIsGone(pid) && now - st.st_mtime < kStaleSeconds) continue;
        const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
        if (fd < 0) continue;
        if (::flock(fd, LOCK_EX | LOCK_NB) == 0) ::unlink(path.c_str());
        ::close(fd);
    }
    ::closedir(dir);
}

// A new temporary file beside target, locked; returns its descriptor and fills temp, or throws.
int createTemp(const std::string& path, const std::string& target, std::string& temp) {
    temp = target + kTempMark + std::to_string(::getpid()) + "-" + std::string(kTempRandom, 'X');
    const int fd = ::mkstemp(temp.data());
    if (fd < 0) throw FileError("cannot write '" + path + "': " + systemReason());
    ::flock(fd, LOCK_EX);
    return fd;
}

// What a path names once written: the device and inode of the file there (through links), or, for a file
// not there yet, its folder after links and its name.
struct FileIdentity {
    bool exists = false;
    dev_t device = 0;
    ino_t inode = 0;
    std::string where;
};

FileIdentity identityOf(const std::string& path) {
    std::string target = path;
    try {
        target = outputTarget(path);
    } catch (const FileError&) {
        // not a regular file, or a link that cannot be followed: compared as it is
    }
    struct stat st {};
    if (::stat(target.c_str(), &st) == 0) return {true, st.st_dev, st.st_ino, {}};
    std::error_code error;
    std::filesystem::path folder = std::filesystem::absolute(folderOf(target), error);
    if (std::filesystem::path resolved = std::filesystem::weakly_canonical(folder, error); !error)
        folder = std::move(resolved);
    return {false, 0, 0, (folder / nameOf(target)).lexically_normal().string()};
}

} // namespace

bool sameFile(const std::string& a, const std::string& b) {
    const FileIdentity x = identityOf(a), y = identityOf(b);
    if (x.exists != y.exists) return false;
    return x.exists ? x.device == y.device && x.inode == y.inode : x.where == y.where;
}

std::string outputTarget(const std::string& path) {
    if (path.empty()) throw FileError("cannot write a file without a name");
    std::string current = path;
    for (int hop = 0; hop < kMaxLinkHops; ++hop) {
        struct stat st {};
        if (::lstat(current.c_str(), &st) != 0) {
            if (errno == ENOENT) return current; // a new file (or the missing target of a link)
            throw FileError("cannot write '" + path + "': " + systemReason());
        }
        if (S_ISREG(st.st_mode)) return current;
        if (!S_ISLNK(st.st_mode))
            throw FileError("will not write '" + path + "': " + (current == path ? "it" : current) + " is " +
                            kindOf(st.st_mode) + ", and only regular files are written");
        std::string link(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 4096) + 1, '\0');
        const ssize_t n = ::readlink(current.c_str(), link.data(), link.size());
        if (n < 0) throw FileError("cannot write '" + path + "': " + systemReason());
        link.resize(static_cast<std::size_t>(n));
        current = link.front() == '/' ? link : folderOf(current) + "/" + link;
    }
    throw FileError("cannot write '" + path + "': too many levels of symbolic links");
}

void checkOutputPath(const std::string& path) {
    const std::string target = outputTarget(path);
    removeStaleTemps(target);
    if (::access(target.c_str(), F_OK) == 0 && ::access(target.c_str(), W_OK) != 0)
        throw FileError("cannot write '" + path + "': " + systemReason());
    std::string temp;
    const int fd = createTemp(path, target, temp);
    ::close(fd);
    ::unlink(temp.c_str());
}

void writePiecesAtomically(const std::string& path, const std::function<void(const PieceSink&)>& produce) {
    const std::string target = outputTarget(path);
    removeStaleTemps(target);
    struct stat existing {};
    const bool replaces = ::stat(target.c_str(), &existing) == 0;
    std::string temp;
    const int fd = createTemp(path, target, temp);
    bool removed = false;
    auto fail = [&](const std::string& what) {
        const std::string reason = systemReason();
        ::close(fd);
        ::unlink(temp.c_str());
        removed = true;
        throw FileError(what + " '" + path + "': " + reason);
    };
    const PieceSink write = [&](std::string_view piece) {
        std::size_t written = 0;
        while (written < piece.size()) {
            const ssize_t n = ::write(fd, piece.data() + written, piece.size() - written);
            if (n < 0) {
                if (errno == EINTR) continue;
                fail("cannot write");
            }
            written += static_cast<std::size_t>(n);
        }
    };
    try {
        produce(write);
    } catch (...) { // out of memory while formatting, say: no half-written file stays behind
        if (!removed) {
            ::close(fd);
            ::unlink(temp.c_str());
        }
        throw;
    }
    // mkstemp creates 0600: the file keeps the permissions of the one it replaces, or gets the usual.
    mode_t mode = existing.st_mode & 07777;
    if (!replaces) {
        mode = ::umask(0);
        ::umask(mode);
        mode = 0666 & ~mode;
    }
    if (::fchmod(fd, mode) != 0 || ::fsync(fd) != 0) fail("cannot write");
    if (::rename(temp.c_str(), target.c_str()) != 0) fail("cannot replace");
    ::close(fd); // held until here: the lock tells cleaners the temporary file is alive
    syncFolder(folderOf(target));
}

void writeFileAtomically(const std::string& path, std::string_view content) {
    writePiecesAtomically(path, [&](const PieceSink& write) { write(content); });
}

FileReader::FileReader(const std::string& path) : path_(path) {
    // O_NONBLOCK: a FIFO opens at once instead of waiting for a writer, and is refused below.
    fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd_ < 0) throw FileError("cannot open '" + path + "': " + systemReason());
    struct stat st {};
    std::string why;
    if (::fstat(fd_, &st) != 0)
        why = "cannot read '" + path + "': " + systemReason();
    else if (!S_ISREG(st.st_mode))
        why =
            "will not read '" + path + "': it is " + kindOf(st.st_mode) + ", and only regular files are read";
    if (!why.empty()) {
        ::close(fd_);
        throw FileError(why);
    }
    size_ = static_cast<std::size_t>(st.st_size);
}

FileReader::~FileReader() {
    ::close(fd_);
}

std::size_t FileReader::read(char* buffer, std::size_t n) {
    for (;;) {
        const ssize_t got = ::read(fd_, buffer, n);
        if (got >= 0) return static_cast<std::size_t>(got);
        if (errno != EINTR) throw FileError("cannot read '" + path_ + "': " + systemReason());
    }
}

std::string readWholeFile(const std::string& path, std::size_t maxBytes, const std::string& what) {
    FileReader file(path);
    const auto tooLarge = [&](std::size_t size) {
        throw FileError("will not read '" + path + "': it holds " + byteSize(size) + ", more than the " +
                        byteSize(maxBytes) + " that " + what + " may hold");
    };
    if (file.size() > maxBytes) tooLarge(file.size());
    std::string text;
    text.reserve(file.size());
    char buffer[1 << 16];
    while (const std::size_t n = file.read(buffer, sizeof buffer)) {
        text.append(buffer, n);
        if (text.size() > maxBytes) tooLarge(text.size()); // it grew since fstat, or says no size (/proc)
    }
    return text;
}

StreamedFile::StreamedFile(const std::string& path) : path_(path) {
    const std::string target = outputTarget(path);
    // O_NONBLOCK: a FIFO put there since the check fails at once instead of waiting for a reader.
    fd_ = ::open(target.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ < 0) throw FileError("cannot write '" + path + "': " + systemReason());
    struct stat st {};
    if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd_);
        fd_ = -1;
        throw FileError("will not write '" + path + "': it is " + kindOf(st.st_mode) +
                        ", and only regular files are written");
    }
    ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
}

StreamedFile::~StreamedFile() {
    if (fd_ >= 0) ::close(fd_);
}

void StreamedFile::write(std::string_view text) {
    if (fd_ < 0) throw FileError("cannot write '" + path_ + "': the file is closed");
    std::size_t written = 0;
    while (written < text.size()) {
        const ssize_t n = ::write(fd_, text.data() + written, text.size() - written);
        if (n < 0) {
            if (errno == EINTR) continue;
            const std::string reason = systemReason();
            // A piece that did not fit (a full disk) is taken back whole: the file ends with the last
            // whole piece (a row), never half of one. Shortening needs no space, so it works on a full disk.
            if (written > 0 && ::ftruncate(fd_, static_cast<off_t>(size_)) == 0)
                ::lseek(fd_, static_cast<off_t>(size_), SEEK_SET);
            throw FileError("cannot write '" + path_ + "': " + reason);
        }
        written += static_cast<std::size_t>(n);
    }
    size_ += written;
}

void StreamedFile::close() {
    if (fd_ < 0) return;
    const int fd = fd_;
    fd_ = -1;
    if (::fsync(fd) != 0 && errno != EINVAL) {
        const std::string reason = systemReason();
        ::close(fd);
        throw FileError("cannot write '" + path_ + "': " + reason);
    }
    if (::close(fd) != 0) throw FileError("cannot write '" + path_ + "': " + systemReason());
}

} // namespace pl
