// The Recommend bar: reads the error target, picks the cheapest passing setting and applies it.
#include "RecommendBar.h"

#include "panels/ScientificSpinBox.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace pl::ui {

RecommendBar::RecommendBar(const QString& errorName, double defaultTarget, QWidget* parent)
    : QWidget(parent) {
    target_ = new ScientificSpinBox(this);
    target_->setRange(1e-15, 1e6);
    target_->setDecimals(15);
    target_->setValue(defaultTarget);
    target_->setToolTip(tr("Largest %1 you accept").arg(errorName));
    recommend_ = new QPushButton(tr("Recommend"), this);
    recommend_->setToolTip(tr("The cheapest measured setting whose %1 is at most the target").arg(errorName));
    apply_ = new QPushButton(tr("Apply"), this);
    apply_->setEnabled(false);
    answer_ = new QLabel(this);
    answer_->setWordWrap(true);
    answer_->setObjectName("recommendation");
    connect(recommend_, &QPushButton::clicked, this, &RecommendBar::recommend);
    connect(apply_, &QPushButton::clicked, this, &RecommendBar::apply);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(new QLabel(tr("Target %1:").arg(errorName), this));
    layout->addWidget(target_);
    layout->addWidget(recommend_);
    layout->addWidget(answer_, 1);
    layout->addWidget(apply_);
}

void RecommendBar::setApplier(Applier applier, Blocker blocker) {
    applier_ = std::move(applier);
    blocker_ = std::move(blocker);
}

void RecommendBar::setTarget(double target) {
    target_->setValue(target);
}

void RecommendBar::clear() {
    choice_.reset();
    answer_->clear();
    apply_->setEnabled(false);
}

void RecommendBar::recommend() {
    const std::vector<methods::Candidate> candidates =
        provider_ ? provider_() : std::vector<methods::Candidate>{};
    choice_ = methods::cheapestWithin(candidates, target_->value());
    apply_->setEnabled(false);
    if (candidates.empty()) {
        answer_->setText(tr("Run the sweep first: there is nothing measured to choose from."));
        return;
    }
    if (!choice_) {
        answer_->setText(tr("No measured setting reaches %1; the best was not enough. Lower the target or "
                            "extend the sweep.")
                             .arg(target_->value(), 0, 'g', 3));
        return;
    }
    answer_->setText(tr("%1: error %2 at %3 %4")
                         .arg(QString::fromStdString(choice_->label))
                         .arg(choice_->error, 0, 'g', 3)
                         .arg(choice_->cost, 0, 'g', 3)
                         .arg(costUnit_));
    const QString why = blocker_ ? blocker_() : tr("this sweep's settings belong to its test problem");
    apply_->setEnabled(applier_ && why.isEmpty());
    apply_->setToolTip(why.isEmpty() ? tr("Set this on the current experiment") : why);
}

void RecommendBar::apply() {
    if (!choice_ || !applier_) return;
    const QString error = applier_(*choice_);
    if (!error.isEmpty()) {
        answer_->setText(tr("Not applied: %1").arg(error));
        return;
    }
    answer_->setText(tr("Applied: %1").arg(QString::fromStdString(choice_->label)));
    apply_->setEnabled(false);
    emit applied(QString::fromStdString(choice_->label));
}

} // namespace pl::ui
