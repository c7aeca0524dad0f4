// "Recommend": the cheapest measured setting whose error meets the user's target, from any sweep's
// points. Only settings that ran to the end and whose error was measured are candidates.
#pragma once

#include "common/ParamSpec.h"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace pl::methods {

struct Candidate {
    std::string label;   // what the user reads: "velocity-verlet, dt = 7e-4"
    ParamValues setting; // what Apply sets on the experiment
    double error = 0;    // in the sweep's error measure
    double cost = 0;     // measured wall time per unit of simulated time (or per run)
};

inline std::optional<Candidate> cheapestWithin(const std::vector<Candidate>& candidates, double target) {
    std::optional<Candidate> best;
    for (const Candidate& c : candidates) {
        if (!std::isfinite(c.error) || !std::isfinite(c.cost) || c.error > target) continue;
        if (!best || c.cost < best->cost) best = c;
    }
    return best;
}

} // namespace pl::methods
