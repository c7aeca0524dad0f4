// The frame every methods-lab tab shares: the note, the content area and the current experiment.
#include "LabPage.h"

#include "LabRunner.h"
#include "SimulationController.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace pl::ui {

LabPage::LabPage(LabRunner* runner, SimulationController* controller, const QString& note, QWidget* parent)
    : QWidget(parent), runner_(runner), controller_(controller) {
    auto* text = new QLabel(note, this);
    text->setWordWrap(true);
    runButton_ = new QPushButton(tr("Run"), this);
    connect(runButton_, &QPushButton::clicked, this, &LabPage::run);
    connect(runner_, &LabRunner::started, runButton_, [this] { runButton_->setEnabled(false); });
    connect(runner_, &LabRunner::finished, runButton_, [this] { runButton_->setEnabled(true); });
    controls_ = new QHBoxLayout;
    controls_->addWidget(runButton_, 0, Qt::AlignLeft);
    layout_ = new QVBoxLayout(this);
    layout_->addWidget(text);
    layout_->addLayout(controls_);
}

Model* LabPage::currentModel(const char* kind) const {
    if (!controller_ || !controller_->model()) return nullptr;
    return controller_->model()->kind() == kind ? controller_->model() : nullptr;
}

void LabPage::addContent(QWidget* widget, int stretch) {
    layout_->insertWidget(layout_->count() - 1, widget, stretch);
}

void LabPage::addContent(QLayout* layout, int stretch) {
    layout_->insertLayout(layout_->count() - 1, layout, stretch);
}

} // namespace pl::ui
