// PresentReadouts: a two-column board of big numbers, each with its name beside it; a readout whose column
// the model lacks, or that needs a body the scene has not, is left out; one that is not (yet) finite shows a
// dash rather than "nan".
#include "PresentReadouts.h"

#include "PresentBoard.h"
#include "SimulationController.h"
#include "i18n/Translations.h"

#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QLocale>
#include <algorithm>
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
    grid_->setSizeConstraint(QLayout::SetNoConstraint); // minimumSizeHint() is the stacked width
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
        name->setWordWrap(true); // a long name wraps rather than widening the board
        shown_.push_back({spec, column, name, value});
        ++index;
    }
    refresh();
    place(width() >= besideWidth());
}

int PresentReadouts::besideWidth() const {
    // The grid aligns its columns: a pair's names take the widest name's room and its numbers the widest
    // number's, even where they stand in different rows (a long name above a short number and a short
    // name above a long one need both widths; counted as pairs, "6.34 N/m" was cut to "6.34 N").
    int width = 0;
    for (int col = 0; col < kColumns; ++col) {
        int widestName = 0, widestValue = 0;
        for (std::size_t i = static_cast<std::size_t>(col); i < shown_.size(); i += kColumns) {
            widestName = std::max(widestName, shown_[i].name->minimumSizeHint().width());
            widestValue = std::max(widestValue, shown_[i].value->sizeHint().width());
        }
        width += widestName + grid_->horizontalSpacing() + widestValue;
    }
    const QMargins m = grid_->contentsMargins();
    return width + (kColumns - 1) * grid_->horizontalSpacing() + m.left() + m.right();
}

void PresentReadouts::place(bool beside) {
    beside_ = beside;
    for (const Shown& s : shown_) {
        grid_->removeWidget(s.name);
        grid_->removeWidget(s.value);
    }
    for (int c = 0; c < grid_->columnCount(); ++c) grid_->setColumnStretch(c, 0);
    // Beside: a line less per row of readouts, which leaves a 1024 × 700 board (projector mode, German)
    // the height for its plot and controls.
    for (std::size_t i = 0; i < shown_.size(); ++i) {
        const int index = static_cast<int>(i);
        const Shown& s = shown_[i];
        s.name->setAlignment(beside ? Qt::AlignRight | Qt::AlignVCenter : Qt::AlignLeft | Qt::AlignBottom);
        if (beside) {
            const int row = index / kColumns, col = 2 * (index % kColumns);
            grid_->addWidget(s.name, row, col);
            grid_->addWidget(s.value, row, col + 1);
            grid_->setColumnStretch(col + 1, 1);
        } else {
            const int row = 2 * (index / kColumns), col = index % kColumns;
            grid_->addWidget(s.name, row, col);
            grid_->addWidget(s.value, row + 1, col);
        }
    }
}

QSize PresentReadouts::minimumSizeHint() const {
    int width = 0;
    for (int col = 0; col < kColumns; ++col) {
        int widest = 0;
        for (std::size_t i = static_cast<std::size_t>(col); i < shown_.size(); i += kColumns)
            widest = std::max(
                {widest, shown_[i].name->minimumSizeHint().width(), shown_[i].value->sizeHint().width()});
        width += widest;
    }
    const QMargins m = grid_->contentsMargins();
    return {width + (kColumns - 1) * grid_->horizontalSpacing() + m.left() + m.right(),
            grid_->minimumSize().height()};
}

void PresentReadouts::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    const bool beside = width() >= besideWidth();
    if (beside != beside_) place(beside);
}

QString readoutValueText(const ReadoutSpec& spec, const TimeSeries& table, int column) {
    if (table.rows() == 0 || column < 0) return QStringLiteral("—");
    const double v = table.row(table.rows() - 1)[static_cast<std::size_t>(column)] * spec.scale;
    if (!std::isfinite(v)) return QStringLiteral("—");
    // In the UI's language (German 0,474), without group separators, as the plots write numbers.
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    PresentReadout readout;
    readout.format = spec.format;
    readout.precision = spec.precision;
    const NumberFormat format = readoutFormat(readout, v); // plain digits up to a million
    const QString number = locale.toString(v, format.format, format.precision);
    return spec.unit.isEmpty() ? number : QStringLiteral("%1 %2").arg(number, spec.unit);
}

void PresentReadouts::refresh() {
    for (const Shown& s : shown_)
        s.value->setText(readoutValueText(s.spec, controller_->series()->table(), s.column));
    if (beside_ && width() < besideWidth()) place(false); // a longer number no longer fits beside
}

void PresentReadouts::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange) {
        for (const Shown& s : shown_) s.value->setFont(valueFont(font()));
        place(width() >= besideWidth()); // larger numbers (projector mode) may no longer fit beside
    }
}

QStringList PresentReadouts::texts() const {
    QStringList out;
    for (const Shown& s : shown_) out << QStringLiteral("%1 = %2").arg(s.spec.name, s.value->text());
    return out;
}

} // namespace pl::ui
