// Force passes: the cell-list gather (default) and the seed's all-pairs loop, which agree to round-off.
#include "MdKernels.h"
#include "common/Parallel.h"
#include "MdModel.h"

#include <algorithm>

namespace pl {

namespace {

struct SpeciesTable {
    double diameter[2];
    double inverseMass[2];
};

SpeciesTable speciesTable(const MdParams& p) {
    return {{p.a.diameter, p.b.diameter}, {1.0 / p.a.mass, 1.0 / p.b.mass}};
}

} // namespace

void MdModel::computeForces(bool countContacts) {
    if (params_.forceMethod == "all-pairs") computeForcesAllPairs(countContacts);
    else computeForcesCellList(countContacts);
    forcesValid_ = true;
}

void MdModel::computeForcesCellList(bool countContacts) {
    MdState& s = state_;
    const std::size_t n = s.size();
    cells_.build(s.x.data(), s.y.data(), n);
    const auto& order = cells_.order();
    const auto& start = cells_.cellStart();
    const auto& cellOf = cells_.cellOfParticle();
    sortedX_.resize(n);
    sortedY_.resize(n);
    const auto count = static_cast<long long>(n);
    // Positions copied into cell order, so each neighbour row is one contiguous run of memory.
#pragma omp parallel for schedule(static) if(count >= kParallelMinParticles)
    for (long long k = 0; k < count; ++k) {
        sortedX_[k] = s.x[order[k]];
        sortedY_[k] = s.y[order[k]];
    }
    const SpeciesTable table = speciesTable(params_);
    const double stiffness = params_.stiffness;
    const double gravity = params_.gravity;
    const int nx = cells_.cellsX(), ny = cells_.cellsY();
    const std::uint8_t* species = s.species.data();

#pragma omp parallel for schedule(static) if(count >= kParallelMinParticles)
    for (long long k = 0; k < count; ++k) {
        const std::uint32_t i = order[k];
        const int cx = static_cast<int>(cellOf[i] % static_cast<std::uint32_t>(nx));
        const int cy = static_cast<int>(cellOf[i] / static_cast<std::uint32_t>(nx));
        const double xi = sortedX_[k], yi = sortedY_[k];
        const double di = table.diameter[species[i]];
        double fx = 0, fy = 0, potential = 0, virial = 0;
        std::uint32_t began = 0;
        const int x0 = std::max(cx - 1, 0), x1 = std::min(cx + 1, nx - 1);
        for (int row = std::max(cy - 1, 0); row <= std::min(cy + 1, ny - 1); ++row) {
            const std::uint32_t first = start[row * nx + x0], last = start[row * nx + x1 + 1];
            for (std::uint32_t kj = first; kj < last; ++kj) {
                if (kj == static_cast<std::uint32_t>(k)) continue;
                const std::uint32_t j = order[kj];
                const double dij = md::contactDiameter(di, table.diameter[species[j]]);
                md::PairResult pair;
                if (!md::harmonicPair(xi - sortedX_[kj], yi - sortedY_[kj], dij, stiffness, pair)) continue;
                fx += pair.fx;
                fy += pair.fy;
                potential += 0.5 * pair.potential; // each pair is visited from both ends
                virial += 0.25 * pair.virial;
                if (countContacts) {
                    const double px = xPrev_[i] - xPrev_[j], py = yPrev_[i] - yPrev_[j];
                    began += (px * px + py * py >= dij * dij) ? 1u : 0u;
                }
            }
        }
        const double invM = table.inverseMass[species[i]];
        s.ax[i] = fx * invM;
        s.ay[i] = fy * invM - gravity;
        s.potential[i] = potential;
        s.virial[i] = virial;
        s.contactsBegun[i] += began;
    }
}

void MdModel::computeForcesAllPairs(bool countContacts) {
    MdState& s = state_;
    const auto count = static_cast<long long>(s.size());
    const SpeciesTable table = speciesTable(params_);
    const double stiffness = params_.stiffness;
    const double gravity = params_.gravity;
#pragma omp parallel for schedule(static) if(count >= kParallelMinParticles)
    for (long long i = 0; i < count; ++i) {
        const double xi = s.x[i], yi = s.y[i];
        const double di = table.diameter[s.species[i]];
        double fx = 0, fy = 0, potential = 0, virial = 0;
        std::uint32_t began = 0;
        for (long long j = 0; j < count; ++j) {
            if (j == i) continue;
            const double dij = md::contactDiameter(di, table.diameter[s.species[j]]);
            md::PairResult pair;
            if (!md::harmonicPair(xi - s.x[j], yi - s.y[j], dij, stiffness, pair)) continue;
            fx += pair.fx;
            fy += pair.fy;
            potential += 0.5 * pair.potential;
            virial += 0.25 * pair.virial;
            if (countContacts) {
                const double px = xPrev_[i] - xPrev_[j], py = yPrev_[i] - yPrev_[j];
                began += (px * px + py * py >= dij * dij) ? 1u : 0u;
            }
        }
        const double invM = table.inverseMass[s.species[i]];
        s.ax[i] = fx * invM;
        s.ay[i] = fy * invM - gravity;
        s.potential[i] = potential;
        s.virial[i] = virial;
        s.contactsBegun[i] += began;
    }
}

} // namespace pl
