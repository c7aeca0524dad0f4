// Validators for CLI11: strict whole numbers and reals with short bounds in their messages.
#include "OptionChecks.h"

#include "common/AtomicFile.h"
#include "common/ParamSpec.h"

#include <charconv>
#include <cmath>
#include <omp.h>

namespace pl::cli {

bool parseStrictNumber(const std::string& text, double& value) {
    const char* begin = text.data();
    const char* end = begin + text.size();
    if (begin != end && *begin == '+') ++begin; // from_chars reads '-' but not '+'
    if (begin == end || *begin == '+' || (*begin == '-' && begin + 1 == end)) return false;
    const auto [stop, error] = std::from_chars(begin, end, value, std::chars_format::general);
    return error == std::errc() && stop == end;
}

namespace {
// The value as typed, cut short: a 309-digit number is not repeated back.
std::string echoed(const std::string& text) {
    return text.size() <= 24
               ? "\"" + text + "\""
               : "\"" + text.substr(0, 20) + "…\" (" + std::to_string(text.size()) + " characters)";
}
} // namespace

int maxThreads() {
    return 4 * std::max(1, omp_get_num_procs());
}

CLI::Validator wholeNumber(long long lo, long long hi, const std::string& why) {
    const std::string range = std::to_string(lo) + " to " + std::to_string(hi);
    const std::string reason = why.empty() ? "" : " (" + why + ")";
    return CLI::Validator(
        [lo, hi, range, reason](std::string& text) -> std::string {
            long long whole = 0;
            const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), whole);
            bool inRange = false;
            if (stop == text.data() + text.size() && error == std::errc()) { // digits
                inRange = whole >= lo && whole <= hi;
            } else if (error != std::errc::result_out_of_range) { // "2e4"
                double value = 0;
                if (!parseStrictNumber(text, value) || !std::isfinite(value) || value != std::floor(value))
                    return "must be a whole number from " + range + ", got " + echoed(text);
                // 2⁶³ itself would not fit: the comparison against hi is strict at the top.
                inRange =
                    value >= static_cast<double>(lo) && value < 0x1p63 && static_cast<long long>(value) <= hi;
                if (inRange) whole = static_cast<long long>(value);
            }
            if (!inRange) return "must be from " + range + ", got " + echoed(text) + reason;
            text = std::to_string(whole);
            return {};
        },
        "INT in " + std::to_string(lo) + "…" + std::to_string(hi));
}

CLI::Validator positiveReal(bool zeroAllowed, double most) {
    const bool bounded = std::isfinite(most);
    return CLI::Validator(
        [zeroAllowed, most, bounded](std::string& text) -> std::string {
            double value = 0;
            const std::string wanted =
                std::string(zeroAllowed ? "a finite number of at least 0" : "a finite number above 0") +
                (bounded ? " and at most " + formatNumber(most) : "");
            if (!parseStrictNumber(text, value) || !std::isfinite(value) || value < 0 ||
                (!zeroAllowed && value == 0) || value > most)
                return "must be " + wanted + ", got " + echoed(text);
            return {};
        },
        std::string(zeroAllowed ? "NUMBER ≥ 0" : "NUMBER > 0") +
            (bounded ? ", ≤ " + formatNumber(most) : ""));
}

CLI::Validator fileName() {
    return CLI::Validator(
        [](std::string& text) -> std::string { return text.empty() ? "needs a file name, got \"\"" : ""; },
        "FILE");
}

CLI::Validator threadCount() {
    return wholeNumber(1, maxThreads(),
                       "at most 4 × the " + std::to_string(omp_get_num_procs()) +
                           " cores of this machine: more threads only wait for each other and can "
                           "exhaust what the system allows");
}

std::string sharedFileRefusal(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs) {
    const auto shown = [](const NamedFile& a, const NamedFile& b) {
        return a.path == b.path ? "'" + a.path + "'"
                                : "'" + a.path + "' and '" + b.path + "', which are one file";
    };
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const NamedFile& out = outputs[i];
        if (out.path.empty()) continue;
        for (const NamedFile& in : inputs)
            if (!in.path.empty() && sameFile(out.path, in.path))
                return out.option + " and " + in.option + " name " + shown(out, in) +
                       ": the output would replace what the run reads; write it to another file";
        for (std::size_t j = 0; j < i; ++j)
            if (!outputs[j].path.empty() && sameFile(outputs[j].path, out.path))
                return outputs[j].option + " and " + out.option + " name " + shown(outputs[j], out) +
                       ": one output would replace the other; give each a file of its own";
    }
    return {};
}

} // namespace pl::cli
