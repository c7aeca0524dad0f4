// The memory a run may come to hold, estimated from its parameters before anything is built, against
// what the machine can give the process now: a run that cannot fit is refused with the parameter that
// decides its size and a value that fits, instead of ending in an allocation failure half way (or, with
// overcommit, in the kernel's out-of-memory killer). docs/architecture.md, "Bounds before the run".
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace pl {

struct MemoryNeed {
    double bytes = 0.0; // the most the model's state can hold [B]
    std::string key;    // the parameter that decides it
    // The sentence's advice for a run that must fit in the given bytes ("use {max_particles} ≤ 120000").
    std::function<std::string(double fittingBytes)> fix;
};

// [B] what this process may still allocate: the smaller of the machine's available memory
// (/proc/meminfo MemAvailable) and the room under its address-space and data limits (RLIMIT_AS,
// RLIMIT_DATA) above what it maps already.
double availableMemoryBytes();

// While one lives, availableMemoryBytes() answers `bytes` instead of asking the machine: what a refusal
// says then depends on its input alone (the catalogue of the UI's translated sentences is made under
// one, so it is the same on every machine). Not nested, not across threads.
class AssumedMemory {
public:
    explicit AssumedMemory(double bytes);
    ~AssumedMemory();
    AssumedMemory(const AssumedMemory&) = delete;
    AssumedMemory& operator=(const AssumedMemory&) = delete;
};

// Throws ParamError(need.key) when need.bytes is more than availableMemoryBytes() allows, naming both and
// the fix. The share of the available memory a run may plan for leaves room for the program itself,
// the plots and the outputs.
void requireMemory(const MemoryNeed& need);
constexpr double kUsableMemoryShare = 0.8;

// [B of memory per B of file] what reading a snapshot holds at its peak per byte of its file: the
// state's numbers as doubles, 8 bytes for the 19 characters a number takes on average (the text itself
// is never held whole). Measured: 0.41 for a tunnel of 10⁷ molecules (a 913 MiB file of 49.6 M
// numbers, 394 MB at the peak); the rest is room for the first array's growth and for states of
// shorter numbers. A file of many more numbers for its size (hand-made, "0,0,0…") is stopped by the
// reader itself before its arrays hold more than the machine can give (SnapshotJson.h).
constexpr double kSnapshotReadMemoryPerFileByte = 0.5;
// [B] the largest snapshot file this process can read now: the usable share of availableMemoryBytes()
// (plus freedBytes, memory the caller holds that a later reader would have) over
// kSnapshotReadMemoryPerFileByte. The same rule that lets a run start bounds what it writes, so a file
// written here reads back on this machine unless its memory is taken by something else.
std::size_t snapshotReadBound(double freedBytes = 0.0);
// Why the bound is what it is, for refusals: "reading a snapshot holds about 0.5 bytes of memory per
// byte of file, and this machine can give 12 GiB now, 80 % of what is available".
std::string snapshotBoundReason(double freedBytes = 0.0);
// [B] the memory this process holds now (its resident set), or 0 where that is not known.
double residentMemoryBytes();

} // namespace pl
