// Series plot specifications. Column names are the models' seriesColumns().
#include "SeriesPlotSpecs.h"

#include <QCoreApplication>

namespace pl::ui {

namespace {
// lupdate files these tr() calls under the enclosing namespace, so that is their context.
QString tr(const char* text) {
    return QCoreApplication::translate("pl::ui", text);
}
const QColor kBlue(40, 90, 170), kOrange(220, 120, 20), kGreen(40, 140, 70), kRed(190, 40, 40),
    kGrey(90, 90, 90);

// Columns against time.
SeriesPanel timePanel(const QString& yLabel, std::vector<SeriesCurve> curves, bool logarithmic = false) {
    SeriesPanel panel;
    panel.yLabel = yLabel;
    panel.curves = std::move(curves);
    panel.logarithmic = logarithmic;
    return panel;
}

// Columns against another column.
SeriesPanel xyPanel(const QString& xColumn, const QString& xLabel, const QString& yLabel,
                    std::vector<SeriesCurve> curves) {
    SeriesPanel panel = timePanel(yLabel, std::move(curves));
    panel.xColumn = xColumn;
    panel.xLabel = xLabel;
    return panel;
}

// The model's profiles of its latest state.
SeriesPanel profilePanel(const QString& xLabel, const QString& yLabel, std::vector<SeriesCurve> curves,
                         bool logarithmic) {
    SeriesPanel panel = timePanel(yLabel, std::move(curves), logarithmic);
    panel.xLabel = xLabel;
    panel.profile = true;
    return panel;
}
} // namespace

const std::vector<SeriesPlotSpec>& seriesPlotSpecs() {
    static const std::vector<SeriesPlotSpec> specs = {
        {"energyPlot",
         tr("Energy"),
         {"gas"},
         timePanel(tr("energy"), {{"kinetic", tr("kinetic"), kBlue},
                                  {"potential", tr("potential"), kOrange},
                                  {"total", tr("total"), kGrey}}),
         timePanel(tr("|E − E₀| / E₀"), {{"energy_drift", tr("relative drift"), kRed}}, true)},
        {"thermodynamicsPlot",
         tr("Thermodynamics"),
         {"gas"},
         timePanel(tr("pressure"), {{"pressure_wall", tr("P from wall impulses"), kBlue},
                                    {"pressure_virial", tr("P from the virial"), kGreen},
                                    {"pressure_ideal", tr("N kT / A"), kGrey}}),
         timePanel(
             tr("kT"),
             {{"kT", tr("kT"), kRed}, {"kT_a", tr("kT of A"), kBlue}, {"kT_b", tr("kT of B"), kOrange}})},
        {"temperaturesPlot",
         tr("Temperatures"),
         {"dsmc"},
         timePanel(tr("temperature [K]"),
                   {{"Tx", tr("T_x"), kBlue}, {"T_perp", tr("T_⊥"), kOrange}, {"T", tr("T"), kGrey}}),
         timePanel(tr("T_x − T_⊥ [K]"), {{"anisotropy", tr("anisotropy"), kRed}}, true)},
        {"momentsPlot",
         tr("Moments"),
         {"dsmc"},
         timePanel(tr("M_2k / M_2k(eq)"), {{"M4", tr("M4"), kBlue},
                                           {"M6", tr("M6"), kGreen},
                                           {"M8", tr("M8"), kOrange},
                                           {"M4_bkw", tr("M4 exact (BKW)"), kBlue, Qt::DashLine},
                                           {"M6_bkw", tr("M6 exact (BKW)"), kGreen, Qt::DashLine},
                                           {"M8_bkw", tr("M8 exact (BKW)"), kOrange, Qt::DashLine}}),
         timePanel(tr("KL to Maxwellian"), {{"kl_divergence", tr("KL divergence [nats]"), kRed}}, true)},
        {"collisionsPlot",
         tr("Collisions"),
         {"dsmc"},
         timePanel(tr("pairs per step"),
                   {{"ng", tr("candidates ng"), kBlue}, {"nc", tr("collisions nc"), kRed}}),
         timePanel(tr("(σ c_r)_max [m³/s]"), {{"sigma_cr_max", tr("(σ c_r)_max"), kGrey}})},
        {"densityErrorPlot",
         tr("Density error"),
         {"fluid"},
         profilePanel(tr("iterations done in the last step"), tr("compression ρ/ρ₀ − 1"),
                      {{"density_error_mean", tr("mean"), kBlue}, {"density_error_max", tr("max"), kRed}},
                      true),
         timePanel(tr("compression ρ/ρ₀ − 1"),
                   {{"density_error_mean", tr("mean"), kBlue}, {"density_error_max", tr("max"), kRed}},
                   true)},
        {"frontPlot",
         tr("Dam-break front"),
         {"fluid"},
         xyPanel("front_T", tr("T = n t √(g/a)"), tr("front Z = z / a"),
                 {{"front_Z", tr("surge front"), kBlue},
                  {"front_Z_shallow_water", tr("shallow-water bound 1 + 2T"), kGrey, Qt::DashLine}}),
         {}},
        {"flowPlot",
         tr("Flow"),
         {"fluid"},
         timePanel(tr("kinetic energy Σ ½ v²"), {{"kinetic", tr("kinetic"), kBlue}}),
         timePanel(tr("neighbours within h"), {{"neighbours_mean", tr("mean"), kGreen},
                                               {"neighbours_max", tr("max"), kOrange},
                                               {"neighbours_min", tr("min"), kGrey}})},
    };
    return specs;
}

} // namespace pl::ui
