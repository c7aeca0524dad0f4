// "Recommend": the user types an error target; the bar picks the cheapest measured setting that meets it
// (common/sweep/Recommend.h) and offers to apply it to the experiment, when the experiment is one it fits.
#pragma once

#include "common/sweep/Recommend.h"

#include <QWidget>
#include <functional>
#include <optional>

class QLabel;
class QPushButton;

namespace pl::ui {

class ScientificSpinBox;

class RecommendBar : public QWidget {
    Q_OBJECT
public:
    using Provider = std::function<std::vector<methods::Candidate>()>;
    // Returns why the candidate cannot be applied now (another scene is loaded), or empty when it can.
    using Blocker = std::function<QString()>;
    // Applies the candidate; returns an error message, or empty.
    using Applier = std::function<QString(const methods::Candidate&)>;

    RecommendBar(const QString& errorName, double defaultTarget, QWidget* parent = nullptr);
    void setProvider(Provider provider) { provider_ = std::move(provider); }
    void setApplier(Applier applier, Blocker blocker);
    void setTarget(double target);
    void setCostUnit(const QString& unit) { costUnit_ = unit; }
    const std::optional<methods::Candidate>& recommendation() const { return choice_; }

public slots:
    void recommend();
    void apply();
    void clear(); // a new run: the old pick is stale

signals:
    void applied(const QString& label);

private:
    ScientificSpinBox* target_ = nullptr;
    QPushButton* recommend_ = nullptr;
    QPushButton* apply_ = nullptr;
    QLabel* answer_ = nullptr;
    Provider provider_;
    Applier applier_;
    Blocker blocker_;
    std::optional<methods::Candidate> choice_;
    QString costUnit_ = tr("s per unit time");
};

} // namespace pl::ui
