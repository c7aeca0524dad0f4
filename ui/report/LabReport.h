// A lab report of the running experiment in one file: what was run (preset, every parameter with its
// unit, the seed, steps, simulated time, integrator, backend, machine), a picture of the scene, every
// plot of the scene as vector graphics and the latest readouts with the theory the model measures them
// against. The content is gathered once (LabReportContent); the PDF (QPdfWriter) and the self-contained
// HTML page (pictures inline as data: URIs, plots as SVG) are two writers of it.
#pragma once

#include <QImage>
#include <QString>
#include <QStringList>
#include <vector>

class QCustomPlot;

namespace pl::ui {

class SimulationController;

struct ReportRow {
    QString name, value, unit, note; // note: the parameter's key, or a readout's theory
};

struct LabReportContent {
    QString title;       // the preset's name
    QString kindTitle;   // "Gas (molecular dynamics)"
    QString description; // the preset's description
    QString units;       // the kind's unit system
    std::vector<ReportRow> parameters;
    std::vector<ReportRow> run;      // seed, steps, simulated time, integrator, backend, machine, date
    std::vector<ReportRow> theory;   // key readouts beside their theory, with a verdict (ReportTheory.h)
    std::vector<ReportRow> readouts; // the last sample of every series column
    QStringList distributions;       // the histograms' one-line summaries ("kT = 0.501, KS distance 0.012")
    QImage scene;                    // the viewport, drawn off screen
    struct Plot {
        QString name; // the plot's object name ("energyPlot"): its data file's name
        QString title;
        QCustomPlot* plot; // drawn as vector graphics by the writers
    };
    std::vector<Plot> plots;
};

// Everything the report says of the controller's experiment now: `name` and `description` are those of
// the preset or file it was opened from (a running model keeps neither); `plots` are the scene's plots,
// fed by the controller (the caller keeps them alive while the content is written).
LabReportContent gatherLabReport(SimulationController& controller, const QString& name,
                                 const QString& description,
                                 const std::vector<LabReportContent::Plot>& plots);

// Writes the report as PDF (.pdf) or a self-contained HTML page (.html, .htm) by the suffix. Returns an
// error sentence, or empty on success. The file is written whole or not at all (QSaveFile).
QString writeLabReport(const LabReportContent& content, const QString& path);

// The report of the controller's experiment now, with every plot of its kind made afresh from the series
// store (hidden widgets: the app's docks stay as they are, and the CLI needs none). With a dataDir (an
// existing folder), every plot's data is written there too, as <plot name>.csv. Returns an error
// sentence, or empty.
QString exportLabReport(SimulationController& controller, const QString& name, const QString& description,
                        const QString& path, const QString& dataDir = {});

// Whether a path's suffix names a report format.
bool isReportPath(const QString& path);

} // namespace pl::ui
