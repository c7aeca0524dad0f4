// Grid sizing and the multi-level prefix sum (2048 counts per work group and level).
#include "GpuCellGrid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pl::gl {

namespace {
constexpr std::size_t kScanBlock = 2048; // counts per work group of common/scan.comp
constexpr unsigned kScanLocalSize = 512;
constexpr std::size_t kMaxLevels = 4; // 2048⁴ counts
} // namespace

// Sized once: the recursion holds references into these vectors.
GpuCellGrid::GpuCellGrid()
    : scan_("common/scan.comp"), add_("common/scan_add.comp"), blockSums_(kMaxLevels),
      blockOffsets_(kMaxLevels) {}

void GpuCellGrid::configure(double left, double bottom, double width, double height, double minSide,
                            std::size_t particles, double particlesPerCell) {
    const double area = width * height;
    const double sparse =
        particles > 0 ? std::sqrt(area * particlesPerCell / static_cast<double>(particles)) : width;
    side_ = std::max({minSide, sparse, 1e-12});
    // At most 2²⁶ cells: a grid that fine would hold mostly empty cells.
    side_ = std::max(side_, std::sqrt(area / double(1 << 26)));
    nx_ = std::max(1, static_cast<int>(std::floor(width / side_)));
    ny_ = std::max(1, static_cast<int>(std::floor(height / side_)));
    // Floor keeps every cell at least side_ wide: the 3×3 stencil still covers the interaction range.
    side_ = std::max(width / nx_, height / ny_);
    left_ = left;
    bottom_ = bottom;
    const std::size_t entries = cells() + 1;
    const std::size_t before = counts_.capacity();
    counts_.reserve(entries * sizeof(std::uint32_t));
    starts_.reserve(entries * sizeof(std::uint32_t));
    if (counts_.capacity() != before || before == 0) counts_.fillZero(counts_.capacity());
}

void GpuCellGrid::setUniforms(ComputeProgram& program) const {
    program.set("cellOrigin", static_cast<float>(left_), static_cast<float>(bottom_));
    program.set("cellInverseSide", static_cast<float>(1.0 / side_));
    program.set("cellDims", nx_, ny_);
}

void GpuCellGrid::scan() {
    scanDispatches_ = 0;
    scanLevel(counts_, starts_, cells() + 1, 0, true);
}

void GpuCellGrid::scanLevel(Buffer& input, Buffer& output, std::size_t count, std::size_t level,
                            bool clearInput) {
    const std::size_t blocks = groupsFor(count, kScanBlock);
    if (level >= kMaxLevels) throw std::length_error("cell grid too large to scan");
    blockSums_[level].reserve(blocks * sizeof(std::uint32_t));
    blockOffsets_[level].reserve(blocks * sizeof(std::uint32_t));
    scan_.use();
    scan_.set("count", static_cast<unsigned>(count));
    scan_.set("clearInput", clearInput ? 1 : 0);
    input.bind(0);
    output.bind(1);
    blockSums_[level].bind(2);
    scan_.dispatch(blocks * kScanLocalSize, kScanLocalSize);
    ++scanDispatches_;
    storageBarrier();
    if (blocks == 1) return;
    scanLevel(blockSums_[level], blockOffsets_[level], blocks, level + 1, false);
    add_.use();
    add_.set("count", static_cast<unsigned>(count));
    output.bind(1);
    blockOffsets_[level].bind(3);
    add_.dispatch(blocks * kScanLocalSize, kScanLocalSize);
    ++scanDispatches_;
    storageBarrier();
}

} // namespace pl::gl
