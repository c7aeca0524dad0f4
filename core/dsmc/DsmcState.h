// The particles of a DSMC cell as a structure of arrays: three velocity components (DSMC needs them even
// in a 0D cell) and the population each particle started in.
#pragma once

#include "DsmcKernels.h"

#include <cstdint>
#include <vector>

namespace pl {

struct DsmcState {
    std::vector<double> vx, vy, vz;   // [m/s]
    std::vector<std::uint8_t> origin; // 0: beam 1 (or the single gas), 1: beam 2

    std::size_t size() const { return vx.size(); }
    dsmc::Velocity velocity(std::size_t i) const { return {vx[i], vy[i], vz[i]}; }
    void setVelocity(std::size_t i, const dsmc::Velocity& v) {
        vx[i] = v.x;
        vy[i] = v.y;
        vz[i] = v.z;
    }
    void clear() {
        vx.clear();
        vy.clear();
        vz.clear();
        origin.clear();
    }
    void append(const dsmc::Velocity& v, std::uint8_t from) {
        vx.push_back(v.x);
        vy.push_back(v.y);
        vz.push_back(v.z);
        origin.push_back(from);
    }
};

} // namespace pl
