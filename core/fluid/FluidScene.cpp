// The fluid as the viewport and the mouse tools see it: the write-up's sea-green tank with blue → red speed
// colours, and the drag-to-spawn rectangle filled on a grid of spacing 0.8 h.
#include "FluidModel.h"
#include "FluidSpawnGrid.h"

#include "common/CellList.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace pl {

namespace {
// Spawned particles closer than this fraction of the spacing to fluid already there are refused: pouring
// onto a pool fills its gaps instead of stacking particles on top of each other.
constexpr double kMinimumSeparation = 0.5;
} // namespace

SceneView FluidModel::sceneView() const {
    pullState();
    SceneView view = sceneFrame();
    const std::size_t n = state_.size();
    view.x.resize(n);
    view.y.resize(n);
    view.radius.assign(n, static_cast<float>(params_.particleRadius));
    view.value.resize(n);
    const double inverseMax = 1.0 / params_.colourSpeedMax;
    for (std::size_t i = 0; i < n; ++i) {
        view.x[i] = static_cast<float>(state_.x[i]);
        view.y[i] = static_cast<float>(state_.y[i]);
        view.value[i] = static_cast<float>(std::hypot(state_.vx[i], state_.vy[i]) * inverseMax);
    }
    return view;
}

// state_.size() is current also while a GPU backend holds the particles: only the CPU changes the count.
SceneView FluidModel::sceneFrame() const {
    SceneView view;
    view.left = 0;
    view.bottom = 0;
    view.right = params_.boxWidth;
    view.top = params_.boxHeight;
    view.background = {46 / 255.0f, 139 / 255.0f, 87 / 255.0f}; // the write-up's #2E8B57
    view.colours = ColourMap::BlueRed;
    view.colourLabel = "speed";
    view.colourMax = params_.colourSpeedMax;
    if (state_.size() == 0) view.hint = "Click and drag to pour fluid";
    view.dragPours = true; // the write-up's one gesture: dragging pours, whatever else is on screen
    view.obstacles = obstacles_;
    return view;
}

std::string FluidModel::Spawned::message() const {
    std::ostringstream out;
    out << "added " << added << (added == 1 ? " particle" : " particles");
    if (refusedCap > 0)
        out << "; " << refusedCap
            << " refused: the particle cap is reached (Parameters → Particles → Particle cap)";
    if (refusedOverlap > 0) out << "; " << refusedOverlap << " refused: fluid is already there";
    if (refusedOutside > 0)
        out << "; " << refusedOutside << " refused: outside the tank or inside an obstacle";
    return out.str();
}

std::string FluidModel::spawnInRectangle(double x0, double y0, double x1, double y1) {
    pullState();
    const long long before = static_cast<long long>(state_.size());
    Spawned result = spawnLattice(x0, y0, x1, y1);
    stateEdited();
    std::string text = result.message();
    const long long over = before + result.added - params_.maxParticles;
    if (params_.drain && over > 0) text += "; the drain will remove the " + std::to_string(over) + " lowest";
    return text;
}

// A grid of spacing δ = 0.8 h centred in the rectangle (a point: one particle), at rest.
FluidModel::Spawned FluidModel::spawnLattice(double x0, double y0, double x1, double y1) {
    const double d = params_.spacing();
    const fluid::SpawnGrid grid = fluid::SpawnGrid::centred(x0, y0, x1, y1, d);

    CellList existing;
    const double separation = kMinimumSeparation * d;
    existing.configure(0, 0, params_.boxWidth, params_.boxHeight, separation);
    existing.build(state_.x.data(), state_.y.data(), state_.size());
    const auto tooClose = [&](double x, double y) {
        const int cx = existing.cellX(x), cy = existing.cellY(y);
        for (int r = std::max(cy - 1, 0); r <= std::min(cy + 1, existing.cellsY() - 1); ++r)
            for (int c = std::max(cx - 1, 0); c <= std::min(cx + 1, existing.cellsX() - 1); ++c) {
                const int cell = r * existing.cellsX() + c;
                for (auto k = existing.cellStart()[cell]; k < existing.cellStart()[cell + 1]; ++k) {
                    const auto j = existing.order()[k];
                    if (std::hypot(state_.x[j] - x, state_.y[j] - y) < separation) return true;
                }
            }
        return false;
    };

    // With the drain on, one gesture may overfill by up to a whole tank; the next step drains the excess.
    const long long cap = params_.drain ? 2 * params_.maxParticles : params_.maxParticles;
    const std::size_t existingCount = state_.size();
    const fluid::Box box = confinementBox();
    Spawned result;
    for (long long r = 0; r < grid.rows; ++r) {
        for (long long c = 0; c < grid.columns; ++c) {
            const double x = grid.x(c), y = grid.y(r);
            if (fluid::outsideFluidDomain(box, obstacles_, params_.particleRadius, d, x, y)) {
                ++result.refusedOutside;
            } else if (existingCount > 0 && tooClose(x, y)) {
                ++result.refusedOverlap;
            } else if (static_cast<long long>(state_.size()) >= cap) {
                ++result.refusedCap;
            } else {
                state_.append(x, y, 0.0, 0.0);
                ++result.added;
            }
        }
    }
    return result;
}

} // namespace pl
