// State of the gas as a structure of arrays, so CPU loops vectorise and GPU buffers map one to one.
#pragma once

#include <cstdint>
#include <vector>

namespace pl {

struct GasState {
    std::vector<double> x, y;          // position [L]
    std::vector<double> vx, vy;        // velocity [L/T]
    std::vector<double> ax, ay;        // acceleration at the current positions [L/T²]
    std::vector<std::uint8_t> species; // 0 = A, 1 = B
    std::vector<std::uint32_t> id;     // stable identity: random streams and dumps follow it

    // Per-particle accumulators written in gather form (each loop iteration writes only particle i),
    // summed serially so that totals do not depend on the thread count.
    std::vector<double> potential; // ½ Σ_j U(r_ij) at the last force evaluation [energy]
    std::vector<double> virial;    // ¼ Σ_j r_ij·f_ij: summed over i gives ½ Σ_{i<j} r_ij·f_ij [energy]
    std::vector<double> wallImpulse; // normal momentum given to the walls since the last sample [M·L/T]
    std::vector<std::uint32_t> contactsBegun; // contacts entered since the last sample (each pair twice)

    std::size_t size() const { return x.size(); }
    void resize(std::size_t n);
    void append(double px, double py, double pvx, double pvy, std::uint8_t s, std::uint32_t pid);
    // Reorders the particles: new particle n is old particle newToOld[n].
    void permute(const std::vector<std::uint32_t>& newToOld);
    // Keeps the particles for which keep(i) is true, preserving order.
    template <class Keep> std::size_t retain(Keep keep);
};

template <class Keep> std::size_t GasState::retain(Keep keep) {
    std::size_t out = 0;
    const std::size_t n = size();
    for (std::size_t i = 0; i < n; ++i) {
        if (!keep(i)) continue;
        x[out] = x[i], y[out] = y[i], vx[out] = vx[i], vy[out] = vy[i], ax[out] = ax[i], ay[out] = ay[i];
        species[out] = species[i], id[out] = id[i], potential[out] = potential[i], virial[out] = virial[i];
        wallImpulse[out] = wallImpulse[i], contactsBegun[out] = contactsBegun[i];
        ++out;
    }
    const std::size_t removed = n - out;
    resize(out);
    return removed;
}

} // namespace pl
