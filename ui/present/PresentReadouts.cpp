// PresentReadouts: a two-column board of big numbers; a readout whose column the model lacks, or that
// needs a body the scene has not, is left out; one that is not (yet) finite shows a dash rather than "nan".
#include "PresentReadouts.h"

#include "PresentBoard.h"
#include "SimulationController.h"
#include "i18n/Translations.h"

#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QLocale>
#include <cmath>

namespace pl::ui {

namespace {
constexpr double kValueFontScale = 1.7; // the numbers are read from the back of a classroom
constexpr int kColumns = 2;

QFont valueFont(const QFont& base) {
    QFont big = base;
    big.setPointSizeF(base.pointSizeF() * kValueFontScale);
    big.setBold(true);
    return big;
}
} // namespace

std::vector<ReadoutSpec> readoutSpecsFor(const Model& model) {
    std::vector<ReadoutSpec> out;
    for (const PresentReadout& r : presentReadouts(model))
        out.push_back({QString::fromStdString(r.column), coreText(r.label),
                       r.unit.empty() ? QString() : coreText(r.unit), r.scale, r.format, r.precision,
                       r.needsBodies});
    return out;
}

PresentReadouts::PresentReadouts(SimulationController* controller, QWidget* parent)
    : QWidget(parent), controller_(controller), grid_(new QGridLayout(this)) {
    setObjectName("presentReadouts");
    grid_->setContentsMargins(4, 4, 4, 4);
    grid_->setHorizontalSpacing(18);
    connect(controller->series(), &SeriesStore::restarted, this, &PresentReadouts::rebuild);
    connect(controller->series(), &SeriesStore::appended, this, &PresentReadouts::refresh);
    rebuild();
}

void PresentReadouts::rebuild() {
    for (const Shown& s : shown_) {
        delete s.name;
        delete s.value;
    }
    shown_.clear();
    const Model* model = controller_->model();
    if (!model) return;
    const QFont big = valueFont(font());
    const SceneTools* tools = controller_->tools();
    const bool hasBodies = tools && !tools->obstacles().empty();
    int index = 0;
    for (const ReadoutSpec& spec : readoutSpecsFor(*model)) {
        const int column = controller_->series()->column(spec.column);
        if (column < 0 || (spec.needsBodies && !hasBodies)) continue;
        auto* name = new QLabel(spec.name, this);
        auto* value = new QLabel(this);
        value->setObjectName("readout_" + spec.column);
        value->setFont(big);
        value->setTextInteractionFlags(Qt::NoTextInteraction);
        const int row = 2 * (index / kColumns), col = index % kColumns;
        grid_->addWidget(name, row, col);
        grid_->addWidget(value, row + 1, col);
        shown_.push_back({spec, column, name, value});
        ++index;
    }
    refresh();
}

QString PresentReadouts::valueText(const ReadoutSpec& spec, int column) const {
    const TimeSeries& table = controller_->series()->table();
    if (table.rows() == 0) return QStringLiteral("—");
    const double v = table.row(table.rows() - 1)[static_cast<std::size_t>(column)] * spec.scale;
    if (!std::isfinite(v)) return QStringLiteral("—");
    // In the UI's language (German 0,474), without group separators, as the plots write numbers.
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    const QString number = locale.toString(v, spec.format, spec.precision);
    return spec.unit.isEmpty() ? number : QStringLiteral("%1 %2").arg(number, spec.unit);
}

void PresentReadouts::refresh() {
    for (const Shown& s : shown_) s.value->setText(valueText(s.spec, s.column));
}

void PresentReadouts::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange)
        for (const Shown& s : shown_) s.value->setFont(valueFont(font()));
}

QStringList PresentReadouts::texts() const {
    QStringList out;
    for (const Shown& s : shown_) out << QStringLiteral("%1 = %2").arg(s.spec.name, s.value->text());
    return out;
}

} // namespace pl::ui
