// Series plot specifications: the registrations' Qt-free plot specs, with colours and translated texts.
#include "SeriesPlotSpecs.h"

#include "catalog/ModelCatalog.h"
#include "i18n/Translations.h"

namespace pl::ui {

namespace {
SeriesPanel panelOf(const PlotPanel& plot) {
    SeriesPanel panel;
    panel.yLabel = coreText(plot.yLabel);
    for (const PlotCurve& c : plot.curves)
        panel.curves.push_back({QString::fromStdString(c.column), coreText(c.label),
                                QColor(c.colour.red, c.colour.green, c.colour.blue),
                                c.dashed ? Qt::DashLine : Qt::SolidLine});
    panel.logarithmic = plot.logarithmic;
    panel.xColumn = QString::fromStdString(plot.xColumn);
    panel.xLabel = coreText(plot.xLabel);
    panel.profile = plot.profile;
    return panel;
}
} // namespace

const std::vector<SeriesPlotSpec>& seriesPlotSpecs() {
    static const std::vector<SeriesPlotSpec> specs = [] {
        std::vector<SeriesPlotSpec> list;
        for (const ModelDescriptor& model : modelCatalog())
            for (const PlotSpec& plot : model.plots)
                list.push_back({QString::fromStdString(plot.name),
                                coreText(plot.title),
                                {QString::fromStdString(model.kind)},
                                panelOf(plot.upper),
                                panelOf(plot.lower),
                                plot.needsBodies});
        return list;
    }();
    return specs;
}

QStringList distributionKinds(const QString& distribution) {
    QStringList kinds;
    for (const ModelDescriptor& model : modelCatalog())
        for (const std::string& name : model.distributions)
            if (QString::fromStdString(name) == distribution)
                kinds.push_back(QString::fromStdString(model.kind));
    return kinds;
}

} // namespace pl::ui
