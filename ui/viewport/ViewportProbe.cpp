// ViewportCore's click probe and profile line: what the probe reads at its point, and the line the
// Profile dock plots along.
#include "FieldOverlay.h"
#include "SimulationController.h"
#include "ViewportCore.h"

#include <QWidget>

namespace pl::ui {

bool ViewportCore::hasSampledFields() const {
    return controller_->model() && controller_->model()->sampledFields();
}

void ViewportCore::closeProbe() {
    probe_.reset();
    requestFrame();
}

void ViewportCore::setProfileLine(std::optional<QLineF> line) {
    if (line == profileLine_) return;
    profileLine_ = line;
    requestFrame();
    emit profileLineChanged();
}

QStringList ViewportCore::probeText() const {
    const SampledFields* fields = controller_->model() ? controller_->model()->sampledFields() : nullptr;
    if (!probe_ || !fields) return {};
    QStringList text{
        tr("At x = %1 m, y = %2 m").arg(formatFieldValue(probe_->x()), formatFieldValue(probe_->y()))};
    const std::vector<FieldValue> values = fields->probe(probe_->x(), probe_->y());
    if (values.empty()) return text << tr("Outside the sampled domain");
    text << probeLines(values);
    const std::int64_t steps = fields->sampledSteps();
    text << (steps > 0 ? tr("Averaged over the last %1 steps").arg(steps)
                       : tr("Not sampled yet: sampling starts after the start-up steps"));
    return text;
}

} // namespace pl::ui
