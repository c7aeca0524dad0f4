// The time series the plots read: one row of the model's observables per sample, fed by the
// SimulationController. Plots subscribe to its signals instead of asking the model themselves.
#pragma once

#include "common/TimeSeries.h"

#include <QObject>
#include <QString>
#include <QVector>

namespace pl::ui {

class SeriesStore : public QObject {
    Q_OBJECT
public:
    explicit SeriesStore(QObject* parent = nullptr);

    // Starts a new table (a new model or a reset).
    void restart(const std::vector<std::string>& columns);
    void append(std::vector<double> row);
    // Starts over with a finished table (a run read back from elsewhere): one restarted(), no appended().
    void replace(TimeSeries table);

    const TimeSeries& table() const { return table_; }
    int column(const QString& name) const; // −1 when the model has no such column
    QVector<double> values(int column) const;
    std::size_t rows() const { return table_.rows(); }

signals:
    void restarted();
    void appended();

private:
    void thinToHalf(); // keeps every other row

    TimeSeries table_;
};

} // namespace pl::ui
