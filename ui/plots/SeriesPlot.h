// A plot of columns of the series store against time (or another column): an upper panel and an optional
// lower one (linear or logarithmic), the latest values in the legend. A panel may instead show one of the
// model's profiles. The Energy, Thermodynamics and Density error docks are instances. After time has run
// backwards, time panels plot against the time run, Σ|Δt|, with the backward stretches dotted, so a
// reversal never draws a curve over itself. Legends sit above their panel (ReadablePlot.h).
#pragma once

#include <QColor>
#include <QStringList>
#include <QWidget>
#include <vector>

class QCustomPlot;
class QCPAxisRect;
class QCPLegend;

namespace pl::ui {

class SimulationController;

struct SeriesCurve {
    QString column; // the model's series column
    QString label;  // legend text
    QColor colour;
    Qt::PenStyle style = Qt::SolidLine; // dashed for exact theory curves beside measured ones
};

struct SeriesPanel {
    QString yLabel;
    std::vector<SeriesCurve> curves;
    bool logarithmic = false;
    QString xColumn = QStringLiteral("time"); // the store column on the x axis
    QString xLabel;                           // empty: "time"
    // Profile panels plot the model's profiles() (curves name profiles, not columns): a curve of the
    // latest state, such as the density error after each solver iteration of the last step.
    bool profile = false;
};

struct SeriesPlotSpec {
    QString objectName; // stable: dock layout and export file names use it
    QString title;      // the dock's title
    QStringList kinds;  // model kinds that have these columns
    SeriesPanel upper;
    SeriesPanel lower;        // no curves: no lower panel
    bool needsBodies = false; // the dock shows only while the scene has a body
};

class SeriesPlot : public QWidget {
    Q_OBJECT
public:
    SeriesPlot(SimulationController* controller, SeriesPlotSpec spec, QWidget* parent = nullptr);
    const SeriesPlotSpec& spec() const { return spec_; }
    QCustomPlot* plot() const { return plot_; }
    void refresh();

protected:
    void changeEvent(QEvent* event) override;   // the projector mode changes the application font
    void showEvent(QShowEvent* event) override; // a hidden or tabbed-away plot catches up when shown

private:
    void rebuild();
    bool hasProfiles() const;
    void addPanel(QCPAxisRect* rect, const SeriesPanel& panel, QCPLegend* legend);

    SimulationController* controller_;
    SeriesPlotSpec spec_;
    QCustomPlot* plot_;
    struct Bound {
        int graph;  // index into plot_->graph()
        int column; // store column, or −1 for a profile
        int xColumn;
        std::string profile;
        QString label;
        QCPLegend* legend;
        int backGraph = -1; // time panels: the same curve where time ran backwards (dotted)
    };
    std::vector<Bound> bound_;
    // Per time panel: the legend entry that explains the dotted curves, shown once time has run backwards.
    struct BackKey {
        int graph;
        QCPLegend* legend;
        QCPAxis* timeAxis;
    };
    std::vector<BackKey> backKeys_;
};

} // namespace pl::ui
