// Shared model helpers.
#include "Model.h"

#include <sstream>

namespace pl {

std::string ModelFailure::message() const {
    std::ostringstream out;
    out << what << " at step " << step << " (t = " << time << ")";
    if (!hint.empty()) out << ". " << hint;
    return out.str();
}

} // namespace pl
