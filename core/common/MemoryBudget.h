// The memory a run may come to hold, estimated from its parameters before anything is built, against
// what the machine can give the process now: a run that cannot fit is refused with the parameter that
// decides its size and a value that fits, instead of ending in an allocation failure half way (or, with
// overcommit, in the kernel's out-of-memory killer). docs/architecture.md, "Bounds before the run".
#pragma once

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

} // namespace pl
