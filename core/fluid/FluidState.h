// The fluid particles as a structure of arrays (unit masses): positions and velocities.
#pragma once

#include <vector>

namespace pl {

struct FluidState {
    std::vector<double> x, y;   // positions at the start of a step [L]
    std::vector<double> vx, vy; // velocities [L/s]

    std::size_t size() const { return x.size(); }
    void clear() {
        x.clear();
        y.clear();
        vx.clear();
        vy.clear();
    }
    void append(double px, double py, double pvx, double pvy) {
        x.push_back(px);
        y.push_back(py);
        vx.push_back(pvx);
        vy.push_back(pvy);
    }
    // Keeps the particles whose keep[i] is true, in order.
    void compact(const std::vector<char>& keep) {
        std::size_t n = 0;
        for (std::size_t i = 0; i < size(); ++i) {
            if (!keep[i]) continue;
            x[n] = x[i];
            y[n] = y[i];
            vx[n] = vx[i];
            vy[n] = vy[i];
            ++n;
        }
        x.resize(n);
        y.resize(n);
        vx.resize(n);
        vy.resize(n);
    }
};

} // namespace pl
