// Series plot specifications. Column names are the models' seriesColumns().
#include "SeriesPlotSpecs.h"

#include <QCoreApplication>

namespace pl::ui {

namespace {
QString tr(const char* text) {
    return QCoreApplication::translate("SeriesPlotSpecs", text);
}
const QColor kBlue(40, 90, 170), kOrange(220, 120, 20), kGreen(40, 140, 70), kRed(190, 40, 40),
    kGrey(90, 90, 90);
} // namespace

const std::vector<SeriesPlotSpec>& seriesPlotSpecs() {
    static const std::vector<SeriesPlotSpec> specs = {
        {"energyPlot",
         tr("Energy"),
         {"gas"},
         {tr("energy"),
          {{"kinetic", tr("kinetic"), kBlue},
           {"potential", tr("potential"), kOrange},
           {"total", tr("total"), kGrey}}},
         {tr("|E − E₀| / E₀"), {{"energy_drift", tr("relative drift"), kRed}}, true}},
        {"thermodynamicsPlot",
         tr("Thermodynamics"),
         {"gas"},
         {tr("pressure"),
          {{"pressure_wall", tr("P from wall impulses"), kBlue},
           {"pressure_virial", tr("P from the virial"), kGreen},
           {"pressure_ideal", tr("N kT / A"), kGrey}}},
         {tr("kT"),
          {{"kT", tr("kT"), kRed}, {"kT_a", tr("kT of A"), kBlue}, {"kT_b", tr("kT of B"), kOrange}}}},
        {"temperaturesPlot",
         tr("Temperatures"),
         {"dsmc"},
         {tr("temperature [K]"),
          {{"Tx", tr("T_x"), kBlue}, {"T_perp", tr("T_⊥"), kOrange}, {"T", tr("T"), kGrey}}},
         {tr("T_x − T_⊥ [K]"), {{"anisotropy", tr("anisotropy"), kRed}}, true}},
        {"momentsPlot",
         tr("Moments"),
         {"dsmc"},
         {tr("M_2k / M_2k(eq)"),
          {{"M4", tr("M4"), kBlue},
           {"M6", tr("M6"), kGreen},
           {"M8", tr("M8"), kOrange},
           {"M4_bkw", tr("M4 exact (BKW)"), kBlue, Qt::DashLine},
           {"M6_bkw", tr("M6 exact (BKW)"), kGreen, Qt::DashLine},
           {"M8_bkw", tr("M8 exact (BKW)"), kOrange, Qt::DashLine}}},
         {tr("KL to Maxwellian"), {{"kl_divergence", tr("KL divergence [nats]"), kRed}}, true}},
        {"collisionsPlot",
         tr("Collisions"),
         {"dsmc"},
         {tr("pairs per step"), {{"ng", tr("candidates ng"), kBlue}, {"nc", tr("collisions nc"), kRed}}},
         {tr("(σ c_r)_max [m³/s]"), {{"sigma_cr_max", tr("(σ c_r)_max"), kGrey}}}},
    };
    return specs;
}

} // namespace pl::ui
