// Neighbour list construction: one gather pass over the 3×3 cell block into per-thread rows, placed at
// the offsets of an exclusive prefix sum.
#include "NeighbourList.h"

#include "Parallel.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace pl {

namespace {

void exclusivePrefixSum(std::vector<std::uint32_t>& values) {
    std::uint32_t sum = 0;
    for (auto& v : values) {
        const std::uint32_t c = v;
        v = sum;
        sum += c;
    }
}

// CellList::cellX / cellY: the same arithmetic, so the grid and the order of the entries are the same.
std::uint32_t clampedCell(double p, double origin, double inverseSize, int cells) {
    const double c = std::floor((p - origin) * inverseSize);
    if (!(c > 0)) return 0; // also catches NaN, which the model reports as a blow-up
    return c >= cells - 1 ? static_cast<std::uint32_t>(cells - 1) : static_cast<std::uint32_t>(c);
}

struct Share {
    std::size_t begin, end;
};

// The calling thread's contiguous share of [0, count); any split gives the same rows.
Share threadShare(std::size_t count) {
    const auto threads = static_cast<std::size_t>(omp_get_num_threads());
    const auto thread = static_cast<std::size_t>(omp_get_thread_num());
    return {count * thread / threads, count * (thread + 1) / threads};
}

// The payload byte of each entry of a new row from the entry of the same particle in its old row (0 for
// a new pair). The rows keep the cell order of their neighbours, which rarely changes between builds,
// so the search resumes after the last match and usually ends at its first comparison.
void carryRow(const std::uint32_t* entries, std::uint8_t* payload, std::uint32_t count,
              const std::uint32_t* oldEntries, const std::uint8_t* oldPayload, std::uint32_t oldCount) {
    std::uint32_t cursor = 0;
    for (std::uint32_t a = 0; a < count; ++a) {
        std::uint8_t carried = 0;
        for (std::uint32_t tried = 0; tried < oldCount; ++tried) {
            const std::uint32_t b = cursor;
            cursor = cursor + 1 == oldCount ? 0 : cursor + 1;
            if (oldEntries[b] == entries[a]) {
                carried = oldPayload[b];
                break;
            }
        }
        payload[a] = carried;
    }
}

} // namespace

void NeighbourList::build(const double* x, const double* y, std::size_t count, double cutoff, double skin,
                          double x0, double y0, double x1, double y1) {
#pragma omp parallel if (static_cast <long long>(count) >= kParallelMinParticles)
    buildInRegion(x, y, count, cutoff, skin, x0, y0, x1, y1);
}

// One search per particle: each thread appends the rows of its share to its own buffer, then the
// buffers are copied to their offsets (an exclusive prefix sum of the row lengths). Row i lists the
// j ≠ i within reach in the order of the 3×3 cell block, rows of cells bottom to top, particles of a
// cell in index order.
void NeighbourList::buildInRegion(const double* x, const double* y, std::size_t count, double cutoff,
                                  double skin, double x0, double y0, double x1, double y1) {
    const double reach = cutoff + skin;
    const double reach2 = reach * reach;
    const auto n = static_cast<long long>(count);
#pragma omp single
    {
        carrying_ = valid_ && offsets_.size() == count + 1;
        if (carrying_) {
            oldOffsets_.swap(offsets_);
            oldEntries_.swap(entries_);
            oldPayload_.swap(payload_);
        }
        // About one particle per cell keeps the grid cheap in dilute gases; never smaller than the reach.
        const double area = (x1 - x0) * (y1 - y0);
        cells_.configure(x0, y0, x1, y1, std::max(reach, std::sqrt(area / std::max<double>(1.0, count))));
        cellX_.resize(count);
        cellY_.resize(count);
        offsets_.resize(count + 1);
        builtX_.resize(count);
        builtY_.resize(count);
        threadEntries_.resize(static_cast<std::size_t>(omp_get_num_threads()));
        threadTotals_.resize(threadEntries_.size());
    }
    const double inverseSize = 1.0 / cells_.cellSize(); // as CellList::configure computes it
    const int nx = cells_.cellsX(), ny = cells_.cellsY();
#pragma omp for schedule(static)
    for (long long i = 0; i < n; ++i) {
        cellX_[i] = clampedCell(x[i], x0, inverseSize, nx);
        cellY_[i] = clampedCell(y[i], y0, inverseSize, ny);
    }
#pragma omp single
    binParticles(x, y, count);

    const Share share = threadShare(count);
    const auto thread = static_cast<std::size_t>(omp_get_thread_num());
    // A local, so appending writes no line another thread reads. Each candidate is written at the end
    // and kept by advancing the end when it is within reach: no branch on the test, which is random.
    std::vector<std::uint32_t> found;
    found.swap(threadEntries_[thread]);
    std::size_t size = 0;
    {
        const std::uint32_t* const start = cellStart_.data();
        const std::uint32_t* const order = cellOrder_.data();
        const double* const sx = cellOrderX_.data();
        const double* const sy = cellOrderY_.data();
        for (std::size_t i = share.begin; i < share.end; ++i) {
            const double xi = x[i], yi = y[i];
            const int cx = static_cast<int>(cellX_[i]), cy = static_cast<int>(cellY_[i]);
            const int columnFirst = std::max(cx - 1, 0), columnLast = std::min(cx + 1, nx - 1);
            const std::size_t before = size;
            for (int row = std::max(cy - 1, 0); row <= std::min(cy + 1, ny - 1); ++row) {
                const std::uint32_t first = start[row * nx + columnFirst];
                const std::uint32_t last = start[row * nx + columnLast + 1];
                if (found.size() < size + (last - first)) [[unlikely]]
                    found.resize(std::max(2 * found.size(), size + (last - first) + 1024));
                std::uint32_t* const out = found.data();
                for (std::uint32_t k = first; k < last; ++k) {
                    const std::uint32_t j = order[k];
                    const double dx = xi - sx[k], dy = yi - sy[k];
                    out[size] = j;
                    size += static_cast<std::size_t>((dx * dx + dy * dy < reach2) & (j != i));
                }
            }
            offsets_[i] = static_cast<std::uint32_t>(size - before); // the row's length for now
        }
    }
    threadTotals_[thread] = static_cast<std::uint32_t>(size);
    found.swap(threadEntries_[thread]);
#pragma omp barrier
#pragma omp single
    {
        std::uint32_t total = 0;
        for (const std::uint32_t t : threadTotals_) total += t;
        entries_.resize(total);
        rowOf_.resize(total);
        payload_.resize(total);
        offsets_[count] = total;
        // Written only here, after every thread has passed the barriers above: the threads of a step
        // read skin_ and valid_ to decide on a rebuild before they enter.
        skin_ = skin;
        valid_ = true;
    }
    std::uint32_t offset = 0;
    for (std::size_t t = 0; t < thread; ++t) offset += threadTotals_[t];
    const std::uint32_t* const mine = threadEntries_[thread].data();
    std::copy(mine, mine + threadTotals_[thread], entries_.begin() + offset);
    for (std::size_t i = share.begin; i < share.end; ++i) {
        const std::uint32_t length = offsets_[i];
        offsets_[i] = offset;
        for (std::uint32_t k = offset; k < offset + length; ++k) rowOf_[k] = static_cast<std::uint32_t>(i);
        if (carrying_) {
            const std::uint32_t oldFirst = oldOffsets_[i];
            carryRow(entries_.data() + offset, payload_.data() + offset, length,
                     oldEntries_.data() + oldFirst, oldPayload_.data() + oldFirst,
                     oldOffsets_[i + 1] - oldFirst);
        } else {
            std::fill_n(payload_.data() + offset, length, std::uint8_t{0});
        }
        builtX_[i] = x[i];
        builtY_[i] = y[i];
        offset += length;
    }
#pragma omp barrier
}

// Counting sort of the particles by cell (stable: index order within a cell), with their positions.
void NeighbourList::binParticles(const double* x, const double* y, std::size_t count) {
    const auto nx = static_cast<std::size_t>(cells_.cellsX());
    const std::size_t cells = nx * static_cast<std::size_t>(cells_.cellsY());
    cellStart_.assign(cells + 1, 0u);
    for (std::size_t i = 0; i < count; ++i) ++cellStart_[cellY_[i] * nx + cellX_[i] + 1];
    for (std::size_t c = 1; c <= cells; ++c) cellStart_[c] += cellStart_[c - 1];
    cellCursor_.assign(cellStart_.begin(), cellStart_.end() - 1);
    cellOrder_.resize(count);
    cellOrderX_.resize(count);
    cellOrderY_.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t k = cellCursor_[cellY_[i] * nx + cellX_[i]]++;
        cellOrder_[k] = static_cast<std::uint32_t>(i);
        cellOrderX_[k] = x[i];
        cellOrderY_[k] = y[i];
    }
}

void NeighbourList::restore(Contents c) {
    offsets_ = std::move(c.offsets);
    entries_ = std::move(c.entries);
    payload_ = std::move(c.payload);
    builtX_ = std::move(c.builtX);
    builtY_ = std::move(c.builtY);
    skin_ = c.skin;
    valid_ = c.valid;
    fillRows();
}

void NeighbourList::fillRows() {
    const auto n = static_cast<long long>(offsets_.empty() ? 0 : offsets_.size() - 1);
    rowOf_.resize(entries_.size());
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i)
        for (std::uint32_t k = offsets_[i]; k < offsets_[i + 1]; ++k)
            rowOf_[k] = static_cast<std::uint32_t>(i);
}

void NeighbourList::permute(const std::vector<std::uint32_t>& newToOld) {
    if (!valid_) return;
    const std::size_t count = newToOld.size();
    std::vector<std::uint32_t> oldToNew(count);
    for (std::size_t m = 0; m < count; ++m) oldToNew[newToOld[m]] = static_cast<std::uint32_t>(m);
    oldOffsets_.swap(offsets_);
    oldEntries_.swap(entries_);
    oldPayload_.swap(payload_);
    offsets_.assign(count + 1, 0);
    for (std::size_t m = 0; m < count; ++m)
        offsets_[m] = oldOffsets_[newToOld[m] + 1] - oldOffsets_[newToOld[m]];
    exclusivePrefixSum(offsets_);
    entries_.resize(oldEntries_.size());
    payload_.resize(oldPayload_.size());
    const auto n = static_cast<long long>(count);
#pragma omp parallel for schedule(static) if (n >= kParallelMinParticles)
    for (long long m = 0; m < n; ++m) {
        const std::uint32_t from = oldOffsets_[newToOld[m]];
        for (std::uint32_t k = 0; k < offsets_[m + 1] - offsets_[m]; ++k) {
            entries_[offsets_[m] + k] = oldToNew[oldEntries_[from + k]];
            payload_[offsets_[m] + k] = oldPayload_[from + k];
        }
    }
    fillRows();
    std::vector<double> bx(count), by(count);
    for (std::size_t m = 0; m < count; ++m) bx[m] = builtX_[newToOld[m]], by[m] = builtY_[newToOld[m]];
    builtX_.swap(bx);
    builtY_.swap(by);
}

bool NeighbourList::needsRebuild(const double* x, const double* y, std::size_t count) const {
    if (!valid_ || builtX_.size() != count) return true;
    double worst = 0.0;
    const auto n = static_cast<long long>(count);
#pragma omp parallel for schedule(static) reduction(max : worst) if (n >= kParallelMinParticles)
    for (long long i = 0; i < n; ++i) {
        const double dx = x[i] - builtX_[i], dy = y[i] - builtY_[i];
        worst = std::max(worst, dx * dx + dy * dy);
    }
    return needsRebuild(worst);
}

} // namespace pl
