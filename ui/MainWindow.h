// The application's composition root: actions, menus, docks and the viewport, wired to one
// SimulationController and one ExperimentDocument. It holds no simulation logic.
#pragma once

#include <QMainWindow>
#include <QSet>
#include <vector>

class QActionGroup;
class QComboBox;
class QDockWidget;
class QLabel;
class QMenu;
class QSlider;
class QSpinBox;
class QToolBar;

namespace pl::ui {

class DistributionPlot;
class ExperimentDocument;
class ParameterPanel;
class ProfilePlot;
class ViewChooser;
class SeriesPlot;
class SimulationController;
class ViewportCore;
class PresentMode;
class Autosave;
class ViewportRoom;
class AppRecorder;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    // Stops listening to the controller first: a field losing focus while the window closes still applies
    // its value, and the window's handlers must not run on a half-destroyed window.
    ~MainWindow() override;

    // Loads a built-in preset by name or a preset file; shows a dialog naming the problem on failure
    // (the running experiment is kept). Returns whether it loaded.
    bool openPreset(const QString& nameOrPath);
    SimulationController* controller() const { return controller_; }
    ExperimentDocument* document() const { return document_; }
    DistributionPlot* histogram() const { return histogram_; }
    ParameterPanel* parameters() const { return parameters_; }
    const std::vector<SeriesPlot*>& seriesPlots() const { return seriesPlots_; }
    AppRecorder* recorder() const { return recorder_; }
    ProfilePlot* profilePlot() const { return profilePlot_; }
    ViewChooser* viewChooser() const { return viewChooser_; }
    QWidget* viewport() const { return viewport_; }
    ViewportCore* viewportCore() const { return viewportCore_; }
    QImage viewportImage() const;
    // The whole window as the user sees it (QWidget::grab misses QPainter content drawn in paintGL).
    QImage windowImage();
    QString saveViewportImage(const QString& path); // error sentence, or empty
    void setProjectorMode(bool on);
    // Present mode: full screen, the viewport and one panel for a lesson (ui/present/PresentMode.h).
    PresentMode* presentMode() const { return present_; }
    Autosave* autosave() const { return autosave_; }
    // File → Export to LAMMPS… and File → Open LAMMPS run… once the folder is chosen (docs/scale-out.md):
    // the reason it did not work, or empty. A refused export writes nothing; an opened run is shown
    // read-only until a preset is opened.
    QString exportToLammps(const QString& dir);
    QString openLammpsRun(const QString& dir);
    // Simulation → Run on LAMMPS… once the folder and ranks are chosen: exports there, runs
    // `mpirun -np ranks lmp` in a worker thread under a progress dialog with Cancel, and opens the run
    // when it ends well (lammpsRunFinished says how it ended). The reason it could not start, or empty.
    QString runOnLammps(const QString& dir, int ranks);

signals:
    void lammpsRunFinished(const QString& problem); // empty when the run opened

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createViewport();
    void createActions();
    void createLammpsActions(QMenu* file);
    void createReportAction(QMenu* file);               // MainWindowRecording.cpp
    void createRecordAction(QMenu* sim, QToolBar* bar); // MainWindowRecording.cpp
    void createRunOnLammpsAction(QMenu* sim);
    QString writeLammpsDeck(const QString& dir, long long& steps); // exportToLammps; steps: the deck's run
    void createSceneBar();
    void createToolPalette();
    void syncGravity(); // the gravity action follows the model's "gravity_on" switch
    void showPace();    // the pace box and the Auto action follow the controller
    void createDocks();
    QDockWidget* addDock(QWidget* content, const QString& title, const QString& objectName,
                         Qt::DockWidgetArea area, const QStringList& kinds = {});
    void readSettings();
    void writeSettings() const;
    void modelChanged();
    void documentChanged();
    // Each dock shows only where it has something to show: the scene's kind, sampled fields, bodies.
    bool dockApplies(const QDockWidget* dock) const;
    void showDocksThatApply();
    // Play and Step are off while an imported run is shown or after a blow-up (until Reset).
    void updateRunActions();
    void updateStatus();
    void fillPresetPicker();
    void fillRecentMenu();

    SimulationController* controller_;
    ExperimentDocument* document_;
    QWidget* viewport_ = nullptr;
    ViewportCore* viewportCore_ = nullptr;
    ParameterPanel* parameters_ = nullptr;
    DistributionPlot* histogram_ = nullptr;
    std::vector<SeriesPlot*> seriesPlots_;
    ProfilePlot* profilePlot_ = nullptr; // scenes with sampled fields
    ViewChooser* viewChooser_ = nullptr;
    QMenu* viewMenu_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QComboBox* scenePicker_ = nullptr;
    QComboBox* presetPicker_ = nullptr;
    QSpinBox* speed_ = nullptr;
    QAction* autoPace_ = nullptr;
    QSlider* heat_ = nullptr;
    QAction* gravity_ = nullptr;
    QLabel* status_ = nullptr;
    AppRecorder* recorder_ = nullptr;
    QAction* recordAction_ = nullptr;
    QLabel* recordingLabel_ = nullptr; // "● REC 0:03.2" while a clip is recorded
    QAction* playAction_ = nullptr;
    QAction* stepAction_ = nullptr;
    QList<QAction*> runActions_; // play, step, reset, speed: off while an imported run is shown
    QAction* projectorAction_ = nullptr;
    QAction* presentAction_ = nullptr;
    PresentMode* present_ = nullptr;
    Autosave* autosave_ = nullptr;
    ViewportRoom* room_ = nullptr; // docks give the viewport its room back (fonts, restored layouts)
    QActionGroup* tools_ = nullptr;
    QSet<QDockWidget*> hiddenForScene_; // docks hidden because the scene has no data for them
    QFont baseFont_;
};

} // namespace pl::ui
