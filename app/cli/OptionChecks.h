// Strict checks of the command line's numbers and paths, so every bad value is refused with a plain
// sentence (and exit code 2) before anything runs.
#pragma once

#include <CLI/CLI.hpp>

#include <limits>
#include <string>
#include <vector>

namespace pl::cli {

// The longest run or sweep the CLI starts: 10⁹ steps are days of computing even for a small scene.
constexpr long long kMaxSteps = 1'000'000'000;

// A whole number in [lo, hi], written in digits or as an exact power notation ("20000", "2e4"); the
// value is rewritten in digits for CLI11. why says where the bounds come from.
CLI::Validator wholeNumber(long long lo, long long hi, const std::string& why = "");
// A finite number above 0 (or at least 0 when zeroAllowed), and at most most; no spaces, no hexadecimal.
CLI::Validator positiveReal(bool zeroAllowed = false, double most = std::numeric_limits<double>::infinity());
// A file name that is not empty.
CLI::Validator fileName();
// Threads for OpenMP: 1 … 4 × the cores of this machine.
CLI::Validator threadCount();
int maxThreads();

// An option and the file it names: {"--out", "s.csv"}; an input too: {"the input", "mine.json"}.
struct NamedFile {
    std::string option;
    std::string path; // empty: not given, skipped
};
// One sentence when two outputs name one file (pl::sameFile: through symbolic or hard links, or the same
// name in the same folder for a file not there yet), or an output names one of the inputs; empty when each
// output has a file of its own. Checked before anything runs or is written (bad input, exit 2).
std::string sharedFileRefusal(const std::vector<NamedFile>& outputs,
                              const std::vector<NamedFile>& inputs = {});

// A strictly written finite or non-finite number: the whole text, decimal, optional sign and exponent.
// Returns false for anything else ("", " 1", "0x10", "1e", "5 ").
bool parseStrictNumber(const std::string& text, double& value);

} // namespace pl::cli
