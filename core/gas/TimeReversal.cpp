// The Loschmidt echo in double, float and integer arithmetic (see TimeReversal.h).
#include "TimeReversal.h"

#include "GasKernels.h"
#include "common/Philox.h"

#include <cmath>
#include <numbers>

namespace pl::gas {

namespace {

struct Start {
    std::vector<double> x, y, vx, vy;
};

// A square lattice filling the box, velocities of one speed in random directions (Philox by disk).
Start startingState(const EchoSetup& s) {
    Start start;
    const int side = static_cast<int>(std::ceil(std::sqrt(double(s.disks))));
    const double spacing = s.box / side;
    for (int i = 0; i < s.disks; ++i) {
        start.x.push_back((i % side + 0.5) * spacing);
        start.y.push_back((i / side + 0.5) * spacing);
        const double angle =
            2.0 * std::numbers::pi *
            unitOpen32(randomWords(s.seed, RngPurpose::InitialVelocity, std::uint32_t(i), 0)[0]);
        start.vx.push_back(s.speed * std::cos(angle));
        start.vy.push_back(s.speed * std::sin(angle));
    }
    return start;
}

template <class Real> Real minimumImage(Real d, Real box) {
    return d - box * std::nearbyint(d / box);
}

// Velocity Verlet on the periodic gas in arithmetic Real; positions unwrapped.
template <class Real> class VerletGas {
public:
    VerletGas(const EchoSetup& s, const Start& start)
        : n_(s.disks), box_(Real(s.box)), d_(Real(s.diameter)), k_(Real(s.stiffness)), h_(Real(s.dt)),
          x_(start.x.begin(), start.x.end()), y_(start.y.begin(), start.y.end()),
          vx_(start.vx.begin(), start.vx.end()), vy_(start.vy.begin(), start.vy.end()), ax_(n_), ay_(n_) {
        accelerations();
    }
    void run(long long steps) {
        for (long long s = 0; s < steps; ++s) {
            for (int i = 0; i < n_; ++i) {
                vx_[i] += Real(0.5) * h_ * ax_[i];
                vy_[i] += Real(0.5) * h_ * ay_[i];
                x_[i] += h_ * vx_[i];
                y_[i] += h_ * vy_[i];
            }
            accelerations();
            for (int i = 0; i < n_; ++i) {
                vx_[i] += Real(0.5) * h_ * ax_[i];
                vy_[i] += Real(0.5) * h_ * ay_[i];
            }
        }
    }
    void reverse() {
        for (int i = 0; i < n_; ++i) vx_[i] = -vx_[i], vy_[i] = -vy_[i];
    }
    double rmsDistance(const Start& start) const {
        double sum = 0;
        for (int i = 0; i < n_; ++i) {
            const double dx = double(x_[i]) - start.x[i], dy = double(y_[i]) - start.y[i];
            sum += dx * dx + dy * dy;
        }
        return std::sqrt(sum / n_);
    }

private:
    // Harmonic repulsion (GasKernels.h, docs/gas.md#pair-force) with the minimum image, all pairs in index
    // order.
    void accelerations() {
        for (int i = 0; i < n_; ++i) {
            Real fx = 0, fy = 0;
            for (int j = 0; j < n_; ++j) {
                if (j == i) continue;
                const Real dx = minimumImage(x_[i] - x_[j], box_), dy = minimumImage(y_[i] - y_[j], box_);
                const Real r2 = dx * dx + dy * dy;
                if (r2 >= d_ * d_ || r2 < Real(kCoincidentR2)) continue;
                const Real r = std::sqrt(r2);
                const Real fOverR = k_ * (d_ - r) / r;
                fx += fOverR * dx;
                fy += fOverR * dy;
            }
            ax_[i] = fx;
            ay_[i] = fy;
        }
    }
    int n_;
    Real box_, d_, k_, h_;
    std::vector<Real> x_, y_, vx_, vy_, ax_, ay_;
};

} // namespace

IntegerVerletGas::IntegerVerletGas(const EchoSetup& setup)
    : setup_(setup), spacing_(setup.box / 4294967296.0) {
    const Start start = startingState(setup);
    const auto n = static_cast<std::size_t>(setup.disks);
    x_.resize(n), y_.resize(n), xPrev_.resize(n), yPrev_.resize(n), fx_.resize(n), fy_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        x_[i] = std::llround(start.x[i] / spacing_);
        y_[i] = std::llround(start.y[i] / spacing_);
        // The previous configuration one step back along the initial velocity (X_{−1} = X_0 − v h / Δ).
        xPrev_[i] = x_[i] - std::llround(start.vx[i] * setup.dt / spacing_);
        yPrev_[i] = y_[i] - std::llround(start.vy[i] * setup.dt / spacing_);
    }
}

void IntegerVerletGas::forces(std::vector<std::int64_t>& fx, std::vector<std::int64_t>& fy) const {
    // Pair distances from integer differences (exact in double below 2⁵³), the minimum image on the
    // integer lattice, and h² a / Δ rounded to an integer: a function of the configuration alone.
    const auto n = static_cast<long long>(x_.size());
    const std::int64_t period = std::int64_t{1} << 32;
    const double d = setup_.diameter, k = setup_.stiffness, scale = setup_.dt * setup_.dt / spacing_;
    for (long long i = 0; i < n; ++i) {
        double ax = 0, ay = 0;
        for (long long j = 0; j < n; ++j) {
            if (j == i) continue;
            std::int64_t ix = (x_[i] - x_[j]) % period, iy = (y_[i] - y_[j]) % period;
            if (ix > period / 2) ix -= period;
            if (ix < -period / 2) ix += period;
            if (iy > period / 2) iy -= period;
            if (iy < -period / 2) iy += period;
            const double dx = double(ix) * spacing_, dy = double(iy) * spacing_;
            PairResult pair;
            if (!harmonicPair(dx, dy, d, k, pair)) continue;
            ax += pair.fx;
            ay += pair.fy;
        }
        fx[i] = std::llround(ax * scale);
        fy[i] = std::llround(ay * scale);
    }
}

void IntegerVerletGas::step() {
    forces(fx_, fy_);
    for (std::size_t i = 0; i < x_.size(); ++i) {
        const std::int64_t nx = 2 * x_[i] - xPrev_[i] + fx_[i], ny = 2 * y_[i] - yPrev_[i] + fy_[i];
        xPrev_[i] = x_[i], yPrev_[i] = y_[i];
        x_[i] = nx, y_[i] = ny;
    }
}

void IntegerVerletGas::reverse() {
    x_.swap(xPrev_);
    y_.swap(yPrev_);
}

double IntegerVerletGas::rmsDistance(const IntegerVerletGas& other) const {
    double sum = 0;
    for (std::size_t i = 0; i < x_.size(); ++i) {
        const double dx = double(x_[i] - other.x_[i]) * spacing_, dy = double(y_[i] - other.y_[i]) * spacing_;
        sum += dx * dx + dy * dy;
    }
    return std::sqrt(sum / double(x_.size()));
}

std::vector<EchoPoint> loschmidtEcho(const EchoSetup& setup, const std::vector<long long>& steps) {
    const Start start = startingState(setup);
    std::vector<EchoPoint> points;
    for (long long n : steps) {
        EchoPoint p;
        p.steps = n;
        VerletGas<double> d(setup, start);
        d.run(n);
        d.reverse();
        d.run(n);
        p.rmsDouble = d.rmsDistance(start);
        VerletGas<float> f(setup, start);
        f.run(n);
        f.reverse();
        f.run(n);
        p.rmsFloat = f.rmsDistance(start);
        const IntegerVerletGas origin(setup);
        IntegerVerletGas g = origin;
        for (long long s = 0; s < n; ++s) g.step();
        g.reverse();
        for (long long s = 0; s < n; ++s) g.step();
        g.reverse(); // back to the original orientation (X_{−1}, X_0)
        p.rmsInteger = g.rmsDistance(origin);
        points.push_back(p);
    }
    return points;
}

} // namespace pl::gas
