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
    };
    return specs;
}

} // namespace pl::ui
