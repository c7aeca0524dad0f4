// Headless methods lab: runs one page to completion and saves its plot and data (particlelab --lab).
#include "LabBatch.h"

#include "DsmcPage.h"
#include "EchoPage.h"
#include "FluidPage.h"
#include "GasSweepPage.h"
#include "LabRunner.h"
#include "MethodsLab.h"
#include "RelaxPage.h"
#include "StabilityPage.h"
#include "plots/PlotExport.h"

#include <QEventLoop>
#include <qcustomplot.h>

namespace pl::ui {

QStringList labPageNames() {
    return {"echo", "sweep", "stability", "fluid-map", "fluid-cost", "dsmc", "relax"};
}

QString runLabPage(const QString& page, const QString& plotPath, const QString& csvPath) {
    if (!labPageNames().contains(page))
        return QStringLiteral("unknown page '%1'; the pages are %2").arg(page, labPageNames().join(", "));
    MethodsLab lab;
    lab.resize(900, 640);
    QEventLoop loop;
    QObject::connect(&lab, &MethodsLab::finished, &loop, &QEventLoop::quit);
    QCustomPlot* plot = nullptr;
    if (page == "echo") {
        lab.runEcho();
        plot = lab.echoPlot();
    } else if (page == "sweep") {
        lab.runSweep();
        plot = lab.sweepPlot();
    } else if (page == "stability") {
        lab.stabilityPage()->run();
        plot = lab.stabilityPage()->plot();
    } else if (page.startsWith("fluid")) {
        lab.fluidPage()->run();
        plot = page == "fluid-map" ? lab.fluidPage()->mapPlot() : lab.fluidPage()->costPlot();
    } else if (page == "dsmc") {
        lab.dsmcPage()->run();
        plot = lab.dsmcPage()->plot();
    } else {
        lab.relaxPage()->run();
        plot = lab.relaxPage()->plot();
    }
    if (lab.isRunning()) loop.exec();
    if (lab.runner()->failedJobs() > 0)
        return QStringLiteral("%1 points failed; the plot was not written").arg(lab.runner()->failedJobs());
    QString error = savePlotImage(plot, plotPath, ImageExportOptions{});
    if (error.isEmpty() && !csvPath.isEmpty()) error = savePlotCsv(plot, csvPath);
    return error;
}

} // namespace pl::ui
