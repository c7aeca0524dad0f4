// ReportTheory: one function per theory, each reading the last sample (or the run's samples) of the
// series by column name, so a kind without the columns simply has no row. Verdicts are worded once here;
// numbers keep four significant digits as the readouts do.
#include "ReportTheory.h"

#include "catalog/ModelCatalog.h"
#include "common/Model.h"
#include "common/Statistics.h"
#include "common/TimeSeries.h"
#include "dsmc/DsmcTheory.h"
#include "fluid/FluidSweep.h"
#include "tunnel/TunnelModel.h"
#include "tunnel/TunnelTheory.h"

#include <algorithm>
#include <cmath>

namespace pl::ui {

namespace {

constexpr double kKsSignificance = 0.01;  // the 1 % critical value
constexpr double kFreeMolecularKn = 10.0; // Kn from which a body sees free-molecular flow
constexpr double kMaxwellianKurtosis = 3.0;
constexpr double kAreaChanged = 0.05;  // a compression or expansion: the area changed by more than this
constexpr double kOnTheAdiabat = 0.05; // kT·A within this of its start: the slow piston's adiabat

QString number(double value) {
    return QString::number(value, 'g', 4);
}
QString percent(double share) {
    return QString::number(100.0 * share, 'g', 3) + QStringLiteral(" %");
}

// Reads columns of the series by name; NaN for a column the kind does not have or an empty series.
class Columns {
public:
    explicit Columns(const TimeSeries& series) : series_(series) {}
    double first(const std::string& name) const {
        const int c = index(name);
        return c < 0 || series_.rows() == 0 ? NAN : series_.row(0)[static_cast<std::size_t>(c)];
    }
    double last(const std::string& name) const {
        const int c = index(name);
        return c < 0 || series_.rows() == 0 ? NAN
                                            : series_.row(series_.rows() - 1)[static_cast<std::size_t>(c)];
    }
    // Every finite value of the column after the first sample (the state the run started from).
    std::vector<double> run(const std::string& name) const {
        std::vector<double> values;
        const int c = index(name);
        for (std::size_t r = 1; c >= 0 && r < series_.rows(); ++r)
            if (const double v = series_.row(r)[static_cast<std::size_t>(c)]; std::isfinite(v))
                values.push_back(v);
        return values;
    }

private:
    int index(const std::string& name) const {
        const auto& columns = series_.columns();
        const auto it = std::find(columns.begin(), columns.end(), name);
        return it == columns.end() ? -1 : static_cast<int>(it - columns.begin());
    }
    const TimeSeries& series_;
};

double paramNumber(const ParamValues& params, const std::string& key) {
    const auto it = params.find(key);
    return it != params.end() && std::holds_alternative<double>(it->second) ? std::get<double>(it->second)
                                                                            : NAN;
}

// Half the summed difference of the histogram's bin shares and the theory's (the total variation
// distance, 0 … 1): the share of the area where the two differ.
double areaOutsideTheory(const NamedHistogram& h) {
    const double total = h.counts.total();
    if (!(total > 0) || !h.theoryDensity) return NAN;
    double difference = 0.0;
    for (std::size_t i = 0; i < h.counts.bins(); ++i)
        difference += std::abs(h.counts.count(i) / total -
                               h.theoryDensity(h.counts.binCentre(i)) * h.counts.binWidth());
    return 0.5 * difference;
}

void gasRows(const Model& model, const Columns& columns, std::vector<ReportRow>& rows) {
    const ParamValues params = model.params();
    const bool mixture = std::isfinite(columns.last("ks_a")) && std::isfinite(columns.last("ks_b"));
    const std::vector<NamedHistogram> histograms = model.histograms();
    for (const std::string species : {"a", "b"}) {
        const double ks = columns.last("ks_" + species);
        if (!std::isfinite(ks)) continue;
        const QString of = mixture
                               ? QStringLiteral(", species %1").arg(QString::fromStdString(species).toUpper())
                               : QString();
        // All disks in a one-species scene, else the preset's count of the species.
        const double n = mixture ? paramNumber(params, "count_" + species) : columns.last("particles");
        if (n >= 2) {
            const double critical = ksCritical(n, kKsSignificance);
            rows.push_back(
                {QStringLiteral("KS distance of the speeds to Maxwell–Boltzmann%1").arg(of),
                 number(ks),
                 {},
                 QStringLiteral("1 % critical value 1.63/√n = %1 for n = %2 disks: %3")
                     .arg(number(critical))
                     .arg(n)
                     .arg(ks <= critical ? QStringLiteral("consistent with Maxwell–Boltzmann")
                                         : QStringLiteral("above it, not (yet) Maxwell–Boltzmann"))});
        }
        const double kT = columns.last(mixture ? "kT_" + species : "kT");
        const auto histogram =
            std::find_if(histograms.begin(), histograms.end(),
                         [&](const NamedHistogram& h) { return h.name == "speed_" + species; });
        if (std::isfinite(kT) && histogram != histograms.end())
            rows.push_back(
                {QStringLiteral("Maxwell–Boltzmann fit of the speeds%1: kT").arg(of), number(kT),
                 QStringLiteral("M·L²/T²"),
                 QStringLiteral("maximum-likelihood fit (the mean kinetic energy per disk in the plane); "
                                "the histogram differs from the fitted curve by %1 of its area")
                     .arg(percent(areaOutsideTheory(*histogram)))});
    }
}

// A compression or expansion by the piston: on the adiabat of a 2D monatomic ideal gas (γ = 2) kT·A stays
// what it was (docs/gas.md); a fast piston drives a compression wave and heats more. The area is the one
// the ideal-gas pressure was computed with, A = N kT / p_ideal.
void compressionRows(const Columns& columns, std::vector<ReportRow>& rows) {
    const auto area = [&](bool atEnd) {
        const auto read = [&](const std::string& name) {
            return atEnd ? columns.last(name) : columns.first(name);
        };
        return read("particles") * read("kT") / read("pressure_ideal");
    };
    const double a0 = area(false), a1 = area(true);
    if (!std::isfinite(a0) || !std::isfinite(a1) || !(a0 > 0) || std::abs(a1 / a0 - 1.0) <= kAreaChanged)
        return;
    const double ratio = columns.last("kT") * a1 / (columns.first("kT") * a0);
    rows.push_back({QStringLiteral("kT·A at the end against its start (area × %1)").arg(number(a1 / a0)),
                    number(ratio),
                    {},
                    QStringLiteral("on the adiabat of a 2D monatomic gas (γ = 2) kT·A stays constant: %1")
                        .arg(std::abs(ratio - 1.0) <= kOnTheAdiabat
                                 ? QStringLiteral("within 5 %, a slow (adiabatic) change")
                                 : (ratio > 1.0 ? QStringLiteral("heated beyond the adiabat (a fast piston's "
                                                                 "compression wave, or Heat)")
                                                : QStringLiteral("cooled below the adiabat (Cool, or a fast "
                                                                 "expansion)")))});
}

void dsmcRows(const Columns& columns, std::vector<ReportRow>& rows) {
    for (const int k : {4, 6, 8}) {
        const std::string name = std::string("M").append(std::to_string(k)); // GCC 12 misreads "M" + string
        const double measured = columns.last(name), exact = columns.last(name + "_bkw");
        if (!std::isfinite(measured) || !std::isfinite(exact)) continue;
        rows.push_back(
            {QStringLiteral("Moment M%1 / M%1(eq) against BKW").arg(k),
             number(measured),
             {},
             QStringLiteral("exact (BKW) %1; error %2 (%3)")
                 .arg(number(exact), number(measured - exact), percent((measured - exact) / exact))});
    }
    if (const double kurtosis = columns.last("kurtosis_vx"); std::isfinite(kurtosis))
        rows.push_back({QStringLiteral("Kurtosis of v_x"),
                        number(kurtosis),
                        {},
                        QStringLiteral("a Maxwellian's is 3; difference %1")
                            .arg(number(kurtosis - kMaxwellianKurtosis))});
}

// The drag of body 0 against a diffuse cylinder's in free-molecular flow. A disc centred on a specular
// bottom or top side is half a cylinder (the side is its symmetry plane), so the theory is halved.
void tunnelRows(const Model& model, const Columns& columns, std::vector<ReportRow>& rows) {
    const auto* tunnel = dynamic_cast<const TunnelModel*>(&model);
    if (!tunnel || tunnel->obstacles().empty()) return;
    const TunnelParams& p = tunnel->parameters();
    const Obstacle& body = tunnel->obstacles().front();
    if (body.shape != Obstacle::Shape::Disc || p.surface != TunnelSurface::Diffuse || !(p.streamSpeed > 0))
        return;
    const auto onSymmetryPlane = [&](double sideY, TunnelBoundary side) {
        return side == TunnelBoundary::Specular && std::abs(body.y - sideY) <= 1e-9 * p.boxHeight;
    };
    const bool half = onSymmetryPlane(0.0, p.bottom) || onSymmetryPlane(p.boxHeight, p.top);
    const double theory = (half ? 0.5 : 1.0) * tunnel_theory::freeMolecularCylinderDrag(
                                                   p.streamDensity, p.streamTemperature, p.mass(),
                                                   p.streamSpeed, body.radius, p.bodyTemperature);
    const bool averaged = columns.last("sampled_steps") > 0;
    const double drag = averaged ? columns.last("drag_avg") : columns.last("drag");
    if (!std::isfinite(drag)) return;
    const double kn = tunnel->knudsenNumber();
    const QString applies =
        kn >= kFreeMolecularKn
            ? QStringLiteral("Kn = %1: free-molecular flow, where the drag tends to this value")
                  .arg(number(kn))
            : QStringLiteral(
                  "Kn = %1: collisions shield the body, so this is the rarefied limit, not a prediction")
                  .arg(number(kn));
    rows.push_back({averaged ? QStringLiteral("Drag of the body, averaged over the fields window")
                             : QStringLiteral("Drag of the body, last step"),
                    number(drag), QStringLiteral("N/m"),
                    QStringLiteral("free-molecular value for a diffuse %1cylinder %2 N/m (ratio %3); %4")
                        .arg(half ? QStringLiteral("half ") : QString(), number(theory),
                             number(drag / theory), applies)});
}

void fluidRows(const Columns& columns, std::vector<ReportRow>& rows) {
    const std::vector<double> mean = columns.run("density_error_mean");
    const std::vector<double> worst = columns.run("density_error_max");
    if (!mean.empty()) {
        double sum = 0.0;
        for (double v : mean) sum += v;
        const double average = sum / static_cast<double>(mean.size());
        const double tolerance = fluid::FluidSweepSetup{}.tolerance;
        rows.push_back({QStringLiteral("Mean density error ρ/ρ₀ − 1, averaged over the run"),
                        percent(average),
                        {},
                        QStringLiteral("the methods lab's tolerance %1: %2")
                            .arg(percent(tolerance), average <= tolerance
                                                         ? QStringLiteral("within it, incompressible enough")
                                                         : QStringLiteral("above it, over-compressed"))});
    }
    if (!worst.empty())
        rows.push_back({QStringLiteral("Largest compression of any particle in the run"),
                        percent(*std::max_element(worst.begin(), worst.end())),
                        {},
                        QStringLiteral("at the end: %1").arg(percent(columns.last("density_error_max")))});
    const double front = columns.last("front_Z"), bound = columns.last("front_Z_shallow_water");
    if (std::isfinite(front) && std::isfinite(bound))
        rows.push_back({QStringLiteral("Surge front Z = z/a at T = %1").arg(number(columns.last("front_T"))),
                        number(front),
                        {},
                        QStringLiteral("Ritter's shallow-water bound 1 + 2T = %1: %2")
                            .arg(number(bound),
                                 front <= bound ? QStringLiteral("below it, as measured fronts are (Martin & "
                                                                 "Moyce 1952)")
                                                : QStringLiteral("above it"))});
}

} // namespace

std::vector<ReportRow> theoryReadouts(const Model& model, const TimeSeries& series) {
    std::vector<ReportRow> rows;
    const Columns columns(series);
    // A kind gets the rows whose columns (or model) it has: no list of kinds to keep up to date.
    gasRows(model, columns, rows);
    compressionRows(columns, rows);
    dsmcRows(columns, rows);
    tunnelRows(model, columns, rows);
    fluidRows(columns, rows);
    return rows;
}

} // namespace pl::ui
