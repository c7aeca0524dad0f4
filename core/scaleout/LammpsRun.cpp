// The child process runs in its own process group, so that a cancel reaches mpirun and every rank it
// started; its output is read through poll() so that a cancel acts while LAMMPS prints nothing.
#include "LammpsRun.h"

#include "LammpsDeck.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <poll.h>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace pl::scaleout {

namespace {

constexpr int kPollMs = 100;           // how soon a cancel acts
constexpr std::size_t kKeptLines = 12; // of LAMMPS's output, for the failure message
constexpr int kExecFailed = 127;       // the shell's "command not found"

bool onPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "");
    for (std::string d; std::getline(dirs, d, ':');)
        if (!d.empty() && ::access((std::filesystem::path(d) / program).c_str(), X_OK) == 0) return true;
    return false;
}

// A thermo row starts with the step and has more numbers after it.
bool thermoStep(const std::string& line, long long& step) {
    std::istringstream words(line);
    std::string rest;
    return (words >> step) && (words >> rest) &&
           rest.find_first_not_of("0123456789.eE+-") == std::string::npos;
}

} // namespace

std::string missingLammpsProgram() {
    for (const char* program : {"lmp", "mpirun"})
        if (!onPath(program)) return program;
    return {};
}

LammpsRunResult runLammps(const std::string& dir, int ranks, const std::function<void(long long)>& onStep,
                          const std::function<bool()>& cancelled) {
    // Open MPI refuses root and more ranks than cores unless told; both are fine for this one job.
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 0);
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 0);
    ::setenv("OMPI_MCA_rmaps_base_oversubscribe", "1", 0);
    const std::string np = std::to_string(ranks);
    int pipeEnds[2];
    if (::pipe(pipeEnds) != 0) return {-1, false, "cannot create a pipe for LAMMPS's output"};
    const pid_t child = ::fork();
    if (child < 0) {
        ::close(pipeEnds[0]);
        ::close(pipeEnds[1]);
        return {-1, false, "cannot start mpirun"};
    }
    if (child == 0) { // only async-signal-safe calls until exec
        ::setpgid(0, 0);
        ::dup2(pipeEnds[1], STDOUT_FILENO);
        ::dup2(pipeEnds[1], STDERR_FILENO);
        ::close(pipeEnds[0]);
        ::close(pipeEnds[1]);
        if (::chdir(dir.c_str()) == 0)
            ::execlp("mpirun", "mpirun", "-np", np.c_str(), "lmp", "-in", kLammpsInput, "-log", kLammpsLog,
                     static_cast<char*>(nullptr));
        ::_exit(kExecFailed);
    }
    ::setpgid(child, child); // also here: whichever runs first, the group exists before a cancel
    ::close(pipeEnds[1]);

    LammpsRunResult result;
    std::deque<std::string> last;
    std::string pending;
    char buffer[4096];
    pollfd output{pipeEnds[0], POLLIN, 0};
    for (;;) {
        if (!result.cancelled && cancelled && cancelled()) {
            result.cancelled = true;
            ::kill(-child, SIGTERM);
        }
        const int ready = ::poll(&output, 1, kPollMs);
        if (ready == 0 || (ready < 0 && errno == EINTR)) continue;
        if (ready < 0) break;
        const ssize_t got = ::read(pipeEnds[0], buffer, sizeof buffer);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) break; // every writer closed the pipe: LAMMPS is done
        pending.append(buffer, static_cast<std::size_t>(got));
        for (std::size_t end; (end = pending.find('\n')) != std::string::npos;) {
            std::string line = pending.substr(0, end + 1);
            pending.erase(0, end + 1);
            long long step = 0;
            if (onStep && thermoStep(line, step)) onStep(step);
            last.push_back(std::move(line));
            if (last.size() > kKeptLines) last.pop_front();
        }
    }
    ::close(pipeEnds[0]);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    result.status =
        WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    for (const auto& line : last) result.lastOutput += line;
    result.lastOutput += pending;
    return result;
}

} // namespace pl::scaleout
