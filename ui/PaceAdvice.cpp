// PaceAdvice: the share of the watchable rate the run reaches, measured over kJudgedSeconds of running,
// and the kind's lighter() values scaled to what this machine keeps up with.
#include "PaceAdvice.h"

#include "SimulationController.h"
#include "catalog/ModelCatalog.h"
#include "i18n/Translations.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <cmath>

namespace pl::ui {

namespace {

constexpr double kMillisecondsPerSecond = 1000.0;

// "fn = 2.1e+16" or "Disks (A) = 800": each advised value with its parameter's label.
QString describe(const ParamValues& values, const std::vector<ParamSpec>& specs) {
    QStringList parts;
    for (const auto& [key, value] : values) {
        const ParamSpec* spec = findSpec(specs, key);
        const QString label = spec ? coreText(spec->label) : QString::fromStdString(key);
        const double* number = std::get_if<double>(&value);
        parts << QStringLiteral("%1 = %2").arg(label,
                                               number ? QLocale().toString(*number, 'g', 3) : QString());
    }
    return parts.join(QStringLiteral(", "));
}

} // namespace

PaceAdvice::PaceAdvice(SimulationController* controller, QWidget* parent)
    : QWidget(parent), controller_(controller), text_(new QLabel(this)), use_(new QPushButton(this)) {
    setObjectName(QStringLiteral("paceAdvice"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    text_->setObjectName(QStringLiteral("paceAdviceText"));
    use_->setObjectName(QStringLiteral("paceAdviceUse"));
    layout->addWidget(text_);
    layout->addWidget(use_);
    connect(use_, &QPushButton::clicked, this, &PaceAdvice::apply);
    connect(controller_, &SimulationController::frameAdvanced, this, &PaceAdvice::judge);
    for (const auto signal : {&SimulationController::modelReplaced, &SimulationController::parametersChanged,
                              &SimulationController::paceChanged})
        connect(controller_, signal, this, &PaceAdvice::restart);
    connect(controller_, &SimulationController::runningChanged, this, [this] { clock_.invalidate(); });
    restart();
}

void PaceAdvice::restart() {
    clock_.invalidate();
    advised_.clear();
    hide();
}

void PaceAdvice::judge() {
    const Model* model = controller_->model();
    if (!model || !controller_->isRunning() || !controller_->automaticPace() || model->failure()) {
        clock_.invalidate();
        return;
    }
    if (!clock_.isValid()) {
        clock_.start();
        startTime_ = model->time();
        startStep_ = model->stepCount();
        return;
    }
    const double wall = static_cast<double>(clock_.elapsed()) / kMillisecondsPerSecond;
    if (wall < kJudgedSeconds) return;
    const double rate = controller_->watchableRate();
    const double share = rate > 0 ? std::abs(model->time() - startTime_) / wall / rate : 1.0;
    const long long steps = model->stepCount() - startStep_;
    clock_.invalidate(); // the next window starts with the next frame
    const ModelDescriptor* kind = findModel(model->kind());
    if (share >= kShortShare || !kind || !kind->lighter || steps <= 0) {
        restart();
        return;
    }
    advised_ = kind->lighter(controller_->parameterValues(), kMargin * share);
    const QString percent = QLocale().toString(100 * share, 'f', 0);
    const QString perStep = QLocale().toString(wall * kMillisecondsPerSecond / steps, 'f', 1);
    const QString particles = QLocale().toString(static_cast<qlonglong>(model->particleCount()));
    // Short, beside the status line; the sentence in full as its tooltip.
    // Short, so that the status line beside it keeps its room at 1024 px; the work of a step is in the
    // tooltip and the accessible description.
    text_->setText(tr("%1 % of the watchable pace").arg(percent));
    text_->setToolTip(
        tr("This machine runs the scene at %1 % of the pace at which it is watchable: each step "
           "takes %2 ms for %3 particles. Fewer particles keep the pace.")
            .arg(percent, perStep, particles));
    if (advised_.empty()) {
        use_->hide();
    } else {
        use_->setText(tr("Use %1").arg(describe(advised_, model->paramSpecs())));
        use_->setToolTip(
            tr("A lighter experiment that this machine runs at the watchable pace; it restarts the "
               "experiment, and nothing changes until you press it."));
        use_->show();
    }
    show();
}

void PaceAdvice::apply() {
    const ParamValues values = advised_;
    if (values.empty()) return;
    if (const QString problem = controller_->setParameters(values); !problem.isEmpty()) {
        text_->setText(problem);
        use_->hide();
        return;
    }
    const bool running = controller_->isRunning();
    controller_->reset();
    if (running) controller_->play();
    restart();
}

} // namespace pl::ui
