// SeriesStore: a bounded table; when it is full, every other old row is dropped so a long run keeps
// its whole history at a coarser resolution instead of forgetting its start.
#include "SeriesStore.h"

namespace pl::ui {

namespace {
constexpr std::size_t kMaxRows = 20000;
} // namespace

SeriesStore::SeriesStore(QObject* parent) : QObject(parent) {}

void SeriesStore::restart(const std::vector<std::string>& columns) {
    table_ = TimeSeries(columns);
    emit restarted();
}

void SeriesStore::append(std::vector<double> row) {
    if (table_.rows() >= kMaxRows) thinToHalf();
    table_.append(std::move(row));
    emit appended();
}

void SeriesStore::replace(TimeSeries table) {
    table_ = std::move(table);
    while (table_.rows() > kMaxRows) thinToHalf();
    emit restarted();
}

void SeriesStore::thinToHalf() {
    TimeSeries thinned(table_.columns());
    for (std::size_t i = 0; i < table_.rows(); i += 2) thinned.append(table_.row(i));
    table_ = std::move(thinned);
}

int SeriesStore::column(const QString& name) const {
    const auto& columns = table_.columns();
    for (std::size_t c = 0; c < columns.size(); ++c)
        if (QString::fromStdString(columns[c]) == name) return static_cast<int>(c);
    return -1;
}

QVector<double> SeriesStore::values(int column) const {
    QVector<double> out;
    if (column < 0) return out;
    out.reserve(static_cast<qsizetype>(table_.rows()));
    for (std::size_t i = 0; i < table_.rows(); ++i)
        out.push_back(table_.row(i)[static_cast<std::size_t>(column)]);
    return out;
}

} // namespace pl::ui
