// One cell of a methods-lab sweep or stability map: how it ended, and the runner that isolates it, so a
// blow-up, a rejected parameter or a failed allocation in one cell is classified and drawn while the
// sweep goes on to the next.
#pragma once

#include <chrono>
#include <exception>
#include <new>
#include <string>

namespace pl::methods {

enum class CellOutcome {
    Stable,         // ran to the end within the error tolerance
    Inaccurate,     // ran to the end, error above the tolerance
    Unstable,       // blew up: energy growth, a disk escaping the box, NaN (the model's checks caught it)
    OverCompressed, // the fluid ran but its density error exceeded the tolerance
    Exploded,       // the fluid diverged
    Rejected,       // did not run: invalid parameters, or no memory for it
};

inline const char* outcomeName(CellOutcome outcome) {
    switch (outcome) {
    case CellOutcome::Stable:
        return "stable";
    case CellOutcome::Inaccurate:
        return "inaccurate";
    case CellOutcome::Unstable:
        return "unstable";
    case CellOutcome::OverCompressed:
        return "over-compressed";
    case CellOutcome::Exploded:
        return "exploded";
    case CellOutcome::Rejected:
        return "rejected";
    }
    return "?";
}

// Wall time of body() in seconds: a sweep times its steps only, not its set-up or its measurements.
template <class Body> double secondsOf(Body&& body) {
    const auto start = std::chrono::steady_clock::now();
    body();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// What every cell reports besides its own measurements.
struct CellStatus {
    CellOutcome outcome = CellOutcome::Rejected;
    std::string detail;  // the model's failure message or the exception's, empty when it ran cleanly
    double seconds = 0;  // wall time of the cell
    long long steps = 0; // steps taken before it ended
};

// Runs body(status) and catches whatever escapes it: a cell never takes the sweep down. The body sets the
// outcome and steps; the runner times it.
template <class Body> CellStatus runIsolated(Body&& body) {
    CellStatus status;
    status.seconds = secondsOf([&] {
        try {
            body(status);
        } catch (const std::bad_alloc&) {
            status.outcome = CellOutcome::Rejected;
            status.detail = "not enough memory for this cell";
        } catch (const std::exception& e) {
            status.outcome = CellOutcome::Rejected;
            status.detail = e.what();
        } catch (...) {
            status.outcome = CellOutcome::Rejected;
            status.detail = "an unknown error stopped this cell";
        }
    });
    return status;
}

} // namespace pl::methods
