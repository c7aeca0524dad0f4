// The particles of the wind tunnel as a structure of arrays: position in the plane, three velocity
// components, and the cell each one was last sorted into.
#pragma once

#include "dsmc/DsmcKernels.h"

#include <cstdint>
#include <vector>

namespace pl {

struct TunnelState {
    std::vector<double> x, y;        // [m]
    std::vector<double> vx, vy, vz;  // [m/s]
    std::vector<std::uint32_t> cell; // j · cellsX + i after the last sort

    std::size_t size() const { return x.size(); }
    dsmc::Velocity velocity(std::size_t i) const { return {vx[i], vy[i], vz[i]}; }
    void setVelocity(std::size_t i, const dsmc::Velocity& v) {
        vx[i] = v.x;
        vy[i] = v.y;
        vz[i] = v.z;
    }
    void append(double px, double py, const dsmc::Velocity& v) {
        x.push_back(px);
        y.push_back(py);
        vx.push_back(v.x);
        vy.push_back(v.y);
        vz.push_back(v.z);
        cell.push_back(0);
    }
    // Removes particle i by moving the last one into its place (order is not kept).
    void removeSwap(std::size_t i) {
        const std::size_t last = size() - 1;
        x[i] = x[last], y[i] = y[last], vx[i] = vx[last], vy[i] = vy[last], vz[i] = vz[last];
        cell[i] = cell[last];
        x.pop_back(), y.pop_back(), vx.pop_back(), vy.pop_back(), vz.pop_back(), cell.pop_back();
    }
    void clear() { x.clear(), y.clear(), vx.clear(), vy.clear(), vz.clear(), cell.clear(); }
};

} // namespace pl
