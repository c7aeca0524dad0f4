// The wind tunnel against physics (docs/wind-tunnel.md#reference-formulas): the empty tunnel's flux
// balance, the free-molecular drag of a diffuse cylinder, a piston-driven shock against Rankine–Hugoniot
// and Alsmeyer's thickness, Couette shear and slip, and the equilibrium collision rate. Every tolerance is
// stated from the sampling noise (batch means or counting statistics) plus the named model errors.
#include "TunnelPhysicsSupport.h"
#include "tunnel/TunnelModel.h"
#include "tunnel/TunnelTheory.h"

#include <QtTest>

#include <algorithm>
#include <numbers>

using namespace pl;
using namespace pl::tunnel_physics;
namespace tt = pl::tunnel_theory;

class TestTunnelPhysics : public QObject {
    Q_OBJECT
private slots:
    void emptyTunnelSettlesWhereTheFluxesBalance_data() {
        QTest::addColumn<double>("speedRatio");
        QTest::addColumn<double>("density");
        QTest::addColumn<double>("width");
        QTest::addColumn<double>("dt");
        QTest::addColumn<int>("warmUp");
        QTest::addColumn<int>("window");
        QTest::addColumn<double>("molecules");
        QTest::newRow("s=9.1, colliding") << 9.13 << 1e20 << 0.1 << 2e-6 << 100 << 400 << 1e4; // λ = 1.2 cm
        QTest::newRow("s=1, collisionless")
            << 1.0 << 1e16 << 0.02 << 1e-5 << 1500 << 4000 << 4e3; // λ = 120 m
    }
    void emptyTunnelSettlesWhereTheFluxesBalance() {
        // Argon at 200 K enters on the left of an empty tunnel (width × width/2) and leaves on the right;
        // top and bottom are mirrors. Every molecule that enters (Ṅ per unit length of the side and time)
        // stays L/v_x: the steady count is n A P(v_x > 0) / F_N = n A (1 + erf s)/2 / F_N, and the gas is
        // the stream's Maxwellian cut to v_x > 0, whose moments are the half-range fluxes over its
        // density: u_x = Ṅ/n', ⟨v_x²⟩ = P_n/(m n') (docs/wind-tunnel.md#inflow). At s = 9.1 that is the
        // stream itself, which collisions keep as it is; at s = 1, 8 % of it is cut away.
        QFETCH(double, speedRatio);
        QFETCH(double, density);
        QFETCH(double, width);
        QFETCH(double, dt);
        QFETCH(int, warmUp);
        QFETCH(int, window);
        QFETCH(double, molecules);
        const double t = 200, m = kArgonMass, height = width / 2, cells = 200;
        const double u = speedRatio * tt::mostProbableSpeed(t, m), open = 0.5 * (1 + std::erf(speedRatio));
        const double fn = density * width * height * open / molecules; // when settled
        TunnelModel model;
        model.reset(tunnelPreset({{"box_width", width},
                                  {"box_height", height},
                                  {"cells_x", 20.0},
                                  {"cells_y", 10.0},
                                  {"fn", fn},
                                  {"dt", dt},
                                  {"stream_density", density},
                                  {"stream_speed", u},
                                  {"stream_temperature", t},
                                  {"initial", std::string("empty")},
                                  {"sample_start", double(warmUp)}},
                                 sides("inflow", "outflow", "specular", "specular")));
        // 5 transits at s = 9.1; at s = 1, 150 transits: the slowest molecules fill in ∝ 1/t (0.03 % left),
        // and they stay so long that the count's mean needs a long window.
        for (int k = 0; k < warmUp; ++k) model.step();
        BatchMeans count;
        for (int k = 0; k < window; ++k) {
            model.step();
            count.values.push_back(double(model.particleCount()));
        }
        const double countTolerance = 4 * count.standardError();
        QVERIFY_WITHIN("particles", count.mean(), molecules, countTolerance);
        QVERIFY(countTolerance < 0.01 * molecules); // the check resolves 1 %
        const tt::HalfRangeFlux flux = tt::halfRangeFlux(density, t, m, u);
        const double n = density * open, ux0 = flux.number / n;
        const double tx0 = m / kBoltzmann * (flux.normalMomentum / (m * n) - ux0 * ux0);
        // A cell of 50 (20) molecules renews them every step (u_x Δt ≥ a cell width), so over the window it
        // has K ≈ its particle-steps independent samples: σ_n/n = 1/√K, σ_u = √(kT/m)/√K, σ_T_x = T_x √(2/K),
        // σ_T = √(2 (T_x² + 2T²)/9K). Every one of the 200 cells within 5 σ.
        const FieldGrid nField = model.field("n"), ux = model.field("ux"), uy = model.field("uy");
        const FieldGrid temperature = model.field("T"), tx = model.field("Tx"), ty = model.field("Ty");
        const double cellVolume = width * height / cells, sampledSteps = double(model.sampledSteps());
        QStringList outliers;
        for (std::size_t c = 0; c < nField.values.size(); ++c) {
            const double k = nField.values[c] * cellVolume / fn * sampledSteps;
            const auto within = [&](const char* what, double value, double target, double sigma) {
                if (!(std::abs(value - target) < 5 * sigma))
                    outliers << QString("cell %1 ").arg(c) + describe(what, value, target, 5 * sigma);
            };
            within("n", nField.values[c], n, n / std::sqrt(k));
            within("ux", ux.values[c], ux0, std::sqrt(kBoltzmann * tx0 / m / k));
            within("uy", uy.values[c], 0.0, std::sqrt(kBoltzmann * t / m / k));
            within("T", temperature.values[c], (tx0 + 2 * t) / 3,
                   std::sqrt(2 * (tx0 * tx0 + 2 * t * t) / (9 * k)));
            within("Tx", tx.values[c], tx0, tx0 * std::sqrt(2 / k));
            within("Ty", ty.values[c], t, t * std::sqrt(2 / k));
        }
        QVERIFY2(outliers.isEmpty(),
                 qPrintable(QString("%1 outliers: ").arg(outliers.size()) + outliers.mid(0, 5).join("; ")));
    }

    void freeMolecularDragOfADiffuseCylinder_data() {
        QTest::addColumn<double>("speedRatio");
        QTest::newRow("s=0.5") << 0.5;
        QTest::newRow("s=2") << 2.0;
        QTest::newRow("s=6") << 6.0;
    }
    void freeMolecularDragOfADiffuseCylinder() {
        // A disc of radius 1 cm at 500 K in argon at 200 K, n = 1e17 m⁻³: λ ≈ 12 m, Kn = λ/2r ≈ 600, so the
        // molecules meet the body and never each other. Every side admits the free stream and removes what
        // leaves, so each molecule arriving at the body comes from the undisturbed Maxwellian
        // (docs/wind-tunnel.md#free-molecular-drag).
        QFETCH(double, speedRatio);
        const double n = 1e17, t = 200, tw = 500, r = 0.01, side = 4 * r;
        const double u = speedRatio * tt::mostProbableSpeed(t, kArgonMass);
        const double dt = 0.1 * r / tt::meanSpeed(t, kArgonMass);
        const double fn = n * (side * side - std::numbers::pi * r * r) / 12000; // 12 000 molecules
        Obstacle disc;
        disc.shape = Obstacle::Shape::Disc;
        disc.x = disc.y = side / 2;
        disc.radius = r;
        TunnelModel model;
        model.reset(tunnelPreset({{"box_width", side},
                                  {"box_height", side},
                                  {"cells_x", 8.0},
                                  {"cells_y", 8.0},
                                  {"fn", fn},
                                  {"dt", dt},
                                  {"stream_density", n},
                                  {"stream_speed", u},
                                  {"stream_temperature", t},
                                  {"initial", std::string("stream")},
                                  {"surface", std::string("diffuse")},
                                  {"body_temperature", tw},
                                  {"sample_start", 50.0}},
                                 sides("inflow", "inflow", "inflow", "inflow"), {disc}));
        for (int k = 0; k < 50; ++k) model.step(); // the re-emitted gas fills in within ~10 steps
        BatchMeans drag;
        for (int k = 0; k < 800; ++k) {
            model.step();
            drag.values.push_back(model.observe().drag);
        }
        const double expected = tt::freeMolecularCylinderDrag(n, t, kArgonMass, u, r, tw);
        // 3 % (the bound) is at least 4 standard errors of the batch means.
        const double error = drag.standardError();
        QVERIFY2(error < 0.0075 * expected,
                 qPrintable(describe("standard error", error, 0, 0.0075 * expected)));
        QVERIFY_WITHIN("drag [N/m]", drag.mean(), expected, 0.03 * expected);
        QVERIFY(std::abs(model.observe().dragAverage / drag.mean() - 1) < 1e-9); // the window's steps
    }

    void pistonDrivenShockMatchesRankineHugoniotAndAlsmeyer() {
        // Argon (VHS, ω = 0.81) at rest, 300 K, n = 1e21 m⁻³ in a 1D strip 80 λ long (λ: the upstream VHS
        // mean free path, Bird eq. 4.65; cells λ/4, 200 molecules each); the piston starts at u_p = 2 a₁,
        // which drives an M = 3 shock (docs/wind-tunnel.md#shock-tube): W = 3 a₁, ρ₂/ρ₁ = 3.
        const double n1 = 1e21, t1 = 300, m = kArgonMass;
        const CollisionModel vhs =
            CollisionModel::fromCrossSection(DsmcCrossSection::Vhs, 0, 4.17e-10, 273, 0.81, 0, m);
        const double lambda = tt::meanFreePath(vhs, n1, t1, m);
        const double a1 = tt::soundSpeed(t1, m);
        const tt::NormalShock jump = tt::normalShockOfMach(3.0, a1);
        const double up = jump.shockSpeed * (1 - 1 / jump.densityRatio);
        const int cells = 320;
        const double length = 80 * lambda, dx = length / cells, height = 1e-3;
        const double fn = n1 * dx * height / 200;
        const double dt = 2e-7; // a quarter of the compressed gas's collision time, 0.13 λ of flight
        TunnelModel model;
        model.reset(tunnelPreset({{"box_width", length},
                                  {"box_height", height},
                                  {"cells_x", double(cells)},
                                  {"cells_y", 1.0},
                                  {"fn", fn},
                                  {"dt", dt},
                                  {"stream_density", n1},
                                  {"stream_temperature", t1},
                                  {"cross_section", kVhs},
                                  {"initial", std::string("rest")},
                                  {"piston_on", true},
                                  {"piston_speed", up},
                                  {"tool_speed", 2 * up}},
                                 sides("specular", "specular", "specular", "specular")));
        const double middle = 0.5 * (1 + jump.densityRatio) * n1;
        const double binWidth = 0.25 * lambda;
        const int behind = 48, ahead = 32; // aligned bins: 12 λ behind the shock, 8 λ ahead
        std::vector<double> aligned(behind + ahead, 0.0);
        std::vector<double> times, positions;
        double plateauCount = 0, plateauLength = 0;
        int alignedSteps = 0;
        std::vector<double> count(cells);
        for (int step = 0; step < 2000; ++step) {
            model.step();
            const double piston = model.pistonX();
            if (piston < 10 * lambda) continue; // the shock forms within a few collision times
            const TunnelState& s = model.state();
            std::fill(count.begin(), count.end(), 0.0);
            for (std::size_t i = 0; i < s.size(); ++i) count[std::min(cells - 1, int(s.x[i] / dx))] += 1;
            // The shock: where the 3-cell mean of the density falls through (n₁ + n₂)/2, from upstream.
            const double x = fallingCrossing(count, middle * dx * height / fn) * dx;
            if (x > length - 8 * lambda) break; // 8 λ of undisturbed gas stay ahead
            times.push_back(model.time());
            positions.push_back(x);
            // The profile is averaged in the frame of the shock's equivalent discontinuity over ±8 λ (where
            // a sharp jump n₁ → n₂ would hold the molecules the window holds), not of the crossing: aligned
            // on their own noisy crossings, the profiles would average to a spuriously steep middle.
            const double xa = x - 8 * lambda, xb = x + 8 * lambda, n2 = jump.densityRatio * n1;
            if (xa < piston + 3 * lambda) continue;
            double window = 0;
            for (double xi : s.x) window += (xi > xa && xi < xb) ? 1.0 : 0.0;
            const double shockAt = (window * fn / height - n1 * xb + n2 * xa) / (n2 - n1);
            // The compressed plateau: 5 λ clear of the piston's start-up layer and 6 λ of the shock.
            for (std::size_t i = 0; i < s.size(); ++i) {
                if (s.x[i] > piston + 5 * lambda && s.x[i] < x - 6 * lambda) plateauCount += 1;
                const int bin = int(std::floor((s.x[i] - shockAt) / binWidth)) + behind;
                if (bin >= 0 && bin < behind + ahead) aligned[bin] += 1;
            }
            plateauLength += std::max(0.0, x - 6 * lambda - (piston + 5 * lambda));
            ++alignedSteps;
        }
        QVERIFY(alignedSteps > 150 && times.size() > 250);
        const double w = fitLine(times, positions).slope;
        QVERIFY_WITHIN("shock speed [m/s]", w, jump.shockSpeed, 0.03 * jump.shockSpeed);
        const double ratio = plateauCount * fn / (plateauLength * height) / n1;
        QVERIFY_WITHIN("ρ₂/ρ₁", ratio, jump.densityRatio, 0.03 * jump.densityRatio);
        // Maximum-slope thickness δ = (n₂ − n₁)/max dn/dx of the profile in the shock's frame, the slope
        // a least-squares line over 5 bins (±λ/2; it lowers the peak slope by ≈ 2 % for a tanh profile).
        std::vector<double> profile(aligned.size());
        for (std::size_t b = 0; b < aligned.size(); ++b)
            profile[b] = aligned[b] * fn / (binWidth * height * alignedSteps);
        const double steepest = steepestFall(profile, binWidth, 2);
        const double thickness = (jump.densityRatio - 1) * n1 / steepest;
        // Alsmeyer (1976, J. Fluid Mech. 74, 497) measured the density thickness of argon shocks by electron-
        // beam absorption; near M = 3 his data give λ₁/δ ≈ 0.26 with λ₁ = 16 μ₁ / (5 ρ₁ √(2π k T₁/m)) (Bird
        // 1994, ch. 12, fits VHS ω = 0.81 to them). Tolerance 18 %: the data's scatter (≈ ±8 %), the cells of
        // λ_VHS/4 (halving them raises λ₁/δ by ≈ 3 %), the 5-bin slope (≈ 2 %) and its noise (≈ 4 %).
        const double lambdaA =
            tt::viscosityMeanFreePath(tt::vhsViscosity(t1, m, 4.17e-10, 273, 0.81), n1, t1, m);
        const double inverse = lambdaA / thickness, alsmeyer = 0.26;
        QVERIFY_WITHIN("λ₁/δ", inverse, alsmeyer, 0.18 * alsmeyer);
    }

    void couetteShearAndSlip_data() {
        QTest::addColumn<double>("knudsen");
        QTest::newRow("Kn=0.1") << 0.1;
        QTest::newRow("free-molecular") << 1.7e5; // n = 1e15 m⁻³ in a 1 cm gap
    }
    void couetteShearAndSlip() {
        // Hard-sphere argon at 273 K between diffuse walls at 273 K moving at ∓133 m/s (0.35 c̄), the gap H
        // = λ/Kn with λ = 1/(√2 π d² n); periodic along x, one column of cells ~λ/4 high
        // (docs/wind-tunnel.md#couette).
        QFETCH(double, knudsen);
        const bool freeMolecular = knudsen > 10;
        const double t = 273, m = kArgonMass, d = 3.595e-10, uw = 133;
        const double n = freeMolecular ? 1e15 : 1e21;
        const double lambda = 1 / (std::sqrt(2.0) * std::numbers::pi * d * d * n);
        const double gap = freeMolecular ? 0.01 : lambda / knudsen;
        const int cells = freeMolecular ? 10 : 40;
        const double width = gap / 4, perCell = freeMolecular ? 400 : 200;
        const double fn = n * width * gap / cells / perCell;
        const double dt = freeMolecular ? 1e-6 : 0.2 * lambda / tt::meanSpeed(t, m);
        // Steady after ~6 viscous times H²/(π² ν), ν ≈ 0.5 λ c̄ (120 collision times at Kn = 0.1). Free
        // molecules settle slowly: those with |v_y| < H/t have not yet crossed by the time t, so the gas
        // near each wall keeps a deficit ∝ 1/t of molecules from the other wall (≈ 0.2 % of the slip by 3
        // ms).
        const int warmUp = freeMolecular ? 3000 : 600, window = freeMolecular ? 1500 : 3000;
        TunnelModel model;
        model.reset(tunnelPreset({{"box_width", width},
                                  {"box_height", gap},
                                  {"cells_x", 1.0},
                                  {"cells_y", double(cells)},
                                  {"fn", fn},
                                  {"dt", dt},
                                  {"stream_density", n},
                                  {"stream_temperature", t},
                                  {"cross_section", std::string("hard-sphere")},
                                  {"diameter", d},
                                  {"initial", std::string("rest")},
                                  {"wall_temperature", t},
                                  {"bottom_wall_speed", -uw},
                                  {"top_wall_speed", uw},
                                  {"sample_start", double(warmUp)}},
                                 sides("periodic", "periodic", "diffuse", "diffuse")));
        for (int k = 0; k < warmUp; ++k) model.step();
        // The shear stress is uniform across the gap in steady flow; it is measured in the interior, 2 λ
        // clear of the Knudsen layers, where the profile is a straight line u = a + G y. A snapshot taken
        // after the collisions sees P_xy = m F_N / V Σ v_x v_y (u_y = 0), but what the flights carry
        // across a plane is its mean over the flight, during which streaming in the gradient adds
        // −G ρ ⟨v_y²⟩ per unit time: τ = −P_xy(snapshot) + (Δt/2) G ρ⟨v_y²⟩ (docs/wind-tunnel.md#couette).
        const double low = freeMolecular ? 0.0 : 2 * lambda, high = gap - low;
        const double interior = width * (high - low);
        BatchMeans snapshot;
        double sumVy2 = 0;
        for (int k = 0; k < window; ++k) {
            model.step();
            const TunnelState& s = model.state();
            double sum = 0;
            for (std::size_t i = 0; i < s.size(); ++i)
                if (s.y[i] > low && s.y[i] < high) sum += s.vx[i] * s.vy[i], sumVy2 += s.vy[i] * s.vy[i];
            snapshot.values.push_back(-sum * fn * m / interior);
        }
        const double density = double(model.particleCount()) * fn / (width * gap);
        // The same interior as a straight line, extrapolated to the walls: the slip is the wall speed
        // minus that line's value there, averaged over both walls. Collisions conserve momentum, so the
        // velocity field needs no such correction.
        const FieldGrid ux = model.field("ux"), temperature = model.field("T");
        std::vector<double> ys, us;
        for (int j = 0; j < cells; ++j) {
            const double y = (j + 0.5) * gap / cells;
            if (y > low && y < high) ys.push_back(y), us.push_back(ux.values[j]);
        }
        const Line profile = fitLine(ys, us);
        const double streaming = 0.5 * dt * profile.slope * sumVy2 / window * fn * m / interior;
        BatchMeans shear = snapshot;
        for (double& v : shear.values) v += streaming;
        const double slip = 0.5 * ((profile.intercept + uw) + (uw - profile.intercept - profile.slope * gap));
        tt::CouetteFlow expected;
        double shearTolerance, slipTolerance;
        if (freeMolecular) {
            // Exact: each wall's molecules cross with its velocity (n c̄/4 per area and time each way).
            expected = tt::freeMolecularCouette(density, t, m, -uw, uw);
            shearTolerance = 0.03 * expected.shearStress;
            slipTolerance = 0.03 * uw;
        } else {
            // Navier–Stokes with first-order slip ζ = 1.1113 λ (Ohwada, Sone & Aoki 1989), hard-sphere μ at
            // the gas's mean temperature (viscous heating raises it ~4 %). 4 %: 4 standard errors plus the
            // cells of λ/4 and Δt of 0.2 collision times (≲ 1 %, Alexander, Garcia & Alder 1998;
            // Hadjiconstantinou 2000) and the O(Kn²) beyond first-order slip (~1 % at Kn = 0.1).
            double meanT = 0;
            for (double v : temperature.values) meanT += v / cells;
            const double mu = tt::hardSphereViscosity(meanT, m, d);
            expected = tt::slipCouette(mu, tt::kHardSphereSlipCoefficient * lambda, gap, -uw, uw);
            // The slip is a line's intercept: its noise and the Knudsen layers' curvature near the fit.
            shearTolerance = 0.04 * expected.shearStress, slipTolerance = 0.1 * expected.wallSlip;
        }
        QVERIFY2(4 * shear.standardError() < shearTolerance,
                 qPrintable(describe("4 standard errors", 4 * shear.standardError(), 0, shearTolerance)));
        QVERIFY_WITHIN("shear stress [Pa]", shear.mean(), expected.shearStress, shearTolerance);
        QVERIFY_WITHIN("wall slip [m/s]", slip, expected.wallSlip, slipTolerance);
    }

    void collisionRateMatchesKineticTheory_data() {
        QTest::addColumn<QString>("crossSection");
        QTest::newRow("vhs") << "vhs";
        QTest::newRow("hard-sphere") << "hard-sphere";
        QTest::newRow("maxwell") << "maxwell";
    }
    void collisionRateMatchesKineticTheory() {
        // A closed box of argon at rest, 300 K, 10 × 10 cells one mean free path wide, 200 molecules each.
        QFETCH(QString, crossSection);
        const double n = 1e21, t = 300, m = kArgonMass;
        TunnelModel probe;
        probe.reset(tunnelPreset({{"cross_section", crossSection.toStdString()},
                                  {"stream_density", n},
                                  {"stream_temperature", t}}));
        const double nu = tt::collisionRate(probe.collisionModel(), n, t, m); // ν = n ⟨σ c_r⟩
        const double lambda = tt::meanFreePath(probe.collisionModel(), n, t, m);
        const double side = 10 * lambda, fn = n * side * side / 20000;
        TunnelModel model;
        model.reset(tunnelPreset({{"cross_section", crossSection.toStdString()},
                                  {"box_width", side},
                                  {"box_height", side},
                                  {"cells_x", 10.0},
                                  {"cells_y", 10.0},
                                  {"fn", fn},
                                  {"dt", 0.1 / nu},
                                  {"stream_density", n},
                                  {"stream_temperature", t},
                                  {"initial", std::string("rest")}},
                                 sides("specular", "specular", "specular", "specular")));
        for (int k = 0; k < 50; ++k) model.step(); // five cell crossings: the occupancy is random
        const auto& p = model.parameters();
        const double cellVolume = p.cellWidth() * p.cellHeight();
        const double meanSigmaCr = model.collisionModel().meanSigmaCr(t, m);
        double accepted = 0, expectedGivenCells = 0;
        BatchMeans perParticleRate;
        for (int k = 0; k < 300; ++k) {
            model.step();
            // NTC's expectation given this step's cells (docs/dsmc.md#ntc-candidate-pairs).
            std::vector<double> occupancy(100, 0.0);
            for (std::uint32_t c : model.state().cell) occupancy[c] += 1;
            for (double nc : occupancy)
                expectedGivenCells += 0.5 * nc * (nc - 1) * fn * meanSigmaCr * p.dt / cellVolume;
            accepted += double(model.lastCollisions());
            perParticleRate.values.push_back(2.0 * double(model.lastCollisions()) /
                                             (double(model.particleCount()) * p.dt));
        }
        // Accepted collisions are close to Poisson given the cells: 4 standard errors √μ.
        QVERIFY_WITHIN("collisions", accepted, expectedGivenCells, 4 * std::sqrt(expectedGivenCells));
        // Averaged over random positions ⟨N_c (N_c − 1)⟩ = N̄_c² (1 − 1/N): each molecule collides at ν.
        const double expectedRate = nu * (1 - 1.0 / double(model.particleCount()));
        const double tolerance = 4 * perParticleRate.standardError();
        QVERIFY_WITHIN("collisions per molecule per second", perParticleRate.mean(), expectedRate, tolerance);
        QVERIFY(tolerance < 0.01 * expectedRate);
        QVERIFY(std::abs(model.field("T").values[0] / t - 1) < 0.05); // still at 300 K
    }
};

QTEST_APPLESS_MAIN(TestTunnelPhysics)
#include "tst_tunnel_physics.moc"
