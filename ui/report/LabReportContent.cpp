// LabReportContent: the report's facts, read from the controller's model, its registration and series.
// The report is written in English whatever the interface language (a document to hand in, one wording
// for every reader); the core's labels are translated where a translator is installed. Theory comes only from
// what the core computes (ReportTheory.cpp).
#include "LabReport.h"

#include "ReportTheory.h"

#include "SimulationController.h"
#include "catalog/ModelCatalog.h"
#include "i18n/Translations.h"
#include "plots/DistributionPlot.h"
#include "plots/PlotExport.h"
#include "plots/SeriesPlot.h"
#include "plots/SeriesPlotSpecs.h"
#include "viewport/ScenePainter.h"

#include <qcustomplot.h> // before the use of SeriesPlot, which names QCPAxis

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QSysInfo>
#include <cmath>
#include <thread>

namespace pl::ui {

namespace {

const QSize kSceneImageSize(1200, 900); // [px] the viewport picture, 4:3
const QSize kPlotWidgetSize(680, 380);  // [px] the plots' layout size while they are filled

QString valueText(const ParamValue& value) {
    if (const auto* number = std::get_if<double>(&value))
        return QString::fromStdString(formatNumber(*number));
    if (const auto* flag = std::get_if<bool>(&value))
        return *flag ? QStringLiteral("on") : QStringLiteral("off");
    return QString::fromStdString(std::get<std::string>(value));
}

QString cpuName() {
    QFile info(QStringLiteral("/proc/cpuinfo"));
    if (info.open(QIODevice::ReadOnly))
        for (const QByteArray& line : info.readAll().split('\n'))
            if (line.startsWith("model name"))
                return QString::fromUtf8(line.mid(line.indexOf(':') + 1)).trimmed();
    return QSysInfo::currentCpuArchitecture();
}

QString machineText() {
    return QStringLiteral("%1, %2 (%3 hardware threads), Qt %4")
        .arg(QSysInfo::prettyProductName(), cpuName())
        .arg(std::thread::hardware_concurrency())
        .arg(QString::fromLatin1(qVersion()));
}

} // namespace

LabReportContent gatherLabReport(SimulationController& controller, const QString& name,
                                 const QString& description,
                                 const std::vector<LabReportContent::Plot>& plots) {
    LabReportContent c;
    const Model* model = controller.model();
    if (!model) return c;
    const Preset preset = model->toPreset();
    const ModelDescriptor* kind = findModel(model->kind());
    c.title = name;
    c.description = description;
    if (kind) {
        c.kindTitle = coreText(kind->title);
        c.units = coreText(kind->units.name) + QStringLiteral(": ") + coreText(kind->units.summary);
    }
    const ParamValues params = model->params();
    for (const ParamSpec& spec : model->paramSpecs()) {
        const auto it = params.find(spec.key);
        if (it == params.end()) continue;
        c.parameters.push_back({coreText(spec.label), valueText(it->second), coreText(spec.unit),
                                QString::fromStdString(spec.key)});
    }

    QString timeUnit;
    if (kind)
        for (const SeriesColumn& column : kind->series)
            if (column.name == "time") timeUnit = QString::fromStdString(column.unit);
    const auto integrator = params.find("integrator");
    c.run.push_back({QStringLiteral("Seed"), QString::number(preset.seed), {}, {}});
    c.run.push_back({QStringLiteral("Steps"), QString::number(model->stepCount()), {}, {}});
    c.run.push_back({QStringLiteral("Simulated time"), QString::number(model->time(), 'g', 6), timeUnit, {}});
    if (integrator != params.end())
        c.run.push_back({QStringLiteral("Integrator"), valueText(integrator->second), {}, {}});
    c.run.push_back({QStringLiteral("Backend"),
                     model->backend() == "gl" ? QStringLiteral("GPU (OpenGL 4.3 compute)")
                                              : QStringLiteral("CPU (OpenMP)"),
                     {},
                     {}});
    c.run.push_back({QStringLiteral("Machine"), machineText(), {}, {}});
    c.run.push_back(
        {QStringLiteral("Written"), QDateTime::currentDateTimeUtc().toString(Qt::ISODate), {}, {}});

    const TimeSeries& table = controller.series()->table();
    if (table.rows() > 0 && kind) {
        const std::vector<double>& last = table.row(table.rows() - 1);
        for (std::size_t i = 0; i < table.columns().size() && i < last.size(); ++i) {
            const std::string& name = table.columns()[i];
            if (name == "step" || name == "time" || std::isnan(last[i])) continue;
            ReportRow row{QString::fromStdString(name), QString::number(last[i], 'g', 5), {}, {}};
            for (const SeriesColumn& column : kind->series)
                if (column.name == name) {
                    row.name = coreText(column.label);
                    row.unit = QString::fromStdString(column.unit);
                }
            c.readouts.push_back(row);
        }
    }
    c.theory = theoryReadouts(*model, table);
    for (const NamedHistogram& histogram : model->histograms())
        if (!histogram.summary.empty())
            c.distributions << QStringLiteral("%1: %2").arg(coreText(histogram.label),
                                                            QString::fromStdString(histogram.summary));
    c.scene = renderScene(model->sceneView(), kSceneImageSize);
    c.plots = plots;
    return c;
}

QString exportLabReport(SimulationController& controller, const QString& name, const QString& description,
                        const QString& path, const QString& dataDir) {
    const Model* model = controller.model();
    if (!model) return QStringLiteral("There is no experiment to report on.");
    const QString kind = QString::fromStdString(model->kind());
    std::vector<std::unique_ptr<QWidget>> widgets;
    std::vector<LabReportContent::Plot> plots;
    // Laid out and refreshed as a shown dock, without a window.
    const auto shown = [&](auto plot) {
        plot->setAttribute(Qt::WA_DontShowOnScreen);
        plot->resize(kPlotWidgetSize);
        plot->show();
        plot->refresh();
        widgets.push_back(std::move(plot));
    };
    for (const SeriesPlotSpec& spec : seriesPlotSpecs()) {
        if (!spec.kinds.contains(kind)) continue;
        auto plot = std::make_unique<SeriesPlot>(&controller, spec);
        plots.push_back({spec.objectName, spec.title, plot->plot()});
        shown(std::move(plot));
    }
    // The distributions the kind's registration lists (its docks: "speedHistogram" shows every histogram
    // named speed…), each with the density theory predicts, titled by what is binned.
    if (const ModelDescriptor* descriptor = findModel(model->kind()))
        for (const std::string& dock : descriptor->distributions) {
            const std::string prefix = dock.substr(0, dock.rfind("Histogram"));
            QString axis;
            for (const NamedHistogram& histogram : model->histograms())
                if (histogram.name.rfind(prefix, 0) == 0) axis = QString::fromStdString(histogram.axis);
            if (axis.isEmpty()) continue; // the model has none of them now
            const QString name = QString::fromStdString(dock);
            auto plot = std::make_unique<DistributionPlot>(&controller, name, QString::fromStdString(prefix));
            plots.push_back({name, QStringLiteral("Distribution of %1").arg(axis), plot->plot()});
            shown(std::move(plot));
        }
    if (const QString problem = writeLabReport(gatherLabReport(controller, name, description, plots), path);
        !problem.isEmpty())
        return problem;
    if (!dataDir.isEmpty())
        for (const LabReportContent::Plot& plot : plots)
            if (const QString problem = savePlotCsv(plot.plot, QDir(dataDir).filePath(plot.name + ".csv"));
                !problem.isEmpty())
                return problem;
    return {};
}

} // namespace pl::ui
