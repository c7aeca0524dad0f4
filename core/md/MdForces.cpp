// Force passes: Verlet neighbour lists built from the cell list (default) and the seed's all-pairs loop;
// both give the same forces to round-off. Gather form: iteration i writes only particle i.
#include "MdKernels.h"
#include "MdModel.h"
#include "common/Parallel.h"

#include <algorithm>

namespace pl {

namespace {

// Neighbour-list skin as a fraction of the largest diameter. A dilute gas has so few neighbours that a
// wide skin costs little in the force loop and saves rebuilds (measured: BENCHMARKS.md).
constexpr double kSkinOverDiameter = 1.0;

struct SpeciesTable {
    double diameter[2];
    double inverseMass[2];
};

SpeciesTable speciesTable(const MdParams& p) {
    return {{p.a.diameter, p.b.diameter}, {1.0 / p.a.mass, 1.0 / p.b.mass}};
}

} // namespace

void MdModel::computeForces(Contacts contacts, double kickAfter, bool energies) {
    if (params_.forceMethod == "all-pairs") {
        computeForcesAllPairs(contacts, kickAfter);
        energies = true; // the comparison path always fills them
    } else {
        const auto n = state_.size();
        const bool rebuild = maxDisplacement2_ >= 0.0
                                 ? neighbours_.needsRebuild(maxDisplacement2_)
                                 : neighbours_.needsRebuild(state_.x.data(), state_.y.data(), n);
        if (rebuild) {
            const double d = params_.maxDiameter();
            neighbours_.build(state_.x.data(), state_.y.data(), n, d, kSkinOverDiameter * d, params_.left(),
                              params_.bottom(), 0.5 * params_.boxWidth, params_.top());
        }
        computeForcesNeighbourList(contacts, kickAfter, energies);
    }
    maxDisplacement2_ = -1.0;
    forcesValid_ = true;
    energiesValid_ = energies;
}

void MdModel::refreshEnergies() {
    ensureForces();
    // Forces at unchanged positions come out bit-identical, so recomputing them here is harmless.
    if (!energiesValid_) computeForces(Contacts::Ignore, 0.0, true);
}

void MdModel::computeForcesNeighbourList(Contacts contacts, double kickAfter, bool energies) {
    MdState& s = state_;
    const auto count = static_cast<long long>(s.size());
    const SpeciesTable table = speciesTable(params_);
    const double stiffness = params_.stiffness;
    const double gravity = params_.gravity;
    const std::uint32_t* offsets = neighbours_.offsets();
    const std::uint32_t* entries = neighbours_.entries();
    std::uint8_t* touching = neighbours_.payload(); // in contact at the last counted evaluation
    // Raw pointers: the byte stores of the contact flags may alias anything, and would otherwise make
    // the compiler reload every vector's data pointer after each of them.
    const double* x = s.x.data();
    const double* y = s.y.data();
    double* vx = s.vx.data();
    double* vy = s.vy.data();
    double* ax = s.ax.data();
    double* ay = s.ay.data();
    double* potentialOut = s.potential.data();
    double* virialOut = s.virial.data();
    std::uint32_t* begunOut = s.contactsBegun.data();
    const std::uint8_t* species = s.species.data();

    // firstprivate: each thread reads its own copy of the loop's constants instead of the master's stack.
#pragma omp parallel for schedule(static) if (count >= kParallelMinParticles)                                \
    firstprivate(table, stiffness, gravity, offsets, entries, touching, x, y, vx, vy, ax, ay, potentialOut,  \
                 virialOut, begunOut, species, contacts, kickAfter, energies)
    for (long long i = 0; i < count; ++i) {
        const double xi = x[i], yi = y[i];
        const double di = table.diameter[species[i]];
        const std::uint32_t first = offsets[i], last = offsets[i + 1];
        double fx = 0, fy = 0, potential = 0, virial = 0;
        std::uint32_t began = 0;
        for (std::uint32_t k = first; k < last; ++k) {
            const std::uint32_t j = entries[k];
            md::PairResult pair;
            const bool inContact = md::harmonicPair(
                xi - x[j], yi - y[j], md::contactDiameter(di, table.diameter[species[j]]), stiffness, pair);
            if (contacts != Contacts::Ignore) {
                began += (contacts == Contacts::Count && inContact && !touching[k]) ? 1u : 0u;
                touching[k] = inContact;
            }
            if (!inContact) continue;
            fx += pair.fx;
            fy += pair.fy;
            potential += 0.5 * pair.potential; // each pair is visited from both ends
            virial += 0.25 * pair.virial;
        }
        const double invM = table.inverseMass[species[i]];
        const double axi = fx * invM, ayi = fy * invM - gravity;
        ax[i] = axi;
        ay[i] = ayi;
        vx[i] += kickAfter * axi;
        vy[i] += kickAfter * ayi;
        if (energies) {
            potentialOut[i] = potential;
            virialOut[i] = virial;
        }
        if (began) begunOut[i] += began;
    }
}

void MdModel::computeForcesAllPairs(Contacts contacts, double kickAfter) {
    MdState& s = state_;
    const auto count = static_cast<long long>(s.size());
    const SpeciesTable table = speciesTable(params_);
    const double stiffness = params_.stiffness;
    const double gravity = params_.gravity;
#pragma omp parallel for schedule(static) if (count >= kParallelMinParticles)
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
            if (contacts == Contacts::Count) {
                const double px = xPrev_[i] - xPrev_[j], py = yPrev_[i] - yPrev_[j];
                began += (px * px + py * py >= dij * dij) ? 1u : 0u;
            }
        }
        const double invM = table.inverseMass[s.species[i]];
        s.ax[i] = fx * invM;
        s.ay[i] = fy * invM - gravity;
        s.vx[i] += kickAfter * s.ax[i];
        s.vy[i] += kickAfter * s.ay[i];
        s.potential[i] = potential;
        s.virial[i] = virial;
        s.contactsBegun[i] += began;
    }
}

} // namespace pl
