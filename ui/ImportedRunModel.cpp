// ImportedRunModel: the two entry points that would change the imported state refuse, with the reason.
#include "ImportedRunModel.h"

#include <stdexcept>

namespace pl::ui {

ImportedRunModel::ImportedRunModel(std::unique_ptr<Model> state, std::int64_t step, double time)
    : state_(std::move(state)), step_(step), time_(time) {}

void ImportedRunModel::setParams(const ParamValues&) {
    throw std::logic_error("an imported run is read-only: open a preset to change parameters");
}

void ImportedRunModel::restoreState(const StateRecord&) {
    throw std::logic_error("an imported run is read-only: open the snapshot as a preset instead");
}

} // namespace pl::ui
