// The wind tunnel's sampler: cell sums over the window turned into n, u, T, T_x, T_y and Mach (Bird 1994
// §1.4, the moments of the distribution), and the momentum given to the bodies turned into forces per
// unit depth (docs/wind-tunnel.md#sampling).
#include "TunnelSampler.h"

#include "dsmc/DsmcParams.h" // kBoltzmann

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace pl {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The field names, in the order of TunnelSampler::CellFieldValues.
enum FieldIndex : std::size_t { kN, kUx, kUy, kSpeed, kT, kTx, kTy, kMach };

const std::vector<FieldChoice>& choices() {
    static const std::vector<FieldChoice> list{
        {"n", "Number density", "m⁻³"}, {"ux", "Velocity u_x", "m/s"}, {"uy", "Velocity u_y", "m/s"},
        {"speed", "Flow speed", "m/s"}, {"T", "Temperature", "K"},     {"Tx", "Temperature T_x", "K"},
        {"Ty", "Temperature T_y", "K"}, {"mach", "Mach number", ""},
    };
    return list;
}

std::vector<BodyForce> meanForces(const std::vector<double>& sumX, const std::vector<double>& sumY,
                                  std::int64_t steps) {
    std::vector<BodyForce> forces(sumX.size());
    if (steps == 0) return forces;
    for (std::size_t b = 0; b < forces.size(); ++b)
        forces[b] = {sumX[b] / double(steps), sumY[b] / double(steps)};
    return forces;
}

// b's sums added to a's, entry by entry (b may be shorter: bodies added since).
std::vector<double> plus(std::vector<double> a, const std::vector<double>& b) {
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) a[i] += b[i];
    return a;
}

// Full precision (17 significant digits round-trip a double); NaN as `nan` whatever its sign bit.
void writeNumber(std::ostream& out, double value) {
    if (std::isnan(value))
        out << "nan";
    else
        out << value;
}

} // namespace

void TunnelSampler::configure(const SamplingGrid& grid) {
    if (grid.nx <= 0 || grid.ny <= 0 || !(grid.right > grid.left) || !(grid.top > grid.bottom))
        throw std::invalid_argument("TunnelSampler: the grid needs cells and a positive extent");
    if (!grid.openFraction.empty() && grid.openFraction.size() != std::size_t(grid.nx) * std::size_t(grid.ny))
        throw std::invalid_argument("TunnelSampler: one open fraction per cell");
    // A new grid is a new run: every sum starts again, the surface's too. (grid may be grid_ itself.)
    SamplingGrid next = grid;
    const std::int64_t window = window_;
    *this = TunnelSampler{};
    grid_ = std::move(next);
    window_ = window;
    cells_.assign(std::size_t(grid_.nx) * std::size_t(grid_.ny), CellSums{});
}

void TunnelSampler::restart() {
    std::fill(cells_.begin(), cells_.end(), CellSums{});
    steps_ = 0;
    std::fill(sumForceX_.begin(), sumForceX_.end(), 0.0);
    std::fill(sumForceY_.begin(), sumForceY_.end(), 0.0);
    forceSteps_ = 0;
    previous_.clear();
    previousSteps_ = 0;
    previousForceX_.clear();
    previousForceY_.clear();
    previousForceSteps_ = 0;
}

void TunnelSampler::setWindow(std::int64_t steps) {
    if (steps < 0) throw std::invalid_argument("TunnelSampler: the window needs 0 or more steps");
    window_ = steps;
    restart();
}

void TunnelSampler::rotateWindow() {
    previous_.swap(cells_);
    cells_.assign(previous_.size(), CellSums{});
    previousSteps_ = steps_;
    steps_ = 0;
    previousForceX_.swap(sumForceX_);
    previousForceY_.swap(sumForceY_);
    sumForceX_.assign(previousForceX_.size(), 0.0);
    sumForceY_.assign(previousForceY_.size(), 0.0);
    previousForceSteps_ = forceSteps_;
    forceSteps_ = 0;
}

void TunnelSampler::addState(const TunnelState& state) {
    const std::size_t cellCount = cells_.size();
    for (std::size_t i = 0; i < state.size(); ++i) {
        const std::size_t c = state.cell[i];
        if (c >= cellCount) continue; // not sorted into the grid (never the model's case)
        CellSums& s = cells_[c];
        const double vx = state.vx[i], vy = state.vy[i], vz = state.vz[i];
        s.count += 1;
        s.mx += vx, s.my += vy, s.mz += vz;
        s.ex += vx * vx, s.ey += vy * vy, s.ez += vz * vz;
    }
    ++steps_;
}

void TunnelSampler::addCellSums(const std::vector<CellSums>& sums, std::int64_t steps) {
    if (sums.size() != cells_.size()) throw std::invalid_argument("TunnelSampler: one sum per cell");
    for (std::size_t c = 0; c < sums.size(); ++c) {
        CellSums& s = cells_[c];
        const CellSums& a = sums[c];
        s.count += a.count;
        s.mx += a.mx, s.my += a.my, s.mz += a.mz;
        s.ex += a.ex, s.ey += a.ey, s.ez += a.ez;
    }
    steps_ += steps;
}

void TunnelSampler::addSurfaceImpulse(std::size_t body, double dpx, double dpy) {
    if (body >= impulseX_.size()) {
        impulseX_.resize(body + 1, 0.0);
        impulseY_.resize(body + 1, 0.0);
    }
    // Each simulated particle stands for fn real molecules per metre of depth.
    impulseX_[body] += dpx * grid_.fn;
    impulseY_[body] += dpy * grid_.fn;
}

void TunnelSampler::endStep(std::size_t bodies, double dt) {
    impulseX_.resize(std::max(impulseX_.size(), bodies), 0.0);
    impulseY_.resize(std::max(impulseY_.size(), bodies), 0.0);
    sumForceX_.resize(bodies, 0.0), sumForceY_.resize(bodies, 0.0);
    intervalForceX_.resize(bodies, 0.0), intervalForceY_.resize(bodies, 0.0);
    last_.assign(bodies, BodyForce{});
    const bool windowOpen = sampledSteps() > 0;
    for (std::size_t b = 0; b < bodies; ++b) {
        // The gas gained Σ m Δv fn over dt; the body feels the opposite, F = −Σ/dt [N/m]
        // (docs/wind-tunnel.md#sampling).
        const BodyForce force{-impulseX_[b] / dt, -impulseY_[b] / dt};
        last_[b] = force;
        intervalForceX_[b] += force.drag, intervalForceY_[b] += force.lift;
        if (windowOpen) sumForceX_[b] += force.drag, sumForceY_[b] += force.lift;
    }
    ++intervalSteps_;
    if (windowOpen) ++forceSteps_;
    std::fill(impulseX_.begin(), impulseX_.end(), 0.0);
    std::fill(impulseY_.begin(), impulseY_.end(), 0.0);
    if (window_ > 0 && steps_ >= (window_ + 1) / 2) rotateWindow();
}

std::vector<BodyForce> TunnelSampler::averageForces() const {
    if (previousForceSteps_ == 0) return meanForces(sumForceX_, sumForceY_, forceSteps_);
    return meanForces(plus(sumForceX_, previousForceX_), plus(sumForceY_, previousForceY_),
                      forceSteps_ + previousForceSteps_);
}

std::vector<BodyForce> TunnelSampler::lastForces() const {
    return last_;
}

std::vector<BodyForce> TunnelSampler::takeIntervalForces() {
    if (intervalSteps_ == 0) return previousInterval_;
    previousInterval_ = meanForces(intervalForceX_, intervalForceY_, intervalSteps_);
    std::fill(intervalForceX_.begin(), intervalForceX_.end(), 0.0);
    std::fill(intervalForceY_.begin(), intervalForceY_.end(), 0.0);
    intervalSteps_ = 0;
    return previousInterval_;
}

std::vector<FieldChoice> TunnelSampler::fieldChoices() const {
    return choices();
}

// The moments of cell c over the window (Bird 1994 §1.4, one species): n = N̄ fn / V with N̄ the mean
// particle count and V = dx·dy·1 m·open fraction; u = ⟨v⟩; k T_x = m (⟨v_x²⟩ − u_x²) and likewise for y
// and z (a variance: round-off below 0 is 0); T = (T_x + T_y + T_z)/3; Mach = |u| / √(γ k T / m) with
// |u| the speed in the plane. NaN throughout where the cell has no sample or no open area.
TunnelSampler::CellFieldValues TunnelSampler::cellFields(std::size_t c) const {
    CellFieldValues f;
    f.fill(kNaN);
    CellSums s = cells_[c];
    if (previousSteps_ > 0) { // a moving window: both halves
        const CellSums& older = previous_[c];
        s.count += older.count;
        s.mx += older.mx, s.my += older.my, s.mz += older.mz;
        s.ex += older.ex, s.ey += older.ey, s.ez += older.ez;
    }
    const std::int64_t steps = sampledSteps();
    const double open = grid_.openFraction.empty() ? 1.0 : grid_.openFraction[c];
    if (s.count <= 0 || steps == 0 || !(open > 0)) return f;
    const double dx = (grid_.right - grid_.left) / grid_.nx, dy = (grid_.top - grid_.bottom) / grid_.ny;
    f[kN] = (s.count / double(steps)) * grid_.fn / (dx * dy * open);
    f[kUx] = s.mx / s.count, f[kUy] = s.my / s.count;
    const double uz = s.mz / s.count;
    const double mOverK = grid_.mass / kBoltzmann;
    f[kTx] = mOverK * std::max(0.0, s.ex / s.count - f[kUx] * f[kUx]);
    f[kTy] = mOverK * std::max(0.0, s.ey / s.count - f[kUy] * f[kUy]);
    const double Tz = mOverK * std::max(0.0, s.ez / s.count - uz * uz);
    f[kT] = (f[kTx] + f[kTy] + Tz) / 3.0;
    f[kSpeed] = std::hypot(f[kUx], f[kUy]);
    const double soundSpeed = std::sqrt(grid_.gamma * kBoltzmann * f[kT] / grid_.mass);
    if (soundSpeed > 0) f[kMach] = f[kSpeed] / soundSpeed;
    return f;
}

FieldGrid TunnelSampler::field(const std::string& name) const {
    const auto& list = choices();
    const auto found =
        std::find_if(list.begin(), list.end(), [&](const FieldChoice& c) { return c.name == name; });
    if (found == list.end()) throw std::invalid_argument("the wind tunnel samples no field '" + name + "'");
    const auto index = std::size_t(found - list.begin());
    FieldGrid grid;
    grid.choice = *found;
    grid.nx = grid_.nx, grid.ny = grid_.ny;
    grid.left = grid_.left, grid.bottom = grid_.bottom, grid.right = grid_.right, grid.top = grid_.top;
    grid.values.resize(cells_.size());
    for (std::size_t c = 0; c < cells_.size(); ++c) grid.values[c] = cellFields(c)[index];
    return grid;
}

std::vector<FieldValue> TunnelSampler::probe(double x, double y) const {
    if (cells_.empty() || !(x >= grid_.left && x <= grid_.right && y >= grid_.bottom && y <= grid_.top))
        return {};
    const double dx = (grid_.right - grid_.left) / grid_.nx, dy = (grid_.top - grid_.bottom) / grid_.ny;
    // The right and top edges belong to the last column and row.
    const int i = std::min(grid_.nx - 1, int((x - grid_.left) / dx));
    const int j = std::min(grid_.ny - 1, int((y - grid_.bottom) / dy));
    const CellFieldValues values = cellFields(std::size_t(j) * std::size_t(grid_.nx) + std::size_t(i));
    std::vector<FieldValue> result;
    const auto& list = choices();
    for (std::size_t k = 0; k < list.size(); ++k) result.push_back({list[k], values[k]});
    return result;
}

void TunnelSampler::writeFieldsCsv(std::ostream& out) const {
    const auto flags = out.flags();
    const auto precision = out.precision(17);
    out << "i,j,x,y,n,ux,uy,T,Tx,Ty,mach\n";
    const double dx = (grid_.right - grid_.left) / grid_.nx, dy = (grid_.top - grid_.bottom) / grid_.ny;
    // The header's columns after i, j, x, y.
    constexpr FieldIndex columns[] = {kN, kUx, kUy, kT, kTx, kTy, kMach};
    for (int j = 0; j < grid_.ny; ++j) {
        for (int i = 0; i < grid_.nx; ++i) {
            const CellFieldValues values =
                cellFields(std::size_t(j) * std::size_t(grid_.nx) + std::size_t(i));
            out << i << ',' << j << ',';
            writeNumber(out, grid_.left + (i + 0.5) * dx);
            out << ',';
            writeNumber(out, grid_.bottom + (j + 0.5) * dy);
            for (FieldIndex k : columns) {
                out << ',';
                writeNumber(out, values[k]);
            }
            out << '\n';
        }
    }
    out.precision(precision);
    out.flags(flags);
}

} // namespace pl
