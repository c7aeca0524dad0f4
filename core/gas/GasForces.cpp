// Force passes: Verlet neighbour lists built from the cell list (default) and the write-up's all-pairs loop;
// both give the same forces to round-off. Gather form: only particle i's sums take pair (i, j).
#include "GasDrift.h"
#include "GasKernels.h"
#include "GasModel.h"
#include "GasThreadRange.h"
#include "common/Parallel.h"

#include <omp.h>

#include <algorithm>
#include <vector>

namespace pl {

namespace {

// Neighbour-list skin as a fraction of the largest diameter. A dilute gas has so few neighbours that a
// wide skin costs little in the force loop and saves rebuilds (measured: BENCHMARKS.md).
constexpr double kSkinOverDiameter = 1.0;

struct SpeciesTable {
    double diameter[2];
    double inverseMass[2];
};

SpeciesTable speciesTable(const GasParams& p) {
    return {{p.a.diameter, p.b.diameter}, {1.0 / p.a.mass, 1.0 / p.b.mass}};
}

// What the neighbour-list force pass reads and writes. Raw pointers: the byte stores of the contact
// flags may alias anything, and would otherwise make the compiler reload every vector's data pointer.
struct ForceArrays {
    const double* x;
    const double* y;
    const std::uint8_t* species;
    const std::uint32_t* offsets;
    const std::uint32_t* entries;
    const std::uint32_t* rowOf;
    std::uint8_t* touching; // in contact at the last counted evaluation
    double* vx;
    double* vy;
    double* ax;
    double* ay;
    double* potential;
    double* virial;
    std::uint32_t* begun;
};

// GasModel::Contacts as a template argument of the force pass (that enum is the model's own).
enum class ContactMode { Ignore, Count, Initialise };

struct ForceConstants {
    SpeciesTable table;
    double stiffness, gravity, kickAfter;
};

// Forces on the disks of one block, then a = F / m − g and v += kickAfter a. The pairs run as one flat
// sweep over the block's list entries (rowOf gives the disk), accumulating into a in list order: per
// disk the same sums in the same order as a loop per disk, so the result is bit-identical to it, and
// the sweep has no inner loop of varying length (with ~1.3 entries per disk its exit branch was the
// most expensive instruction of the pass). Only disks of the block are written.
template <ContactMode mode, bool energies>
void forceBlock(const ForceArrays& a, const ForceConstants& c, gas::ParticleRange range) {
    const std::size_t first = range.begin, last = range.end;
    if (first >= last) return;
    // Locals, not a.*: a byte store may alias the struct, locals whose address is never taken may not.
    const double* const x = a.x;
    const double* const y = a.y;
    const std::uint8_t* const species = a.species;
    const std::uint32_t* const rowOf = a.rowOf;
    const std::uint32_t* const entries = a.entries;
    std::uint8_t* const touching = a.touching;
    double* const ax = a.ax;
    double* const ay = a.ay;
    double* const vx = a.vx;
    double* const vy = a.vy;
    double* const potential = a.potential;
    double* const virial = a.virial;
    std::uint32_t* const begun = a.begun;
    for (std::size_t i = first; i < last; ++i) {
        ax[i] = 0.0;
        ay[i] = 0.0;
        if constexpr (energies) {
            potential[i] = 0.0;
            virial[i] = 0.0;
        }
    }
    const double stiffness = c.stiffness;
    const double diameterA = c.table.diameter[0], diameterB = c.table.diameter[1];
    for (std::uint32_t k = a.offsets[first], end = a.offsets[last]; k < end; ++k) {
        const std::uint32_t i = rowOf[k], j = entries[k];
        const double di = species[i] ? diameterB : diameterA;
        const double dj = species[j] ? diameterB : diameterA;
        gas::PairResult pair;
        const bool inContact =
            gas::harmonicPair(x[i] - x[j], y[i] - y[j], gas::contactDiameter(di, dj), stiffness, pair);
        if constexpr (mode != ContactMode::Ignore) {
            if constexpr (mode == ContactMode::Count)
                if (inContact && !touching[k]) ++begun[i]; // a contact that began since the last evaluation
            touching[k] = inContact;
        }
        if (!inContact) continue;
        ax[i] += pair.fx;
        ay[i] += pair.fy;
        if constexpr (energies) {
            potential[i] += 0.5 * pair.potential; // each pair is visited from both ends
            virial[i] += 0.25 * pair.virial;
        }
    }
    const double inverseMassA = c.table.inverseMass[0], inverseMassB = c.table.inverseMass[1];
    const double gravity = c.gravity, kickAfter = c.kickAfter;
    for (std::size_t i = first; i < last; ++i) {
        const double invM = species[i] ? inverseMassB : inverseMassA;
        const double axi = ax[i] * invM, ayi = ay[i] * invM - gravity;
        ax[i] = axi;
        ay[i] = ayi;
        vx[i] += kickAfter * axi;
        vy[i] += kickAfter * ayi;
    }
}

// The force pass's arrays; the list's, read after any rebuild (it reallocates them).
ForceArrays forceArrays(GasState& s, NeighbourList& list) {
    return {s.x.data(),   s.y.data(),         s.species.data(), list.offsets(),        list.entries(),
            list.rowOf(), list.payload(),     s.vx.data(),      s.vy.data(),           s.ax.data(),
            s.ay.data(),  s.potential.data(), s.virial.data(),  s.contactsBegun.data()};
}

void forceBlockFor(ContactMode mode, bool energies, const ForceArrays& a, const ForceConstants& c,
                   gas::ParticleRange range) {
    switch (mode) {
    case ContactMode::Ignore:
        energies ? forceBlock<ContactMode::Ignore, true>(a, c, range)
                 : forceBlock<ContactMode::Ignore, false>(a, c, range);
        break;
    case ContactMode::Count:
        energies ? forceBlock<ContactMode::Count, true>(a, c, range)
                 : forceBlock<ContactMode::Count, false>(a, c, range);
        break;
    case ContactMode::Initialise:
        energies ? forceBlock<ContactMode::Initialise, true>(a, c, range)
                 : forceBlock<ContactMode::Initialise, false>(a, c, range);
        break;
    }
}

// GasModel::Contacts (protected, so deduced here rather than named) as the force pass's template argument.
template <class Contacts> ContactMode contactModeOf(Contacts contacts) {
    if (contacts == Contacts::Count) return ContactMode::Count;
    if (contacts == Contacts::Initialise) return ContactMode::Initialise;
    return ContactMode::Ignore;
}

// Each thread's share of the drift's reductions, on a cache line of its own.
struct alignas(64) DriftOutcome {
    double worst = 0.0; // largest squared displacement since the list build
    bool escaped = false;
};

} // namespace

void GasModel::computeForces(Contacts contacts, double kickAfter, bool energies) {
    ++forceEvaluations_;
    if (params_.forceMethod == GasForceMethod::AllPairs) {
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

void GasModel::refreshEnergies() {
    ensureForces();
    // Forces at unchanged positions come out bit-identical, so recomputing them here is harmless.
    if (!energiesValid_) computeForces(Contacts::Ignore, 0.0, true);
}

void GasModel::computeForcesNeighbourList(Contacts contacts, double kickAfter, bool energies) {
    const std::size_t count = state_.size();
    const ForceArrays a = forceArrays(state_, neighbours_);
    const ForceConstants c{speciesTable(params_), params_.stiffness, params_.appliedGravity(), kickAfter};
    const ContactMode mode = contactModeOf(contacts);
    // One region; each thread owns a block of disks and the list rows that belong to them.
#pragma omp parallel if (static_cast <long long>(count) >= kParallelMinParticles)
    forceBlockFor(mode, energies, a, c, gas::threadRange(count));
}

// driftStage, then computeForces with the neighbour list, in one parallel region: the drift's largest
// displacement is combined after a barrier (every thread takes the same maximum, so every thread takes
// the same decision to rebuild), the list is rebuilt by the region's threads, then each thread computes
// the forces on its own block. The same operations on the same blocks as the two passes: bit-identical.
void GasModel::driftThenForces(double kickBefore, double h, double kickAfterDrift, Contacts contacts,
                               double kickAfter) {
    ++forceEvaluations_;
    GasState& s = state_;
    const std::size_t count = s.size();
    const gas::Boundaries walls = boundaries(h);
    const bool track = neighbours_.valid();
    const gas::DriftArrays drift{s.x.data(),  s.y.data(),           s.vx.data(),          s.vy.data(),
                                 s.ax.data(), s.ay.data(),          s.wallImpulse.data(), s.species.data(),
                                 s.id.data(), neighbours_.builtX(), neighbours_.builtY()};
    const gas::DriftStep step{kickBefore, h, kickAfterDrift, track};
    const ForceConstants c{speciesTable(params_), params_.stiffness, params_.appliedGravity(), kickAfter};
    const ContactMode mode = contactModeOf(contacts);
    const double d = params_.maxDiameter();
    const double left = params_.left(), bottom = params_.bottom(), right = 0.5 * params_.boxWidth,
                 top = params_.top();
    std::vector<DriftOutcome> outcomes(static_cast<std::size_t>(omp_get_max_threads()));
#pragma omp parallel if (static_cast <long long>(count) >= kParallelMinParticles)
    {
        const gas::ParticleRange range = gas::threadRange(count);
        DriftOutcome mine;
        gas::driftBlock(walls, step, drift, range, mine.escaped, mine.worst);
        outcomes[static_cast<std::size_t>(omp_get_thread_num())] = mine;
#pragma omp barrier
        double worst = 0.0;
        for (const DriftOutcome& o : outcomes) worst = std::max(worst, o.worst);
        if (!track || neighbours_.needsRebuild(worst))
            neighbours_.buildInRegion(s.x.data(), s.y.data(), count, d, kSkinOverDiameter * d, left, bottom,
                                      right, top);
        forceBlockFor(mode, false, forceArrays(s, neighbours_), c, range);
    }
    for (const DriftOutcome& o : outcomes) escaped_ = escaped_ || o.escaped;
    ++driftIndex_;
    maxDisplacement2_ = -1.0;
    forcesValid_ = true;
    energiesValid_ = false;
}

void GasModel::computeForcesAllPairs(Contacts contacts, double kickAfter) {
    GasState& s = state_;
    const auto count = static_cast<long long>(s.size());
    const SpeciesTable table = speciesTable(params_);
    const double stiffness = params_.stiffness;
    const double gravity = params_.appliedGravity();
#pragma omp parallel for schedule(static) if (count >= kParallelMinParticles)
    for (long long i = 0; i < count; ++i) {
        const double xi = s.x[i], yi = s.y[i];
        const double di = table.diameter[s.species[i]];
        double fx = 0, fy = 0, potential = 0, virial = 0;
        std::uint32_t began = 0;
        for (long long j = 0; j < count; ++j) {
            if (j == i) continue;
            const double dij = gas::contactDiameter(di, table.diameter[s.species[j]]);
            gas::PairResult pair;
            if (!gas::harmonicPair(xi - s.x[j], yi - s.y[j], dij, stiffness, pair)) continue;
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
