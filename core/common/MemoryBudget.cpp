#include "MemoryBudget.h"

#include "InputLimits.h"
#include "ParamSpec.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <sys/resource.h>
#include <unistd.h>

namespace pl {

namespace {

// A "Name:   123 kB" line of a /proc file, in bytes; NaN when the file or the line is missing.
double procKilobytes(const char* file, const std::string& name) {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        if (line.compare(0, name.size() + 1, name + ":") != 0) continue;
        std::istringstream fields(line.substr(name.size() + 1));
        double kilobytes = 0.0;
        if (fields >> kilobytes) return kilobytes * 1024.0;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

// The room under a resource limit above what is used of it already; infinite when unlimited.
double roomUnder(int resource, double used) {
    rlimit limit{};
    if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
        return std::numeric_limits<double>::infinity();
    return std::max(0.0, static_cast<double>(limit.rlim_cur) - (std::isnan(used) ? 0.0 : used));
}

double assumedBytes = std::numeric_limits<double>::quiet_NaN(); // NaN: ask the machine

} // namespace

AssumedMemory::AssumedMemory(double bytes) {
    assumedBytes = bytes;
}

AssumedMemory::~AssumedMemory() {
    assumedBytes = std::numeric_limits<double>::quiet_NaN();
}

double availableMemoryBytes() {
    if (!std::isnan(assumedBytes)) return assumedBytes;
    double available = procKilobytes("/proc/meminfo", "MemAvailable");
    if (std::isnan(available)) // not Linux, or a kernel before 3.14: the physical memory
        available = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGESIZE));
    available = std::min(available, roomUnder(RLIMIT_AS, procKilobytes("/proc/self/status", "VmSize")));
    return std::min(available, roomUnder(RLIMIT_DATA, procKilobytes("/proc/self/status", "VmData")));
}

void requireMemory(const MemoryNeed& need) {
    const double usable = kUsableMemoryShare * availableMemoryBytes();
    if (!(need.bytes > usable)) return;
    const auto bytes = [](double b) { // a need can be far beyond any size_t (1e30 bytes of a huge count)
        return byteSize(b >= static_cast<double>(SIZE_MAX) ? SIZE_MAX
                                                           : static_cast<std::size_t>(std::max(0.0, b)));
    };
    throw ParamError(need.key, "{" + need.key + "} lets the run hold about " + bytes(need.bytes) +
                                   " of memory, more than the " + bytes(usable) +
                                   " this machine can give it now; " + need.fix(usable));
}

namespace {
double usableForSnapshots(double freedBytes) {
    return kUsableMemoryShare * std::max(0.0, availableMemoryBytes() + freedBytes);
}
} // namespace

std::size_t snapshotReadBound(double freedBytes) {
    const double bound = usableForSnapshots(freedBytes) / kSnapshotReadMemoryPerFileByte;
    return bound >= static_cast<double>(SIZE_MAX) ? SIZE_MAX : static_cast<std::size_t>(bound);
}

std::string snapshotBoundReason(double freedBytes) {
    char share[32];
    std::snprintf(share, sizeof share, "%.2g", kSnapshotReadMemoryPerFileByte);
    return std::string("reading a snapshot holds about ") + share +
           " bytes of memory per byte of file, and this machine can give " +
           byteSize(static_cast<std::size_t>(usableForSnapshots(freedBytes))) + " now, " +
           std::to_string(static_cast<int>(kUsableMemoryShare * 100)) + " % of what is available";
}

double residentMemoryBytes() {
    const double resident = procKilobytes("/proc/self/status", "VmRSS");
    return std::isnan(resident) ? 0.0 : resident;
}

} // namespace pl
