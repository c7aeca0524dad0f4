// The report's theory rows are the kind's (ModelDescriptor::theoryRows, computed in core); this file only
// carries them into the report's table.
#include "ReportTheory.h"

#include "catalog/ModelCatalog.h"
#include "common/Model.h"

namespace pl::ui {

std::vector<ReportRow> theoryReadouts(const Model& model, const TimeSeries& series) {
    std::vector<ReportRow> rows;
    const ModelDescriptor* kind = findModel(model.kind());
    if (!kind || !kind->theoryRows) return rows;
    for (const TheoryRow& row : kind->theoryRows(model, series))
        rows.push_back({QString::fromStdString(row.name), QString::fromStdString(row.value),
                        QString::fromStdString(row.unit), QString::fromStdString(row.note)});
    return rows;
}

} // namespace pl::ui
